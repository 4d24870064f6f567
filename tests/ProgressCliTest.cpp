// The progress of the long subcommands on a non-terminal stderr (a CI log, a pipe): `bench golden` and
// `bench ci` print one line per finished cell or configuration with done/total, and golden's repeated
// per-cell warnings come once, with their count, at the end. Each run is the smallest subset the
// filters allow; the totals are counted by hand from what the subset is:
//   golden --scene synthetic_draws --technique planar: one technique in the four GL submission
//   modes (immediate, display list, retained, instanced) and Vulkan's two (retained, instanced) = 6
//   cells. The scene declares no receiver plane, so planar says so in every cell, GL and Vulkan.
//   Of the two built-in scenes without one it is the smaller (10000 quads against synthetic_triangles'
//   million triangles, whose run took 25 s instead of 4, and 53 s under the sanitizers).
//   ci --quick --configs none_aircraft,none_vulkan: layer A only, two configurations = 2.
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "TestPaths.h"
#include "TestSupport.h"

using namespace sb;

namespace {

size_t count(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
}

/// The progress lines ProgressBar writes off a terminal: "ok     <label>  (<done>/<total>, ...".
std::vector<std::pair<std::string, std::string>> progressLines(const std::string& output) {
    static const std::regex kLine(R"((ok    |FAILED) (.+)  \((\d+/\d+),)");
    std::vector<std::pair<std::string, std::string>> out;
    for (auto it = std::sregex_iterator(output.begin(), output.end(), kLine); it != std::sregex_iterator();
         ++it)
        out.emplace_back((*it)[2].str(), (*it)[3].str());
    return out;
}

TEST(ProgressCliTest, GoldenCountsCellsAndSaysARepeatedWarningOnce) {
    const std::string diff = test::freshTestDir("progress");
    const test::CommandResult r = test::runCommand(std::string(test::benchBinary()) +
                                                   " golden --check --scene synthetic_draws --technique "
                                                   "planar --diff-dir " +
                                                   diff);
    std::filesystem::remove_all(diff);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto lines = progressLines(r.output);
    ASSERT_EQ(lines.size(), 6u) << r.output;
    for (size_t i = 0; i < lines.size(); ++i)
        EXPECT_EQ(lines[i].second, std::to_string(i + 1) + "/6") << r.output;
    EXPECT_EQ(lines.front().first, "planar/synthetic_draws/retained");
    EXPECT_EQ(lines.back().first, "planar/synthetic_draws/instanced/vulkan");
    // The technique's line appears once, inside the summary, which counts the six cells (the four GL
    // modes and planar's Vulkan form in its two).
    const std::string cause = "planar: scene 'synthetic_draws' declares no receiver plane";
    EXPECT_EQ(count(r.output, cause), 1u) << r.output;
    EXPECT_NE(r.output.find("warning: 6 cells: " + cause), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("(first: planar/synthetic_draws/retained)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("golden check: 6 cells checked, 0 failed, 0 unsupported"), std::string::npos)
        << r.output;
}

TEST(ProgressCliTest, CiCountsConfigurations) {
    const std::string out = test::freshTestDir("progress");
    const test::CommandResult r = test::runCommand(
        std::string(test::benchBinary()) + " ci --quick --configs none_aircraft,none_vulkan --out " + out);
    std::filesystem::remove_all(out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto lines = progressLines(r.output);
    ASSERT_EQ(lines.size(), 2u) << r.output;
    EXPECT_EQ(lines[0], std::make_pair(std::string("work none_aircraft (head)"), std::string("1/2")));
    EXPECT_EQ(lines[1], std::make_pair(std::string("work none_vulkan (head)"), std::string("2/2")));
    EXPECT_NE(r.output.find("exact work of 2 configurations"), std::string::npos) << r.output;
}

} // namespace
