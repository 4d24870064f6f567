// The dashboard exports read by the tool they are for: two real runs exported with
// `bench export --format gbench` and compared by Google Benchmark's own compare.py (Debian's
// libbenchmark-tools), whose relative time change must be the one computed here from the two CSVs; and
// the github-action-benchmark file carries each row's median and exact work. Skipped without
// compare.py or SciPy (scripts/install-deps.sh installs both). About 15 s.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestPaths.h"
#include "TestSupport.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kCompare = "/usr/share/benchmark/compare.py";

class DashboardCliTest : public ::testing::Test {
protected:
    void SetUp() override { mDir = test::freshTestDir("dashboard"); }
    void TearDown() override { fs::remove_all(mDir); }
    std::string path(const std::string& name) const { return (fs::path(mDir) / name).string(); }
    void measure(const std::string& csv) const {
        const auto r =
            test::runCommand(std::string(SB_BENCH_BINARY) +
                             " -t none -t shadowmap --frames 3 --warmup 1 --size 96x96 --instances 10"
                             " --no-timer-check -q --csv " +
                             csv);
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    std::string mDir;
};

} // namespace

TEST_F(DashboardCliTest, GoogleBenchmarksComparePyReadsTheExportAndAgreesWithTheCsv) {
    if (!fs::exists(kCompare)) GTEST_SKIP() << "apt-get install libbenchmark-tools";
    if (test::runCommand("/usr/bin/python3 -c 'import scipy'").exitCode != 0)
        GTEST_SKIP() << "compare.py needs SciPy: apt-get install python3-scipy";
    measure(path("a.csv"));
    measure(path("b.csv"));
    for (const char* side : {"a", "b"}) {
        const auto e =
            test::runCommand(std::string(SB_BENCH_BINARY) + " export " + path(std::string(side) + ".csv") +
                             " --format gbench -o " + path(std::string(side) + ".json"));
        ASSERT_EQ(e.exitCode, 0) << e.output;
    }
    const auto cmp =
        test::runCommand("/usr/bin/python3 " + std::string(kCompare) + " --no-color -d " + path("diff.json") +
                         " benchmarks " + path("a.json") + " " + path("b.json"));
    ASSERT_EQ(cmp.exitCode, 0) << cmp.output;
    const json diff = json::parse(test::readFile(path("diff.json")));
    const auto a = test::csvRowMaps(path("a.csv"));
    const auto b = test::csvRowMaps(path("b.csv"));
    // One entry per benchmark, then compare.py's own OVERALL_GEOMEAN aggregate.
    ASSERT_EQ(diff.size(), 3u) << diff.dump(1);
    for (size_t i = 0; i < 2; ++i) {
        SCOPED_TRACE(a[i].at(col::kTechnique));
        // compare.py names the benchmark as we did and computes (new - old) / old of real_time: here
        // from the CSVs' medians, which the export carried (4 decimals in the CSV, so 1e-9 relative).
        EXPECT_EQ(diff[i]["name"].get<std::string>().rfind(a[i].at(col::kTechnique), 0), 0u)
            << diff[i]["name"];
        const double oldMs = std::stod(a[i].at(col::kWallMsMedian)),
                     newMs = std::stod(b[i].at(col::kWallMsMedian));
        ASSERT_FALSE(diff[i]["measurements"].empty());
        const json& m = diff[i]["measurements"][0];
        EXPECT_NEAR(m["real_time"].get<double>(), oldMs, 1e-9 * oldMs);
        EXPECT_NEAR(m["real_time_other"].get<double>(), newMs, 1e-9 * newMs);
        EXPECT_NEAR(m["time"].get<double>(), (newMs - oldMs) / oldMs, 1e-9);
        EXPECT_EQ(diff[i]["time_unit"], "ms");
    }
    // The aggregate: the geometric mean of each side's times, which compare.py reports in seconds.
    const json& geomean = diff[2]["measurements"][0];
    EXPECT_EQ(diff[2]["name"], "OVERALL_GEOMEAN");
    const double oldMean =
        std::sqrt(std::stod(a[0].at(col::kWallMsMedian)) * std::stod(a[1].at(col::kWallMsMedian)));
    EXPECT_NEAR(geomean["real_time"].get<double>(), oldMean / 1000.0, 1e-9 * oldMean);
}

TEST_F(DashboardCliTest, GithubActionBenchmarkFileCarriesMediansAndExactWork) {
    measure(path("a.csv"));
    const auto e = test::runCommand(std::string(SB_BENCH_BINARY) + " export " + path("a.csv") +
                                    " --format gh-benchmark -o " + path("gh.json"));
    ASSERT_EQ(e.exitCode, 0) << e.output;
    const json items = json::parse(test::readFile(path("gh.json")));
    const auto rows = test::csvRowMaps(path("a.csv"));
    ASSERT_EQ(rows.size(), 2u);
    for (const auto& row : rows) {
        SCOPED_TRACE(row.at(col::kTechnique));
        bool time = false, fragments = false;
        for (const json& item : items) {
            const std::string name = item["name"];
            // The name starts with the technique, then its properties (":...") or the scene ("/...").
            const std::string& technique = row.at(col::kTechnique);
            if (name.rfind(technique, 0) != 0 || name.size() == technique.size() ||
                (name[technique.size()] != '/' && name[technique.size()] != ':'))
                continue;
            if (item["unit"] == "ms") {
                time = true;
                EXPECT_DOUBLE_EQ(item["value"].get<double>(), std::stod(row.at(col::kWallMsMedian)));
            }
            if (name.size() > 15 && name.substr(name.size() - 15) == " load_fragments") {
                fragments = true;
                EXPECT_DOUBLE_EQ(item["value"].get<double>(), std::stod(row.at(col::kLoadFragments)));
            }
        }
        EXPECT_TRUE(time && fragments) << items.dump(1);
    }
    // A CSV that is not rows of bench is refused as the user's mistake.
    test::writeFile(path("other.csv"), "a,b\n1,2\n");
    EXPECT_EQ(
        test::runCommand(std::string(SB_BENCH_BINARY) + " export " + path("other.csv") + " --format gbench")
            .exitCode,
        2);
}
