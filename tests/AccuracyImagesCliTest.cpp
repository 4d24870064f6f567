// `bench accuracy --images DIR` and `bench golden --check --diff-dir DIR` end to end: the pictures are
// read back from disk (bench/golden/GoldenImage, as goldens are read) and held to numbers
// that reach the test by another path: the error map's marked pixels against the CSV row's
// percentages times its judged-sample count, the signed map's presence against the technique's own
// visibility picture, the contact sheet's tiles against the error maps; and a golden broken on purpose
// gets pictures that mark the pixels broken. A DIR that cannot be written stops the run before any frame.
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/golden/GoldenImage.h"
#include "bench/golden/MatrixCheck.h"
#include "bench/lib/images/AccuracyImages.h"
#include "bench/lib/images/ContactSheet.h"
#include "bench/lib/images/ErrorMap.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;
using test::runCommand;

namespace {

namespace fs = std::filesystem;

const std::string kBench = SB_BENCH_BINARY;
// sphere_plane from above: a small scene whose shadow fills part of a 128x128 frame; one frame and no
// stability perturbations keep the run near a second.
const std::string kRun = " --scene sphere_plane --camera top --size 128x128 --frames 2 --warmup 1 "
                         "--no-timer-check --no-stability";

Rgb pixel(const Image8& image, int x, int y) {
    const uint8_t* p = &image.pixels[size_t(y * image.width + x) * size_t(image.channels)];
    return image.channels >= 3 ? Rgb{p[0], p[1], p[2]} : Rgb{p[0], p[0], p[0]};
}

struct MapCounts {
    uint64_t evaluated = 0, falseShadow = 0, falseLight = 0, band = 0;
    uint64_t falseShadowOffBand = 0, falseLightOffBand = 0;
};

/// Counts the error map's colours (bench/lib/images/ErrorMap.h); fails on a colour that is none of them.
MapCounts countColours(const Image8& map) {
    MapCounts n;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            const Rgb c = pixel(map, x, y);
            if (c == ErrorMap::kNotJudged || c == ErrorMap::kBackground) continue;
            ++n.evaluated;
            if (c == ErrorMap::kFalseShadow)
                ++n.falseShadow, ++n.falseShadowOffBand;
            else if (c == ErrorMap::kFalseLight)
                ++n.falseLight, ++n.falseLightOffBand;
            else if (c == ErrorMap::kFalseShadowEdge)
                ++n.falseShadow, ++n.band;
            else if (c == ErrorMap::kFalseLightEdge)
                ++n.falseLight, ++n.band;
            else if (c == ErrorMap::kEdgeBand)
                ++n.band;
            else if (!(c.r == c.g && c.g == c.b && c.r >= 40 && c.r <= 140))
                ADD_FAILURE() << "(" << x << ", " << y
                              << ") has a colour the error map does not use: " << int(c.r) << ", " << int(c.g)
                              << ", " << int(c.b);
        }
    return n;
}

/// A count written as a percentage with 4 decimals (bench/lib/output/CsvNumber.h) of `whole`, recovered: the
/// percentage is within 5e-5 points of the exact one, i.e. within 5e-7 * whole samples, under 0.01 of a
/// sample for the 16384 samples of 128x128, so rounding recovers the count exactly.
uint64_t countFromPercent(const std::string& pct, uint64_t whole) {
    return uint64_t(std::llround(std::stod(pct) / 100.0 * double(whole)));
}

/// Where `tile` lies inside `sheet` (the first exact match, scanning rows top-down); (-1, -1) if nowhere.
std::pair<int, int> find(const Image8& sheet, const Image8& tile) {
    for (int y = 0; y + tile.height <= sheet.height; ++y)
        for (int x = 0; x + tile.width <= sheet.width; ++x) {
            bool match = true;
            for (int ty = 0; ty < tile.height && match; ++ty)
                for (int tx = 0; tx < tile.width && match; ++tx)
                    match = pixel(sheet, x + tx, y + ty) == pixel(tile, tx, ty);
            if (match) return {x, y};
        }
    return {-1, -1};
}

TEST(AccuracyImagesCli, ErrorMapsCountWhatTheRowsReportAndTheSheetShowsThem) {
    const std::string dir = test::freshTestDir("accuracy-images");
    const std::string images = dir + "/images", csv = dir + "/rows.csv";
    // A coarse shadow map (errors to count: its 64-texel map misplaces the edge), `none` (false light
    // wherever the reference shadows) and pcss (a soft technique: its signed map).
    const std::vector<std::string> specs = {"shadowmap:resolution=64", "none", "pcss"};
    std::string command = kBench + " accuracy";
    for (const std::string& s : specs) command += " -t " + s;
    const auto r = runCommand(command + kRun + " --csv " + csv + " --images " + images);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), specs.size());
    const std::string sheetPath = images + "/sphere_plane.light0.contact.png";
    EXPECT_NE(r.output.find("contact sheet: " + sheetPath), std::string::npos) << r.output;

    std::vector<Image8> maps;
    uint64_t marked = 0;
    for (size_t k = 0; k < specs.size(); ++k) {
        const auto& row = rows[k];
        const std::string stem = images + "/sphere_plane." + AccuracyImages::fileLabel(specs[k]) + ".light0.";
        SCOPED_TRACE(stem);
        for (const char* kind : {"technique", "reference", "error"})
            ASSERT_TRUE(fs::exists(stem + kind + ".png")) << r.output;
        const Image8 map = GoldenImage::read(stem + "error.png");
        ASSERT_EQ(map.width, 128);
        ASSERT_EQ(map.height, 128);
        const MapCounts n = countColours(map);
        const uint64_t evaluated = uint64_t(std::llround(std::stod(row.at(col::kAccEvaluated))));
        EXPECT_EQ(n.evaluated, evaluated);
        EXPECT_EQ(n.falseShadow, countFromPercent(row.at(col::kAccFalseShadowPct), evaluated));
        EXPECT_EQ(n.falseLight, countFromPercent(row.at(col::kAccFalseLightPct), evaluated));
        EXPECT_EQ(n.falseShadow + n.falseLight, countFromPercent(row.at(col::kAccWrongPct), evaluated));
        // Off the edge band, over the samples off it (the picture's band is the judgement's).
        const uint64_t offBand = n.evaluated - n.band;
        EXPECT_EQ(n.falseShadowOffBand, countFromPercent(row.at(col::kAccFalseShadowNoEdgePct), offBand));
        EXPECT_EQ(n.falseLightOffBand, countFromPercent(row.at(col::kAccFalseLightNoEdgePct), offBand));
        marked += n.falseShadow + n.falseLight;

        // The signed map exists exactly where visibility is not binary: a soft technique (pcss) or a
        // judged sample of the technique's own picture that is neither black nor white.
        const Image8 technique = GoldenImage::read(stem + "technique.png");
        bool fractional = false;
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 128; ++x) {
                const Rgb c = pixel(map, x, y);
                const uint8_t v = pixel(technique, x, y).r;
                fractional |= !(c == ErrorMap::kNotJudged || c == ErrorMap::kBackground) && v > 0 && v < 255;
            }
        EXPECT_EQ(fs::exists(stem + "signed.png"), specs[k] == "pcss" || fractional);
        maps.push_back(map);
    }
    EXPECT_GT(marked, 0u) << "nothing to count: the test would pass with any picture";
    EXPECT_TRUE(fs::exists(images + "/sphere_plane.pcss.light0.signed.png"));

    // The contact sheet: the size of its layout, and every error map in it, in order, side by side.
    const Image8 sheet = GoldenImage::read(sheetPath);
    std::vector<ContactTile> tiles(specs.size());
    for (size_t k = 0; k < specs.size(); ++k) {
        tiles[k].title = specs[k]; // "shadowmap:resolution=64" takes two lines of a 128 px tile
        tiles[k].map = RgbImage(128, 128);
        tiles[k].lines.resize(AccuracyImages::figures({}, {}, false).size());
    }
    const ContactSheet::Layout layout = ContactSheet::layout(
        AccuracyImages::header("sphere_plane", 0, false, 128, 128), AccuracyImages::legend(), tiles);
    EXPECT_EQ(sheet.width, layout.width);
    EXPECT_EQ(sheet.height, layout.height);
    int previousX = -1, row = -1;
    for (size_t k = 0; k < maps.size(); ++k) {
        const auto [x, y] = find(sheet, maps[k]);
        ASSERT_GE(x, 0) << "error map " << k << " is not on the sheet";
        if (row < 0) row = y;
        EXPECT_EQ(y, row) << "one row of tiles";
        if (previousX >= 0) {
            EXPECT_EQ(x, previousX + 128 + ContactSheet::kMargin) << "side by side";
        }
        previousX = x;
    }
}

TEST(AccuracyImagesCli, AnUnwritableFolderStopsTheRunBeforeItMeasures) {
    const std::string dir = test::freshTestDir("accuracy-images-bad");
    test::writeFile(dir + "/a-file", "not a folder");
    const std::string csv = dir + "/rows.csv";
    for (const std::string& bad :
         {dir + "/a-file", dir + "/missing/deeper", std::string("/proc/shadowbench-images")}) {
        const auto r =
            runCommand(kBench + " accuracy -t shadowmap" + kRun + " --csv " + csv + " --images " + bad);
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find("--images " + bad), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("frames"), std::string::npos) << "measured before failing: " << r.output;
        EXPECT_FALSE(fs::exists(csv)) << "a row was written";
    }
    EXPECT_FALSE(fs::exists(dir + "/missing"));
    // The plain run has no pictures to write.
    const auto plain = runCommand(kBench + " -t shadowmap" + kRun.substr(0, kRun.find(" --no-stability")) +
                                  " --images " + dir + "/x");
    EXPECT_EQ(plain.exitCode, 2) << plain.output;
    EXPECT_NE(plain.output.find("--images belongs to `bench accuracy`"), std::string::npos) << plain.output;
}

TEST(AccuracyImagesCli, AChangedGoldenGetsDifferencePicturesOfThatCell) {
    // The committed goldens copied, shadowmap's sphere_plane visibility broken: every 61st pixel
    // inverted (1.6% of them; the check allows 0.5%). Only shadowmap is rendered (all its cells: the
    // submission modes and the Vulkan axis, a few seconds).
    const std::string dir = test::freshTestDir("golden-diff-cli");
    const std::string goldens = dir + "/goldens", diffs = dir + "/diffs";
    fs::create_directories(goldens);
    fs::copy(std::string(SB_SOURCE_DIR) + "/results/goldens/sphere_plane", goldens + "/sphere_plane",
             fs::copy_options::recursive);
    fs::copy_file(std::string(SB_SOURCE_DIR) + "/results/goldens/bounds.json", goldens + "/bounds.json");
    const std::string vis = MatrixCheck::goldenPath(goldens, "sphere_plane", "shadowmap", "visibility");
    const Image8 original = GoldenImage::read(vis);
    ASSERT_EQ(original.channels, 1) << "sphere_plane has one light";
    Image8 broken = original;
    std::vector<size_t> inverted;
    for (size_t p = 0; p < broken.pixelCount(); p += 61) {
        broken.pixels[p] = uint8_t(255 - broken.pixels[p]);
        inverted.push_back(p);
    }
    GoldenImage::write(vis, broken);

    const auto r = runCommand(kBench + " golden --check --scene sphere_plane --technique shadowmap --dir " +
                              goldens + " --diff-dir " + diffs);
    EXPECT_EQ(r.exitCode, 1) << "the verdict is the check's, pictures or not: " << r.output;
    // Every cell that failed on its visibility golden names its pictures, and they exist.
    const std::regex failed(R"((shadowmap/sphere_plane/[a-z_/]+): FAILED)");
    size_t cells = 0;
    for (auto it = std::sregex_iterator(r.output.begin(), r.output.end(), failed);
         it != std::sregex_iterator(); ++it) {
        const std::string cell = (*it)[1];
        std::string stem = cell;
        std::replace(stem.begin(), stem.end(), '/', '.');
        const std::string error = diffs + "/" + stem + ".visibility.light0.error.png";
        const std::string line = "visibility difference against " + vis + ": " + error + " " + diffs + "/" +
                                 stem + ".visibility.light0.signed.png";
        EXPECT_NE(r.output.find(line), std::string::npos) << cell << ":\n" << r.output;
        ASSERT_TRUE(fs::exists(error)) << error;
        ++cells;
        // The inverted pixels are marked. Not every one of them: a pixel of the original golden at
        // 128 +- 1 does not change sides when inverted, and the rendered image may differ from the
        // original golden by up to 2/255 anywhere and by more at up to 0.5% of the pixels (the check's
        // own tolerance): a 10% allowance covers both, a broken map would mark none.
        const Image8 map = GoldenImage::read(error);
        size_t marked = 0;
        for (size_t p : inverted) {
            const Rgb c = pixel(map, int(p % size_t(map.width)), int(p / size_t(map.width)));
            marked += c == ErrorMap::kFalseShadow || c == ErrorMap::kFalseLight ||
                      c == ErrorMap::kFalseShadowEdge || c == ErrorMap::kFalseLightEdge;
        }
        EXPECT_GE(double(marked), 0.9 * double(inverted.size())) << cell;
        // And little else: at most the inverted pixels plus the check's 0.5% of differing ones.
        const MapCounts n = countColours(map);
        EXPECT_LE(n.falseShadow + n.falseLight, inverted.size() + map.width * map.height / 200) << cell;
    }
    EXPECT_GE(cells, 1u) << r.output;
    // An unwritable --diff-dir is refused before the matrix renders.
    const auto bad = runCommand(kBench + " golden --check --scene sphere_plane --technique shadowmap --dir " +
                                goldens + " --diff-dir /proc/shadowbench-diffs");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("--diff-dir /proc/shadowbench-diffs"), std::string::npos) << bad.output;
}

} // namespace
