// `bench floors` under callgrind (bench/floors/PassProbe.cpp dumps at every pass boundary and around
// every floor; FloorsCommand reads the dumps back from the working folder): the instruction columns are
// filled for every pass that has a floor, their ratio is the quotient of the two printed counts, and
// the dumps are where the help says (callgrind.out.<pid>.N in the working folder). A tiny configuration:
// one frame of none and of shadowmap with a 64^2 map at 32x32 (about 15 s, most of it valgrind's start).
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/callgrind/InstructionCount.h"

namespace sb {
namespace {

namespace fs = std::filesystem;

TEST(FloorsValgrind, EveryPassAndFloorIsCountedFromTheDumps) {
    ASSERT_TRUE(InstructionCount::valgrindAvailable()) << "valgrind is needed (scripts/install-deps.sh)";
    const std::string dir = test::freshDir("floors-valgrind");
    const auto r = test::runCommand("cd " + dir +
                                    " && LP_NUM_THREADS=0 valgrind -q --tool=callgrind --instr-atstart=no " +
                                    SB_BENCH_BINARY +
                                    " floors -t none -t shadowmap:resolution=64 --scene sphere_plane"
                                    " --size 32x32 --frames 1 --warmup 0 --format md");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("under callgrind: instructions exact"), std::string::npos) << r.output;
    int rows = 0;
    std::istringstream in(r.output);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("| none ", 0) != 0 && line.rfind("| shadowmap ", 0) != 0) continue;
        std::vector<std::string> cells;
        std::stringstream cs(line.substr(1));
        for (std::string c; std::getline(cs, c, '|');) cells.push_back(c);
        ASSERT_GE(cells.size(), 13u) << line;
        // technique, pass, kind, target, fragments, floor fragments, pass ms, floor ms, pass/floor,
        // pass Ir, floor Ir, Ir pass/floor, note
        const double pass = std::stod(cells[9]), floor = std::stod(cells[10]), ratio = std::stod(cells[11]);
        EXPECT_GT(pass, 0.0) << line;
        EXPECT_GT(floor, 0.0) << line;
        EXPECT_NEAR(ratio, pass / floor, 1e-3) << line; // printed with 3 decimals
        ++rows;
    }
    EXPECT_EQ(rows, 3) << r.output; // none: lighting; shadowmap: depth, lighting
    int dumps = 0;
    for (const auto& entry : fs::directory_iterator(dir))
        dumps += entry.path().filename().string().rfind("callgrind.out.", 0) == 0;
    EXPECT_GT(dumps, 6) << "one dump per pass and per floor of each measured frame";
    fs::remove_all(dir);
}

} // namespace
} // namespace sb
