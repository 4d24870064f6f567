// The accuracy pictures without GL (bench/lib/images/, bench/golden/GoldenDiff.h): on hand-built buffers the
// error map's pixels are exactly the colours ErrorMap.h specifies and its counts are the judgement's
// (reference/AccuracyMetrics.h), the signed difference map maps -1/0/+1 to blue/white/red with its colour
// bar and scale under it, the contact sheet puts maps and labels where ContactSheet.h says, every glyph
// drawn is the font table's, and the golden check's difference pictures mark the pixels that changed.
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/golden/GoldenDiff.h"
#include "bench/golden/GoldenImage.h"
#include "bench/lib/font/BitmapFont.h"
#include "bench/lib/images/AccuracyImages.h"
#include "bench/lib/images/ContactSheet.h"
#include "bench/lib/images/DifferenceMap.h"
#include "bench/lib/images/ErrorMap.h"
#include "bench/lib/images/FlipRows.h"
#include "core/Error.h"
#include "reference/AccuracyMetrics.h"

using namespace sb;

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();

/// Whether the glyph of `c` is drawn at (x, y) of `image` at `scale`: every font pixel a scale x scale
/// block of `ink` where the table sets it and of `paper` where it does not.
::testing::AssertionResult glyphAt(const RgbImage& image, int x, int y, char c, int scale, Rgb ink,
                                   Rgb paper) {
    for (int gy = 0; gy < BitmapFont::kGlyphHeight; ++gy)
        for (int gx = 0; gx < BitmapFont::kGlyphWidth; ++gx)
            for (int sy = 0; sy < scale; ++sy)
                for (int sx = 0; sx < scale; ++sx) {
                    const Rgb want = BitmapFont::pixel(c, gx, gy) ? ink : paper;
                    const int px = x + gx * scale + sx, py = y + gy * scale + sy;
                    if (!(image.at(px, py) == want))
                        return ::testing::AssertionFailure() << "'" << c << "' font pixel (" << gx << ", "
                                                             << gy << ") at (" << px << ", " << py << ")";
                }
    return ::testing::AssertionSuccess();
}

std::string rgbText(Rgb c) {
    return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

// The 4x4 case, top row first. Reference: columns 0-1 lit, 2-3 shadowed, so the edge band (a judged
// sample with a neighbour of the other class) is columns 1 and 2. (0, 3) is geometry outside the mask,
// (3, 3) no geometry (reference -1, outside the mask).
struct Case4x4 {
    static constexpr int w = 4, h = 4;
    std::vector<float> reference, technique;
    std::vector<uint8_t> mask;
    Case4x4() {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) reference.push_back(x < 2 ? 1.0f : 0.0f);
        reference[idx(3, 3)] = -1.0f;
        technique = reference;
        technique[idx(3, 3)] = 1.0f; // outside the mask: whatever the technique says is not judged
        mask.assign(size_t(w * h), 1);
        mask[idx(0, 3)] = 0;
        mask[idx(3, 3)] = 0;
        technique[idx(0, 0)] = 0.0f;  // false shadow, off the band
        technique[idx(0, 1)] = kNaN;  // NaN: the opposite of the reference (lit) -> false shadow
        technique[idx(3, 0)] = 1.0f;  // false light, off the band
        technique[idx(1, 1)] = 0.2f;  // false shadow in the band
        technique[idx(2, 1)] = 0.9f;  // false light in the band
        technique[idx(1, 2)] = 0.5f;  // 0.5 is lit (shadowed is < 0.5): correct, in the band
        technique[idx(3, 2)] = 0.49f; // shadowed: correct, off the band
    }
    static size_t idx(int x, int y) { return size_t(y * w + x); }
};

TEST(ErrorMap, HandBuiltPixelsHaveTheSpecifiedColours) {
    const Case4x4 c;
    const ErrorMap map = ErrorMap::build(c.technique, c.reference, c.mask, c.w, c.h);
    const Rgb lit{140, 140, 140}, dark{40, 40, 40}; // 40 + 100 * reference
    const Rgb band{100, 88, 0};
    const Rgb fs{30, 90, 255}, fl{255, 40, 30}, fsBand{150, 185, 255}, flBand{255, 170, 150};
    const Rgb notJudged{20, 20, 20}, none{0, 0, 0};
    const Rgb expected[4][4] = {
        {fs, band, band, fl},
        {fs, fsBand, flBand, dark},
        {lit, band, band, dark},
        {notJudged, band, band, none},
    };
    ASSERT_EQ(map.image().width(), 4);
    ASSERT_EQ(map.image().height(), 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            EXPECT_EQ(map.image().at(x, y), expected[y][x])
                << "(" << x << ", " << y << "): " << rgbText(map.image().at(x, y)) << " instead of "
                << rgbText(expected[y][x]);
    // The named constants are these colours (the README and the legend describe them).
    EXPECT_EQ(ErrorMap::kFalseShadow, fs);
    EXPECT_EQ(ErrorMap::kFalseLight, fl);
    EXPECT_EQ(ErrorMap::kEdgeBand, band);
}

TEST(ErrorMap, HandBuiltCountsMatchTheJudgement) {
    const Case4x4 c;
    const ErrorMap::Counts n = ErrorMap::build(c.technique, c.reference, c.mask, c.w, c.h).counts();
    // By hand: 14 judged; false shadow (0,0), (0,1), (1,1); false light (3,0), (2,1); the band is the
    // 8 judged samples of columns 1 and 2.
    EXPECT_EQ(n.evaluated, 14u);
    EXPECT_EQ(n.falseShadow, 3u);
    EXPECT_EQ(n.falseLight, 2u);
    EXPECT_EQ(n.edgeBand, 8u);
    EXPECT_EQ(n.evaluatedNoEdge, 6u);
    EXPECT_EQ(n.falseShadowNoEdge, 2u);
    EXPECT_EQ(n.falseLightNoEdge, 1u);
    // The judgement itself agrees (the map is its picture, not a second opinion).
    const HardMetrics m = AccuracyMetrics::hard(c.technique, c.reference, c.mask, c.w, c.h);
    EXPECT_EQ(m.evaluated, n.evaluated);
    EXPECT_EQ(m.falseShadow, n.falseShadow);
    EXPECT_EQ(m.falseLight, n.falseLight);
    EXPECT_EQ(m.evaluatedNoEdge, n.evaluatedNoEdge);
    EXPECT_EQ(m.falseShadowNoEdge, n.falseShadowNoEdge);
    EXPECT_EQ(m.falseLightNoEdge, n.falseLightNoEdge);
}

TEST(ErrorMap, CountsEqualTheJudgementOnRandomBuffers) {
    // Random visibility, soft references and masks with holes: every count of the map equals
    // AccuracyMetrics::hard's, exactly (both count the same samples; no tolerance applies).
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int round = 0; round < 20; ++round) {
        const int w = 5 + round * 3, h = 3 + round * 2;
        std::vector<float> tech(size_t(w * h)), ref(size_t(w * h));
        std::vector<uint8_t> mask(size_t(w * h));
        for (size_t i = 0; i < tech.size(); ++i) {
            tech[i] = u(rng) < 0.02f ? kNaN : u(rng);
            ref[i] = u(rng) < 0.1f ? -1.0f : (u(rng) < 0.5f ? u(rng) : float(u(rng) < 0.5f));
            mask[i] = ref[i] >= 0.0f && u(rng) < 0.9f;
        }
        const ErrorMap::Counts n = ErrorMap::build(tech, ref, mask, w, h).counts();
        const HardMetrics m = AccuracyMetrics::hard(tech, ref, mask, w, h);
        EXPECT_EQ(n.evaluated, m.evaluated) << w << "x" << h;
        EXPECT_EQ(n.falseShadow, m.falseShadow) << w << "x" << h;
        EXPECT_EQ(n.falseLight, m.falseLight) << w << "x" << h;
        EXPECT_EQ(n.evaluatedNoEdge, m.evaluatedNoEdge) << w << "x" << h;
        EXPECT_EQ(n.falseShadowNoEdge, m.falseShadowNoEdge) << w << "x" << h;
        EXPECT_EQ(n.falseLightNoEdge, m.falseLightNoEdge) << w << "x" << h;
    }
}

TEST(ErrorMap, MismatchedBuffersAreRefused) {
    EXPECT_THROW(ErrorMap::build({1.0f}, {1.0f, 0.0f}, {1, 1}, 2, 1), std::invalid_argument);
    EXPECT_THROW(DifferenceMap::build({1.0f}, {1.0f}, {1}, 2, 1), std::invalid_argument);
}

TEST(AccuracyImagesDifferenceMap, MinusOneZeroPlusOneAreBlueWhiteRed) {
    EXPECT_EQ(DifferenceMap::colour(-1.0f), (Rgb{0, 0, 255}));
    EXPECT_EQ(DifferenceMap::colour(0.0f), (Rgb{255, 255, 255}));
    EXPECT_EQ(DifferenceMap::colour(1.0f), (Rgb{255, 0, 0}));
    // Halfway: 255 * 0.5 = 127.5 rounds to 128. Beyond the scale: clamped.
    EXPECT_EQ(DifferenceMap::colour(-0.5f), (Rgb{128, 128, 255}));
    EXPECT_EQ(DifferenceMap::colour(0.5f), (Rgb{255, 128, 128}));
    EXPECT_EQ(DifferenceMap::colour(-3.0f), (Rgb{0, 0, 255}));
    // Another full scale: 0.1 is then the end of the bar.
    EXPECT_EQ(DifferenceMap::colour(0.1f, 0.1f), (Rgb{255, 0, 0}));
    EXPECT_EQ(DifferenceMap::niceScale(0.03f), 0.05f);
    EXPECT_EQ(DifferenceMap::niceScale(0.5f), 0.5f);
    EXPECT_EQ(DifferenceMap::niceScale(7.0f), 1.0f);
}

TEST(AccuracyImagesDifferenceMap, MapPixelsAndColourBarWithItsScale) {
    const int w = 64, h = 4;
    std::vector<float> ref(size_t(w * h), 0.5f), tech = ref;
    std::vector<uint8_t> mask(size_t(w * h), 1);
    ref[0] = 1.0f, tech[0] = 0.0f; // -1
    ref[1] = 0.0f, tech[1] = 1.0f; // +1
    tech[2] = kNaN;                // non-finite
    mask[3] = 0;                   // geometry, not judged
    mask[4] = 0, ref[4] = -1.0f;   // no geometry
    const RgbImage map = DifferenceMap::build(tech, ref, mask, w, h);
    ASSERT_EQ(map.width(), w);
    ASSERT_EQ(map.height(), h + DifferenceMap::barHeight(w));
    EXPECT_EQ(map.at(0, 0), (Rgb{0, 0, 255}));
    EXPECT_EQ(map.at(1, 0), (Rgb{255, 0, 0}));
    EXPECT_EQ(map.at(2, 0), DifferenceMap::kNonFinite);
    EXPECT_EQ(map.at(3, 0), DifferenceMap::kNotJudged);
    EXPECT_EQ(map.at(4, 0), DifferenceMap::kBackground);
    EXPECT_EQ(map.at(5, 0), (Rgb{255, 255, 255}));
    // The bar: from x = kPad (-1, blue) to width - kPad - 1 (+1, red), kBarThickness rows at
    // y = h + kPad. It has 56 columns, t stepping by 2/55: no column is exactly 0, the middle one
    // (x = 32, t = 1/55) is within one step of white.
    const int x0 = DifferenceMap::kPad, x1 = w - DifferenceMap::kPad, y0 = h + DifferenceMap::kPad;
    for (int y = y0; y < y0 + DifferenceMap::kBarThickness; ++y) {
        EXPECT_EQ(map.at(x0, y), (Rgb{0, 0, 255})) << y;
        EXPECT_EQ(map.at(x1 - 1, y), (Rgb{255, 0, 0})) << y;
    }
    const Rgb mid = map.at((x0 + x1) / 2, y0);
    EXPECT_EQ(mid.r, 255);
    EXPECT_GE(int(mid.g), 255 - 10) << "2/55 of 255 is 9.3 levels";
    EXPECT_EQ(map.at(x0 - 1, y0), DifferenceMap::kPanel) << "the bar starts at kPad";
    // Its scale: "-1" at the left, "0" centred, "+1" right-aligned, in the font of the table.
    const int s = DifferenceMap::textScale(w), ly = y0 + DifferenceMap::kBarThickness + DifferenceMap::kPad;
    const Rgb ink = DifferenceMap::kText, paper = DifferenceMap::kPanel;
    EXPECT_TRUE(glyphAt(map, x0, ly, '-', s, ink, paper));
    EXPECT_TRUE(glyphAt(map, x0 + BitmapFont::kCellWidth * s, ly, '1', s, ink, paper));
    EXPECT_TRUE(glyphAt(map, (x0 + x1) / 2 - BitmapFont::textWidth("0", s) / 2, ly, '0', s, ink, paper));
    const int plus = x1 - BitmapFont::textWidth("+1", s);
    EXPECT_TRUE(glyphAt(map, plus, ly, '+', s, ink, paper));
    EXPECT_TRUE(glyphAt(map, plus + BitmapFont::kCellWidth * s, ly, '1', s, ink, paper));
    // The caption's first letter on the line below.
    EXPECT_TRUE(glyphAt(map, x0, ly + BitmapFont::textHeight(s) + DifferenceMap::kPad, 't', s, ink, paper));
}

TEST(AccuracyImagesDifferenceMap, ScaleIsPrintedOnTheBar) {
    const int w = 96, h = 2;
    std::vector<float> v(size_t(w * h), 0.0f);
    std::vector<uint8_t> mask(size_t(w * h), 1);
    const RgbImage map = DifferenceMap::build(v, v, mask, w, h, 0.05f);
    const int s = DifferenceMap::textScale(w);
    const int ly = h + DifferenceMap::kPad + DifferenceMap::kBarThickness + DifferenceMap::kPad;
    const std::string lo = "-0.05";
    for (size_t k = 0; k < lo.size(); ++k)
        EXPECT_TRUE(glyphAt(map, DifferenceMap::kPad + int(k) * BitmapFont::kCellWidth * s, ly, lo[k], s,
                            DifferenceMap::kText, DifferenceMap::kPanel));
}

TEST(AccuracyImagesBitmapFont, DrawsTheTableAndMeasuresText) {
    RgbImage image(40, 12, Rgb{1, 2, 3});
    const Rgb ink{200, 100, 50};
    EXPECT_EQ(BitmapFont::draw(image, 2, 1, "Hg%", ink, 1), 2 + 3 * BitmapFont::kCellWidth);
    EXPECT_TRUE(glyphAt(image, 2, 1, 'H', 1, ink, {1, 2, 3}));
    EXPECT_TRUE(glyphAt(image, 8, 1, 'g', 1, ink, {1, 2, 3}));
    EXPECT_TRUE(glyphAt(image, 14, 1, '%', 1, ink, {1, 2, 3}));
    // Scale 2: each font pixel a 2x2 block; an unknown character is the hollow box.
    RgbImage big(20, 20);
    BitmapFont::draw(big, 0, 0, "\x01", ink, 2);
    for (int gy = 0; gy < 7; ++gy)
        for (int gx = 0; gx < 5; ++gx) {
            const bool border = gx == 0 || gx == 4 || gy == 0 || gy == 6;
            EXPECT_EQ(big.at(gx * 2 + 1, gy * 2 + 1) == ink, border) << gx << ", " << gy;
        }
    EXPECT_EQ(BitmapFont::textWidth("", 1), 0);
    EXPECT_EQ(BitmapFont::textWidth("ab", 1), 11);
    EXPECT_EQ(BitmapFont::textWidth("ab", 3), 33);
    EXPECT_EQ(BitmapFont::fit("abcdef", 17, 1), "abc");
    EXPECT_EQ(BitmapFont::wrap("abcdefg", 17, 1, 5), (std::vector<std::string>{"abc", "def", "g"}));
    EXPECT_EQ(BitmapFont::wrap("abcdefg", 17, 1, 2), (std::vector<std::string>{"abc", "def"}));
    EXPECT_EQ(BitmapFont::wrap("ab", 3, 1, 5), (std::vector<std::string>{"a", "b"}))
        << "one per line at least";
    EXPECT_TRUE(BitmapFont::wrap("", 17, 1, 5).empty());
    // Drawing past the border is clipped, not an error.
    BitmapFont::draw(image, 38, 10, "W", ink, 2);
}

TEST(AccuracyImagesBitmapFont, EveryPrintableCharacterHasAGlyphAndOnlySpaceIsBlank) {
    for (char c = BitmapFont::kFirst; c <= BitmapFont::kLast; ++c) {
        int set = 0;
        for (int y = 0; y < 7; ++y)
            for (int x = 0; x < 5; ++x) set += BitmapFont::pixel(c, x, y);
        EXPECT_EQ(set == 0, c == ' ') << "'" << c << "'";
    }
    // Distinct glyphs for characters that must not be confused in figures and names.
    for (const char* pair : {"0O", "1l", "5S", "8B", "-_", ".,", "%#", "gq"})
        EXPECT_NE(BitmapFont::glyph(pair[0]), BitmapFont::glyph(pair[1])) << pair;
    // One x-height: lowercase letters without an ascender, those with a descender included, leave the
    // top two rows blank.
    for (char c : std::string("acegmnopqrsuvwxyz"))
        for (int x = 0; x < BitmapFont::kGlyphWidth; ++x)
            EXPECT_FALSE(BitmapFont::pixel(c, x, 0) || BitmapFont::pixel(c, x, 1))
                << "'" << c << "' column " << x;
}

/// A map whose every pixel is distinct, so a copy at a wrong offset cannot pass.
RgbImage pattern(int w, int h, uint8_t seed) {
    RgbImage image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) image.set(x, y, {uint8_t(x * 7 + seed), uint8_t(y * 11), uint8_t(seed)});
    return image;
}

TEST(AccuracyImagesContactSheet, TilesAndLabelsGoWhereTheLayoutSays) {
    std::vector<ContactTile> tiles = {
        {"Alpha", {"wrong 1.00%", "x"}, pattern(30, 20, 10)},
        {"Beta", {"wrong 2.00%"}, pattern(30, 20, 90)},
        {"Gamma", {}, pattern(30, 20, 170)},
    };
    const std::vector<std::string> header = {"H"};
    const std::vector<LegendEntry> legend = {{Rgb{1, 200, 3}, "L"}};
    const RgbImage sheet = ContactSheet::compose(header, legend, tiles, 2);
    const ContactSheet::Layout l = ContactSheet::layout(header, legend, tiles, 2);
    ASSERT_EQ(sheet.width(), l.width);
    ASSERT_EQ(sheet.height(), l.height);
    ASSERT_EQ(l.tiles.size(), 3u);
    // The geometry of ContactSheet.h at text scale 1 (maps under 512 px): lines 8 + 3 px apart, the
    // grid after one header line and one legend entry, labels of the tallest tile (3 lines).
    const int m = ContactSheet::kMargin, line = 11;
    EXPECT_EQ(l.textScale, 1);
    EXPECT_EQ(l.lineHeight, line);
    EXPECT_EQ(l.gridTop, m + 2 * line + m);
    EXPECT_EQ(l.labelHeight, 3 * line);
    EXPECT_EQ(l.columns, 2);
    const int xs[] = {m, m + 30 + m, m}, ys[] = {l.gridTop, l.gridTop, l.gridTop + 3 * line + 20 + m};
    for (size_t k = 0; k < 3; ++k) {
        const ContactSheet::Placement& p = l.tiles[k];
        EXPECT_EQ(p.labelX, xs[k]) << k;
        EXPECT_EQ(p.labelY, ys[k]) << k;
        EXPECT_EQ(p.mapX, xs[k]) << k;
        EXPECT_EQ(p.mapY, ys[k] + 3 * line) << k;
        // The map's pixels, exactly, at its offset.
        for (int y = 0; y < 20; ++y)
            for (int x = 0; x < 30; ++x)
                ASSERT_EQ(sheet.at(p.mapX + x, p.mapY + y), tiles[k].map.at(x, y))
                    << "tile " << k << " pixel (" << x << ", " << y << ")";
        // The label: the title's first letter in kTitle, in the font of the table.
        EXPECT_TRUE(glyphAt(sheet, p.labelX, p.labelY, tiles[k].title[0], 1, ContactSheet::kTitle,
                            ContactSheet::kBackground))
            << k;
    }
    // Figures on the lines below the title, in kText: "w" of "wrong".
    EXPECT_TRUE(glyphAt(sheet, l.tiles[0].labelX, l.tiles[0].labelY + line, 'w', 1, ContactSheet::kText,
                        ContactSheet::kBackground));
    // Header and legend: "H" at the top-left margin, the legend's swatch and its "L" after it.
    EXPECT_TRUE(glyphAt(sheet, m, m, 'H', 1, ContactSheet::kText, ContactSheet::kBackground));
    EXPECT_EQ(sheet.at(m, m + line), ContactSheet::kSwatchOutline);
    EXPECT_EQ(sheet.at(m + 1, m + line + 1), (Rgb{1, 200, 3}));
    EXPECT_EQ(sheet.at(m + 5, m + line + 5), (Rgb{1, 200, 3}));
    EXPECT_EQ(sheet.at(m + 6, m + line + 6), ContactSheet::kSwatchOutline);
    EXPECT_TRUE(glyphAt(sheet, m + 7 + 4, m + line, 'L', 1, ContactSheet::kText, ContactSheet::kBackground));
    // The empty fourth cell stays background.
    EXPECT_EQ(sheet.at(l.tiles[1].mapX + 5, l.tiles[2].mapY + 5), ContactSheet::kBackground);
}

TEST(AccuracyImagesContactSheet, WidensForItsHeaderAndCutsLongLabels) {
    const std::string longTitle(40, 'x');
    std::vector<ContactTile> tiles = {{longTitle, {}, pattern(16, 16, 1)}};
    const std::vector<std::string> header = {std::string(30, 'h')};
    const ContactSheet::Layout l = ContactSheet::layout(header, {}, tiles);
    EXPECT_EQ(l.width, ContactSheet::kMargin * 2 + BitmapFont::textWidth(header[0], 1));
    const RgbImage sheet = ContactSheet::compose(header, {}, tiles);
    // The title wraps at the tile's 16 px (two whole characters, 11 px) over kTitleLines lines, the rest
    // dropped; nothing is drawn right of the tile.
    EXPECT_EQ(l.labelHeight, ContactSheet::kTitleLines * l.lineHeight);
    for (int k = 0; k < ContactSheet::kTitleLines; ++k) {
        const int y0 = l.tiles[0].labelY + k * l.lineHeight;
        EXPECT_TRUE(glyphAt(sheet, l.tiles[0].labelX + 6, y0, 'x', 1, ContactSheet::kTitle,
                            ContactSheet::kBackground));
        for (int y = y0; y < y0 + 7; ++y)
            for (int x = l.tiles[0].labelX + 16; x < l.width; ++x)
                ASSERT_EQ(sheet.at(x, y), ContactSheet::kBackground) << x << ", " << y;
    }
    EXPECT_THROW(ContactSheet::compose(header, {}, {}), std::invalid_argument);
}

TEST(AccuracyImagesRgbImage, FlipAndBlitClip) {
    RgbImage a = pattern(3, 2, 5);
    const RgbImage f = a.flippedVertically();
    EXPECT_EQ(f.at(1, 0), a.at(1, 1));
    EXPECT_EQ(f.at(2, 1), a.at(2, 0));
    RgbImage canvas(4, 4, {9, 9, 9});
    canvas.blit(a, 2, 3); // only (2, 3) and (3, 3) land inside
    EXPECT_EQ(canvas.at(2, 3), a.at(0, 0));
    EXPECT_EQ(canvas.at(3, 3), a.at(1, 0));
    EXPECT_EQ(canvas.at(1, 3), (Rgb{9, 9, 9}));
    EXPECT_EQ(flipRows(std::vector<int>{1, 2, 3, 4, 5, 6}, 2, 3), (std::vector<int>{5, 6, 3, 4, 1, 2}));
}

TEST(AccuracyImages, LabelsNeverLeaveTheFolder) {
    EXPECT_EQ(AccuracyImages::fileLabel("shadowmap:pcf=3"), "shadowmap_pcf=3");
    EXPECT_EQ(AccuracyImages::fileLabel("vsm:min_variance=1e-06"), "vsm_min_variance=1e-06");
    // No separator survives, and a leading dot is not left to hide the file.
    EXPECT_EQ(AccuracyImages::fileLabel("../x/y"), "_.._x_y");
    EXPECT_EQ(AccuracyImages::fileLabel(""), "_");
}

TEST(AccuracyImages, FolderIsCheckedUpFront) {
    namespace fs = std::filesystem;
    const std::string dir = test::freshTestDir("images");
    auto codeOf = [](const std::string& path) {
        try {
            AccuracyImages::prepareDirectory(path);
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
            return int(e.code());
        }
        return 0;
    };
    // A new folder under an existing one is created, and left empty (the probe is removed).
    EXPECT_EQ(codeOf(dir + "/new"), 0);
    EXPECT_TRUE(fs::is_directory(dir + "/new"));
    EXPECT_TRUE(fs::is_empty(dir + "/new"));
    // Bad input (2): a file, a folder whose parent is missing (nothing above DIR is created), a place
    // where nothing can be created (root is not stopped by permission bits, /proc stops everyone).
    test::writeFile(dir + "/file", "x");
    EXPECT_EQ(codeOf(dir + "/file"), 2);
    EXPECT_EQ(codeOf(dir + "/missing/deeper"), 2);
    EXPECT_FALSE(fs::exists(dir + "/missing"));
    EXPECT_EQ(codeOf("/proc/shadowbench-images"), 2);
}

TEST(AccuracyImages, SignedMapOnlyWhereVisibilityIsNotBinary) {
    std::vector<float> v = {0.0f, 1.0f, 0.001f, 0.999f};
    std::vector<uint8_t> mask = {1, 1, 1, 1};
    EXPECT_FALSE(AccuracyImages::fractional(v, mask)) << "0.001 and 0.999 are 0 and 255 in 8 bits";
    v.push_back(0.5f);
    mask.push_back(0);
    EXPECT_FALSE(AccuracyImages::fractional(v, mask)) << "not judged";
    mask.back() = 1;
    EXPECT_TRUE(AccuracyImages::fractional(v, mask));
}

TEST(AccuracyImagesGoldenDiff, ChangedPixelsOfASyntheticPairAreMarked) {
    // A synthetic golden pair (the golden check's own CLI test, AccuracyImagesCliTest, runs the real
    // one): a 16x8 visibility golden, left half lit; the rendered image flips two samples far from the
    // edge and brightens one shadowed sample a little (no flip).
    Image8 golden;
    golden.width = 16, golden.height = 8, golden.channels = 1;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) golden.pixels.push_back(x < 8 ? 255 : 0);
    Image8 rendered = golden;
    rendered.pixels[2 * 16 + 1] = 0;    // false shadow at (1, 2)
    rendered.pixels[5 * 16 + 13] = 255; // false light at (13, 5)
    rendered.pixels[6 * 16 + 12] = 40;  // 40/255 < 0.5: still shadowed
    const std::string dir = test::freshTestDir("golden-diff");
    const GoldenChange change{"visibility", "golden.png", golden, rendered};
    const std::vector<std::string> written =
        GoldenDiff::write(dir, "shadowmap/sphere_plane/retained", change);
    ASSERT_EQ(written.size(), 2u);
    EXPECT_EQ(written[0], dir + "/shadowmap.sphere_plane.retained.visibility.light0.error.png");
    EXPECT_EQ(written[1], dir + "/shadowmap.sphere_plane.retained.visibility.light0.signed.png");
    const Image8 error = GoldenImage::read(written[0]);
    ASSERT_EQ(error.width, 16);
    ASSERT_EQ(error.channels, 3);
    auto at = [&](const Image8& image, int x, int y) {
        const uint8_t* p = &image.pixels[size_t(y * image.width + x) * 3];
        return Rgb{p[0], p[1], p[2]};
    };
    int marked = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) {
            const Rgb c = at(error, x, y);
            marked += c == ErrorMap::kFalseShadow || c == ErrorMap::kFalseLight ||
                      c == ErrorMap::kFalseShadowEdge || c == ErrorMap::kFalseLightEdge;
        }
    EXPECT_EQ(marked, 2);
    EXPECT_EQ(at(error, 1, 2), ErrorMap::kFalseShadow);
    EXPECT_EQ(at(error, 13, 5), ErrorMap::kFalseLight);
    // The signed map: scale niceScale(1) = 1; +40/255 at (12, 6) is a light red.
    const Image8 diff = GoldenImage::read(written[1]);
    EXPECT_EQ(diff.height, 8 + DifferenceMap::barHeight(16));
    EXPECT_EQ(at(diff, 13, 5), (Rgb{255, 0, 0}));
    EXPECT_EQ(at(diff, 1, 2), (Rgb{0, 0, 255}));
    EXPECT_EQ(at(diff, 12, 6), DifferenceMap::colour(40.0f / 255.0f));
    EXPECT_EQ(at(diff, 0, 0), (Rgb{255, 255, 255}));
    // A colour change: one signed luminance map.
    Image8 colourGolden = golden, colourRendered = rendered;
    colourGolden.channels = colourRendered.channels = 1;
    const auto colourFiles = GoldenDiff::write(dir, "none/teapot/retained/vulkan",
                                               {"colour", "c.png", colourGolden, colourRendered});
    ASSERT_EQ(colourFiles.size(), 1u);
    EXPECT_EQ(colourFiles[0], dir + "/none.teapot.retained.vulkan.colour.signed.png");
    EXPECT_TRUE(std::filesystem::exists(colourFiles[0]));
}

} // namespace
