// `bench floors` through the binary (bench/floors/FloorsCommand.h): every pass of shadowmap and volume
// gets a row with its kind, its target, its fragments and the ratio of its time to its floor's, at a
// tiny size. The fragments are checked against `bench explain`'s census of the same options, run as a
// separate command; the kinds and targets against what the techniques draw into (techniques/shadowmap:
// a depth-only map; techniques/volume: the stencil of the frame targets).
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"

namespace sb {
namespace {

const std::string kBench = SB_BENCH_BINARY;
const std::string kOptions = " -t shadowmap -t volume --scene sphere_plane --size 64x64";

std::vector<std::string> cellsOf(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream in(line.substr(1)); // after the leading '|'
    for (std::string cell; std::getline(in, cell, '|');) {
        const size_t b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
        cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
    }
    return cells;
}

/// (technique, pass) -> the Markdown row's cells, keyed by the heading.
std::map<std::pair<std::string, std::string>, std::map<std::string, std::string>>
rowsOf(const std::string& out) {
    std::map<std::pair<std::string, std::string>, std::map<std::string, std::string>> rows;
    std::vector<std::string> headings;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("| ", 0) != 0) continue;
        std::vector<std::string> cells = cellsOf(line);
        if (headings.empty()) {
            headings = cells;
            continue;
        }
        if (cells.empty() || cells[0] == "---") continue;
        std::map<std::string, std::string> row;
        for (size_t i = 0; i < cells.size() && i < headings.size(); ++i) row[headings[i]] = cells[i];
        rows[{row["technique"], row["pass"]}] = row;
    }
    return rows;
}

/// `bench explain`'s fragments per (technique, pass): "    depth     ran  1 draws, ..., 1234 fragments".
std::map<std::pair<std::string, std::string>, std::string> explainedFragments(const std::string& out) {
    std::map<std::pair<std::string, std::string>, std::string> fragments;
    const std::regex pass(R"(^\s+(\w+)\s+ran\s+.*, (\d+) fragments$)");
    std::string technique;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("shadowmap ", 0) == 0) technique = "shadowmap";
        if (line.rfind("volume ", 0) == 0) technique = "volume";
        std::smatch m;
        if (std::regex_match(line, m, pass)) fragments[{technique, m[1]}] = m[2];
    }
    return fragments;
}

TEST(FloorsCli, EveryPassOfShadowmapAndVolumeHasItsFloorAndRatio) {
    const auto r = test::runCommand(kBench + " floors" + kOptions + " --frames 2 --warmup 0 --format md");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto explain = test::runCommand(kBench + " explain" + kOptions);
    ASSERT_EQ(explain.exitCode, 0) << explain.output;
    const auto fragments = explainedFragments(explain.output);
    const auto rows = rowsOf(r.output);
    struct Expected {
        const char* technique;
        const char* pass;
        const char* kind;
        const char* target; ///< a regular expression
    };
    const Expected expected[] = {
        {"shadowmap", "depth", "depth", R"(\d+x\d+ DEPTH_COMPONENT\w+)"},
        {"shadowmap", "lighting", "lit", "64x64 RGBA8\\+DEPTH24_STENCIL8"},
        {"volume", "ambient", "lit", "64x64 RGBA8\\+DEPTH24_STENCIL8"},
        {"volume", "mark", "stencil", "64x64 RGBA8\\+DEPTH24_STENCIL8"},
        {"volume", "lighting", "lit", "64x64 RGBA8\\+DEPTH24_STENCIL8"},
    };
    EXPECT_EQ(rows.size(), std::size(expected)) << r.output;
    for (const Expected& e : expected) {
        SCOPED_TRACE(std::string(e.technique) + " " + e.pass);
        const auto it = rows.find({e.technique, e.pass});
        ASSERT_NE(it, rows.end()) << r.output;
        const auto& row = it->second;
        EXPECT_EQ(row.at("kind"), e.kind);
        EXPECT_TRUE(std::regex_match(row.at("target"), std::regex(e.target))) << row.at("target");
        ASSERT_TRUE(fragments.count({e.technique, e.pass})) << explain.output;
        EXPECT_EQ(row.at("fragments"), fragments.at({e.technique, e.pass}));
        EXPECT_GT(std::stoull(row.at("fragments")), 0u);
        // Timed on both sides, with a finite positive ratio; no note (every pass has its floor).
        EXPECT_GT(std::stod(row.at("pass ms")), 0.0);
        EXPECT_GT(std::stod(row.at("floor ms")), 0.0);
        EXPECT_GT(std::stod(row.at("pass/floor")), 0.0);
        EXPECT_EQ(row.at("note"), "-");
        EXPECT_EQ(row.at("pass Ir"), "-") << "instructions are counted only under callgrind";
    }
}

TEST(FloorsCli, ConsoleTableHelpAndVulkan) {
    const auto r = test::runCommand(kBench + " floors -t none --size 32x32 --frames 1 --warmup 0");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("scene aircraft, 32x32"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("pass/floor"), std::string::npos) << r.output;
    EXPECT_TRUE(
        std::regex_search(r.output, std::regex(R"(none\s+lighting\s+lit\s+32x32 RGBA8\+DEPTH24_STENCIL8)")))
        << r.output;
    const auto help = test::runCommand(kBench + " floors --help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.output.find("bench floors [options]: the options of a run"), std::string::npos)
        << help.output;
    EXPECT_NE(help.output.find("  bench floors -t shadowmap -t volume"), std::string::npos) << help.output;
    EXPECT_NE(test::runCommand(kBench + " --help").output.find("bench floors [options]"), std::string::npos);
    // GL only: Vulkan is what this machine's bench floors lacks (exit 3), with the reason.
    const auto vulkan = test::runCommand(kBench + " floors --api vulkan -t none --size 32x32");
    EXPECT_EQ(vulkan.exitCode, 3) << vulkan.output;
    EXPECT_NE(vulkan.output.find("bench floors renders with GL only"), std::string::npos) << vulkan.output;
}

} // namespace
} // namespace sb
