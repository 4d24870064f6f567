// Instructions per measured frame, measured for real: the bench under callgrind (bench/ci/InstructionCount)
// on a small configuration (256x256, 10 instances, one warm-up frame), `-t none -t shadowmap` in one
// process (two dumps), three runs: N frames, the same again, and 2N frames. 20-30 s per run (mostly
// valgrind's start-up and the uninstrumented shader compiles), 80 s in all on a loaded 2-core machine;
// skipped when valgrind is not installed. Prints each run's numbers (the figures of the
// instruction-count layer) as JSON.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>

#include "TestPaths.h"
#include "bench/ci/Fingerprint.h"
#include "bench/ci/InstructionCount.h"
#include "bench/ci/InstructionLayer.h"

using namespace sb;
namespace fs = std::filesystem;

namespace {

constexpr int kFrames = 3;

InstructionRun countFrames(int frames, const std::string& tag) {
    InstructionCount::Options o;
    o.bench = SB_BENCH_BINARY;
    o.benchArgs = {"-t", "none", "-t", "shadowmap", "--frames", std::to_string(frames)};
    const std::vector<std::string> small = {"--warmup",    "1",  "--size",          "256x256",
                                            "--instances", "10", "--no-timer-check"};
    o.benchArgs.insert(o.benchArgs.end(), small.begin(), small.end());
    o.outDir = (fs::temp_directory_path() / ("sb-ir-" + std::to_string(getpid()) + "-" + tag)).string();
    InstructionRun run = InstructionCount(o).run();
    fs::remove_all(o.outDir);
    nlohmann::json figures = run.toJson(5);
    figures["run"] = tag;
    std::cout << figures.dump() << "\n";
    return run;
}

double relativeDifference(double a, double b) {
    return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
}

class InstructionCountValgrindTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!InstructionCount::valgrindAvailable())
            GTEST_SKIP() << "valgrind is not installed (apt-get install valgrind)";
    }
};

} // namespace

TEST_F(InstructionCountValgrindTest, CountsOnlyTheMeasuredFramesAndRepeatsExactlyOutsideLibc) {
    const InstructionRun a = countFrames(kFrames, "a");
    const InstructionRun again = countFrames(kFrames, "again");
    const InstructionRun twice = countFrames(2 * kFrames, "twice");
    ASSERT_EQ(a.techniques.size(), 2u);
    ASSERT_EQ(again.techniques.size(), 2u);
    ASSERT_EQ(twice.techniques.size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
        const TechniqueInstructions& n = a.techniques[i];
        const TechniqueInstructions& n2 = again.techniques[i];
        const TechniqueInstructions& n2x = twice.techniques[i];
        SCOPED_TRACE(n.technique);
        EXPECT_EQ(n.technique, i == 0 ? "none" : "shadowmap");
        EXPECT_EQ(n.frames, kFrames);
        EXPECT_EQ(n2x.frames, 2 * kFrames);
        // Millions of instructions per frame even for `none` (a 256x256 clear and 10 instances drawn).
        EXPECT_GT(n.irPerFrame, 1e6);

        // Repeatability. With the pinned environment (LP_NUM_THREADS=0: no rasteriser thread) repeated
        // runs are bit-identical in the driver, the shader code and the harness; libc is not. In a full
        // parallel ctest run (landing CI of 2026-12-04) a pair of `none` runs differed by 2.76e-4 in
        // total, every instruction of it in System (607107 against 636357 Ir over 3 frames: calloc's
        // memset clears reused heap memory but not fresh pages, so it follows the heap's history), while
        // Mesa, ShaderJit and Harness were equal to the instruction. So: everything outside libc within
        // 2e-4 (0 measured; once 1.006e-4 before the categories were compared), and the total within the
        // gate's A/A limit, 1e-3 (InstructionLayer::kUnstableAbove), which still fails a run that lost its
        // pinning only if it drifts further: with one rasteriser thread identical runs spread by 7.6e-4.
        double outside = 0.0, outside2 = 0.0;
        for (int c = 0; c < kCostCategoryCount; ++c)
            if (c != int(CostCategory::System)) {
                outside += double(n.byCategory[c]);
                outside2 += double(n2.byCategory[c]);
            }
        EXPECT_LT(relativeDifference(outside, outside2), 2e-4) << outside << " vs " << outside2;
        EXPECT_LT(relativeDifference(n.irPerFrame, n2.irPerFrame), InstructionLayer::kUnstableAbove)
            << n.irPerFrame << " vs " << n2.irPerFrame;

        // Only the measured frames are counted. Two points give the cost of a frame, (T(2N) - T(N)) / N,
        // and what the bracket counts once per run, 2 T(N) - T(2N): the latter must be far below one
        // frame. Client requests in the wrong place would count the warm-up and census frames too (a
        // fixed cost of 2 frames, 200%), no requests at all the whole process (far more). Measured: 0.06%
        // (none) and 0.24% (shadowmap, libc's memset in calloc, which clears reused heap memory but not
        // fresh pages, so it follows the heap's history); 1% leaves a margin of 4.
        const double frameIr = double(n2x.totalIr - n.totalIr) / kFrames;
        const double fixedIr = 2.0 * double(n.totalIr) - double(n2x.totalIr);
        EXPECT_LT(std::abs(fixedIr), 0.01 * frameIr) << "fixed " << fixedIr << " Ir, frame " << frameIr;
        // Hence Ir per frame of N and 2N frames agree within fixed / (2N frame) < 1% / 6 = 1.7e-3, and
        // the total of 2N frames is twice that of N within 2 * 1.7e-3.
        EXPECT_LT(relativeDifference(n.irPerFrame, n2x.irPerFrame), 2e-3)
            << n.irPerFrame << " vs " << n2x.irPerFrame;
        EXPECT_NEAR(double(n2x.totalIr) / double(n.totalIr), 2.0, 4e-3);

        // The categories partition the count, and the frames run shader code, the driver and the harness.
        uint64_t sum = 0;
        for (uint64_t c : n.byCategory) sum += c;
        EXPECT_EQ(sum, n.totalIr);
        EXPECT_GT(n.fraction(CostCategory::ShaderJit), 0.0);
        EXPECT_GT(n.fraction(CostCategory::Mesa), 0.0);
        EXPECT_GT(n.fraction(CostCategory::Harness), 0.0);
    }
    // Each dump is its own technique: shadowmap renders a depth pass on top of what none does.
    EXPECT_GT(a.techniques[1].irPerFrame, a.techniques[0].irPerFrame * 1.2);
    // The pinned environment reached the child, and the rows say so.
    EXPECT_EQ(a.environment.at("LP_NUM_THREADS"), "0");
    EXPECT_EQ(a.rows.at(0).at("lp_num_threads"), 0);
    EXPECT_EQ(a.environment.count("HOME"), 0u); // the caller's environment stays out
    const Fingerprint f = Fingerprint::capture(a.rows.at(0), InstructionCount::valgrindVersion(), a.pinned);
    std::cout << f.toJson().dump() << "\n";
    EXPECT_TRUE(f.differences(Fingerprint::capture(twice.rows.at(0), InstructionCount::valgrindVersion(),
                                                   twice.pinned))
                    .empty());
}
