// The technique x submission x scene matrix, checked on every run (bench/golden/MatrixCheck.h): every
// registered technique in every submission mode on every built-in scene at 128^2 must (a) render the same
// image as in retained mode, (b) match the committed golden in results/goldens/, and (c) stay within its
// committed accuracy bound against the Embree reference. `bench golden --check` runs the same check;
// `bench golden --update` regenerates goldens and bounds (README, "Run the tests").
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include <algorithm>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "bench/golden/GoldenCommand.h"
#include "bench/golden/GoldenImage.h"
#include "bench/golden/GoldenMatrix.h"
#include "bench/golden/MatrixCheck.h"
#include "bench/golden/MatrixVariants.h"
#include "core/DriverTable.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

std::map<std::string, AccuracyBound> committedBounds() {
    return AccuracyBounds::read(std::string(SB_SOURCE_DIR) + "/results/goldens/bounds.json");
}

class Matrix : public ::testing::TestWithParam<std::string> {};

TEST_P(Matrix, EveryCellMatchesRetainedGoldenAndBound) {
    const std::string scene = GetParam();
    const std::vector<MatrixCell> cells = GoldenMatrix::renderScene(scene, MatrixOptions{});
    // Every technique in every mode is a cell, and so is every variant a technique declares
    // (bench/golden/MatrixVariants.h) and -t auto: none may be dropped on the way. The Vulkan axis adds
    // each of them in Vulkan's two modes (retained, instanced), supported or not.
    const size_t techniques = MatrixVariants::all().size() + 1;
    EXPECT_GT(MatrixVariants::all().size(), TechniqueRegistry::names().size()); // raytraced's two
    ASSERT_EQ(cells.size(), techniques * (std::size(kAllSubmitModes) + 2));
    EXPECT_EQ(
        size_t(std::count_if(cells.begin(), cells.end(), [](const MatrixCell& c) { return c.vulkan(); })),
        techniques * 2);
    const std::vector<CellVerdict> verdicts =
        MatrixCheck::check(cells, std::string(SB_SOURCE_DIR) + "/results/goldens", committedBounds());
    size_t checked = 0, unsupported = 0, notRun = 0;
    for (const CellVerdict& v : verdicts) {
        if (!v.notRun.empty()) { // judged on a driver that can run it (tests/CMakeLists.txt), said here
            ++notRun;
            std::cout << v.cell << ": not run: " << v.notRun << "\n";
            continue;
        }
        if (!v.unsupported.empty() && v.passed()) {
            ++unsupported;
            std::cout << v.cell << ": unsupported: " << v.unsupported << "\n";
            continue;
        }
        ++checked;
        std::string failures;
        for (const std::string& f : v.failures) failures += "\n  " + f;
        EXPECT_TRUE(v.passed()) << v.cell << failures;
    }
    std::cout << scene << ": " << checked << " cells checked, " << unsupported << " unsupported, " << notRun
              << " not run on the driver " << DriverTable::current() << "\n";
}

INSTANTIATE_TEST_SUITE_P(Scenes, Matrix, ::testing::ValuesIn(GoldenMatrix::builtinScenes()),
                         [](const auto& p) { return p.param; });

} // namespace

namespace {

// Negative controls: the check must see a golden that no longer matches, a bound loosened past its rule
// and a missing golden. sphere_plane is the smallest scene; the goldens are copied, then broken.
TEST(MatrixCheck, ChangedGoldenLooseBoundAndMissingGoldenAreCaught) {
    namespace fs = std::filesystem;
    const std::string dir = test::freshTestDir("matrix");
    fs::copy(std::string(SB_SOURCE_DIR) + "/results/goldens", dir, fs::copy_options::recursive);
    MatrixOptions options;
    options.scenes = {"sphere_plane"};
    options.techniques = {"none", "shadowmap", "volume"};
    const std::vector<MatrixCell> cells = GoldenMatrix::renderScene("sphere_plane", options);

    // shadowmap's visibility golden: 1% of the pixels inverted (the tolerance allows 0.5%).
    const std::string vis = MatrixCheck::goldenPath(dir, "sphere_plane", "shadowmap", "visibility");
    Image8 golden = GoldenImage::read(vis);
    for (size_t p = 0; p < golden.pixelCount() / 100; ++p) {
        uint8_t& v = golden.pixels[p * 97 % golden.pixelCount() * size_t(golden.channels)];
        v = uint8_t(255 - v);
    }
    GoldenImage::write(vis, golden);
    // volume's bound loosened past its rule (exact: 0.5% off the edge band).
    std::map<std::string, AccuracyBound> bounds = AccuracyBounds::read(dir + "/bounds.json");
    bounds["volume/sphere_plane/light0"].max = 5.0;
    // none's colour golden removed.
    fs::remove(MatrixCheck::goldenPath(dir, "sphere_plane", "none", "colour"));

    std::map<std::string, std::string> failures;
    for (const CellVerdict& v : MatrixCheck::check(cells, dir, bounds))
        for (const std::string& f : v.failures) failures[v.cell] += f + "\n";
    EXPECT_NE(failures["shadowmap/sphere_plane/retained"].find("visibility vs golden"), std::string::npos)
        << failures["shadowmap/sphere_plane/retained"];
    EXPECT_NE(failures["volume/sphere_plane/retained"].find("looser than the rule"), std::string::npos)
        << failures["volume/sphere_plane/retained"];
    EXPECT_NE(failures["none/sphere_plane/retained"].find("no golden"), std::string::npos)
        << failures["none/sphere_plane/retained"];
    // Nothing else: every mode of a technique fails on its injected fault only (modes share the golden
    // and the bound), and every line of a failure is that fault.
    const std::map<std::string, std::string> injected = {
        {"shadowmap", "visibility vs golden"}, {"volume", "looser than the rule"}, {"none", "no golden"}};
    for (const auto& [cell, text] : failures) {
        const std::string technique = cell.substr(0, cell.find('/'));
        ASSERT_TRUE(injected.count(technique)) << cell << ": " << text;
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);)
            EXPECT_NE(line.find(injected.at(technique)), std::string::npos) << cell << ": " << line;
    }
}

} // namespace

namespace {

// An update of one technique on one scene rewrites that technique's cells only: every other cell of
// bounds.json keeps its rule, bound and measured value exactly (it once came back with measured 0).
TEST(MatrixUpdate, APartialUpdateKeepsEveryOtherCellAsItWas) {
    namespace fs = std::filesystem;
    const std::string dir = test::freshTestDir("matrix-update");
    fs::copy(std::string(SB_SOURCE_DIR) + "/results/goldens", dir, fs::copy_options::recursive);
    const nlohmann::json before = nlohmann::json::parse(test::readFile(dir + "/bounds.json"));
    std::vector<std::string> args = {"golden",  "--update",     "--dir",       dir,
                                     "--scene", "sphere_plane", "--technique", "none"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    testing::internal::CaptureStdout();
    const int code = GoldenCommand::main(int(argv.size()), argv.data());
    const std::string out = testing::internal::GetCapturedStdout();
    ASSERT_EQ(code, 0) << out;
    const nlohmann::json after = nlohmann::json::parse(test::readFile(dir + "/bounds.json"));
    ASSERT_EQ(after["cells"].size(), before["cells"].size());
    size_t kept = 0;
    for (const auto& [cell, entry] : before["cells"].items()) {
        if (cell.rfind("none/sphere_plane/", 0) == 0) continue;
        EXPECT_EQ(after["cells"][cell], entry) << cell;
        ++kept;
    }
    EXPECT_GT(kept, 100u); // the matrix's other cells, not an empty file
    // none's own cell: no shadow is judged exactly, so its rewritten value is the committed one.
    EXPECT_EQ(after["cells"]["none/sphere_plane/light0"], before["cells"]["none/sphere_plane/light0"]);
}

} // namespace
