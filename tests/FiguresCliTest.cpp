// `bench figures --reduced` end to end: every declared figure's small variant is measured,
// classified where it is a bottleneck figure, plotted by tools/plot.py and summarised, so the path from
// declaration to PNG never rots. The checks are structural (the files exist and are what they claim to
// be, the rows are the plan's); the numbers are the other tests' business.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"

using namespace sb;
using test::runCommand;

namespace {
const std::string kBench = SB_BENCH_BINARY;

bool isPng(const std::string& path) {
    const std::string head = test::readFile(path).substr(0, 8);
    return head == std::string("\x89PNG\r\n\x1a\n", 8);
}

std::vector<std::string> declaredFigures() {
    std::ifstream in(std::string(SB_SOURCE_DIR) + "/results/figures/figures.json");
    const nlohmann::json doc = nlohmann::json::parse(in, nullptr, true, true);
    std::vector<std::string> names;
    for (const auto& f : doc) names.push_back(f["name"]);
    return names;
}
} // namespace

TEST(FiguresCli, ReducedRunWritesEveryFigure) {
    const std::string dir = test::freshDir("figures");
    auto r = runCommand(kBench + " figures --reduced --no-progress --out " + dir);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto names = declaredFigures();
    ASSERT_GE(names.size(), 4u);
    for (const std::string& name : names) {
        const std::string f = dir + "/" + name;
        SCOPED_TRACE(name);
        EXPECT_TRUE(isPng(f + "/figure.png"));
        EXPECT_NE(test::readFile(f + "/figure.svg").find("<svg"), std::string::npos);
        const std::string summary = test::readFile(f + "/summary.md");
        EXPECT_NE(summary.find("Claim tested:"), std::string::npos);
        EXPECT_NE(summary.find("figure.png"), std::string::npos);
        const CsvTable data = CsvWriter::read(f + "/data.csv");
        ASSERT_FALSE(data.rows.empty());
        EXPECT_FALSE(std::filesystem::exists(f + "/data.partial.csv")) << "renamed once complete";
        if (name.rfind("bottleneck", 0) == 0) {
            EXPECT_FALSE(CsvWriter::read(f + "/classes.csv").rows.empty());
        }
    }
    // Replotting from the CSVs alone.
    auto again = runCommand(kBench + " figures --reduced --plot-only --only instances_teapot --out " + dir);
    EXPECT_EQ(again.exitCode, 0) << again.output;
    auto bad = runCommand(kBench + " figures --reduced --only nosuch --out " + dir);
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("nosuch"), std::string::npos) << bad.output;
}
