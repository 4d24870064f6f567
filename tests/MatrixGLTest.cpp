// The technique x submission x scene matrix, checked on every run (bench/golden/MatrixCheck.h): every
// registered technique in every submission mode on every built-in scene at 128^2 must (a) render the same
// image as in retained mode, (b) match the committed golden in results/goldens/, and (c) stay within its
// committed accuracy bound against the Embree reference. `bench golden --check` runs the same check;
// `bench golden --update` regenerates goldens and bounds (README, "Run the tests").
#include <iostream>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/golden/GoldenMatrix.h"
#include "bench/golden/MatrixCheck.h"
#include "techniques/TechniqueRegistry.h"

using namespace sb;

namespace {

std::map<std::string, AccuracyBound> committedBounds() {
    std::map<std::string, AccuracyBound> out;
    for (AccuracyBound& b : AccuracyBounds::read(std::string(SB_SOURCE_DIR) + "/results/goldens/bounds.json"))
        out[b.cell] = std::move(b);
    return out;
}

class Matrix : public ::testing::TestWithParam<std::string> {};

TEST_P(Matrix, EveryCellMatchesRetainedGoldenAndBound) {
    const std::string scene = GetParam();
    const std::vector<MatrixCell> cells = GoldenMatrix::renderScene(scene, MatrixOptions{});
    // Every technique in every mode is a cell: none may be dropped on the way.
    ASSERT_EQ(cells.size(), TechniqueRegistry::names().size() * std::size(kAllSubmitModes));
    const std::vector<CellVerdict> verdicts =
        MatrixCheck::check(cells, std::string(SB_SOURCE_DIR) + "/results/goldens", committedBounds());
    size_t checked = 0, unsupported = 0;
    for (const CellVerdict& v : verdicts) {
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
    std::cout << scene << ": " << checked << " cells checked, " << unsupported << " unsupported\n";
}

INSTANTIATE_TEST_SUITE_P(Scenes, Matrix, ::testing::ValuesIn(GoldenMatrix::builtinScenes()),
                         [](const auto& p) { return p.param; });

} // namespace
