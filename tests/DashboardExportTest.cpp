// The dashboard exports (bench/lib/output/DashboardExport.h) on a hand-written table: every expected name,
// number and unit is written out here, so the test does not read the values back through the code it
// checks. Google Benchmark's own compare.py reading the export is ExportCliTest's business.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/DashboardExport.h"
#include "bench/lib/output/RowExport.h"
#include "core/Error.h"

using namespace sb;
using nlohmann::json;

namespace {

// Two measured rows and a failed one, columns as bench writes them (a subset, in bench's order).
CsvTable sampleTable() {
    return CsvTable{{"timestamp",     "git_commit",    "status",
                     "api",           "api_version",   "renderer",
                     "cpu_model",     "hw_threads",    "scene",
                     "technique",     "properties",    "instances",
                     "submit",        "camera",        "width",
                     "height",        "frames",        "wall_ms_median",
                     "wall_ms_p5",    "wall_ms_p95",   "cpu_submit_ms_median",
                     "load_gl_calls", "load_vertices", "load_fragments"},
                    {{"2026-12-04T17:00:00Z",
                      "abc123",
                      "ok",
                      "gl",
                      "4.5 Mesa",
                      "llvmpipe",
                      "EPYC",
                      "2",
                      "aircraft",
                      "none",
                      "",
                      "40",
                      "retained",
                      "far",
                      "160",
                      "160",
                      "30",
                      "12.5000",
                      "11.0000",
                      "14.2500",
                      "3.7500",
                      "126",
                      "105472",
                      "74068"},
                     {"2026-12-04T17:00:01Z",
                      "abc123",
                      "ok",
                      "gl",
                      "4.5 Mesa",
                      "llvmpipe",
                      "EPYC",
                      "2",
                      "aircraft",
                      "shadowmap",
                      "resolution=512",
                      "40",
                      "retained",
                      "far",
                      "160",
                      "160",
                      "30",
                      "20.0000",
                      "19.0000",
                      "25.0000",
                      "5.0000",
                      "252",
                      "210944",
                      ""},
                     {"2026-12-04T17:00:02Z",
                      "abc123",
                      "error",
                      "gl",
                      "4.5 Mesa",
                      "llvmpipe",
                      "EPYC",
                      "2",
                      "aircraft",
                      "volume",
                      "",
                      "40",
                      "retained",
                      "far",
                      "160",
                      "160",
                      "",
                      "",
                      "",
                      "",
                      "",
                      "",
                      "",
                      ""}}};
}

} // namespace

TEST(DashboardExportTest, NamesARowByWhatMakesItDistinct) {
    const CsvTable t = sampleTable();
    EXPECT_EQ(DashboardExport::benchmarkName(t, t.rows[0]), "none/aircraft/n40/retained/far/160x160/gl");
    EXPECT_EQ(DashboardExport::benchmarkName(t, t.rows[1]),
              "shadowmap:resolution=512/aircraft/n40/retained/far/160x160/gl");
    // The perf gate's rows are named by their configuration.
    const CsvTable gate{{"ci_config", "technique", "wall_ms_median"}, {{"volume_day", "volume", "1"}}};
    EXPECT_EQ(DashboardExport::benchmarkName(gate, gate.rows[0]), "volume_day");
}

TEST(DashboardExportTest, GoogleBenchmarkJsonHasOneIterationRunPerMeasuredRow) {
    const json doc = json::parse(DashboardExport::googleBenchmark(sampleTable()));
    ASSERT_TRUE(doc.contains("context"));
    EXPECT_EQ(doc["context"]["date"], "2026-12-04T17:00:00Z");
    EXPECT_EQ(doc["context"]["num_cpus"], 2);
    EXPECT_EQ(doc["context"]["git_commit"], "abc123");
    EXPECT_EQ(doc["context"]["rows_not_ok"], 1); // the volume row failed: nothing to chart
    const json& b = doc["benchmarks"];
    ASSERT_EQ(b.size(), 2u);
    EXPECT_EQ(b[0]["name"], "none/aircraft/n40/retained/far/160x160/gl");
    EXPECT_EQ(b[0]["run_type"], "iteration");
    EXPECT_EQ(b[0]["iterations"], 30);
    EXPECT_EQ(b[0]["time_unit"], "ms");
    EXPECT_DOUBLE_EQ(b[0]["real_time"].get<double>(), 12.5);
    EXPECT_DOUBLE_EQ(b[0]["cpu_time"].get<double>(), 3.75);
    EXPECT_DOUBLE_EQ(b[0]["load_gl_calls"].get<double>(), 126.0);
    EXPECT_DOUBLE_EQ(b[0]["load_fragments"].get<double>(), 74068.0);
    EXPECT_EQ(b[1]["family_index"], 1);
    EXPECT_DOUBLE_EQ(b[1]["real_time"].get<double>(), 20.0);
    EXPECT_FALSE(b[1].contains("load_fragments")); // empty cell: no counter, never a made-up 0
}

TEST(DashboardExportTest, GithubActionBenchmarkListsTimeAndExactWorkSeries) {
    const json items = json::parse(DashboardExport::githubActionBenchmark(sampleTable()));
    ASSERT_TRUE(items.is_array());
    // none: time + 3 counters; shadowmap: time + 2 counters (load_fragments empty).
    ASSERT_EQ(items.size(), 7u);
    EXPECT_EQ(items[0]["name"], "none/aircraft/n40/retained/far/160x160/gl");
    EXPECT_EQ(items[0]["unit"], "ms");
    EXPECT_DOUBLE_EQ(items[0]["value"].get<double>(), 12.5);
    EXPECT_EQ(items[0]["range"], "p5-p95 11.0000..14.2500");
    EXPECT_EQ(items[1]["name"], "none/aircraft/n40/retained/far/160x160/gl load_gl_calls");
    EXPECT_EQ(items[1]["unit"], "gl_calls/frame");
    EXPECT_DOUBLE_EQ(items[1]["value"].get<double>(), 126.0);
    EXPECT_EQ(items[3]["unit"], "fragments/frame");
    EXPECT_EQ(items[4]["name"], "shadowmap:resolution=512/aircraft/n40/retained/far/160x160/gl");
    EXPECT_NE(items[4]["extra"].get<std::string>().find("resolution=512"), std::string::npos);
    for (const json& item : items) { // github-action-benchmark requires these three on every entry
        EXPECT_TRUE(item["name"].is_string());
        EXPECT_TRUE(item["unit"].is_string());
        EXPECT_TRUE(item["value"].is_number());
    }
}

TEST(DashboardExportTest, ReachableThroughTheRowFormatsAndRefusesTablesWithoutTimes) {
    EXPECT_EQ(parseRowFormat("gbench"), RowFormat::GoogleBenchmark);
    EXPECT_EQ(parseRowFormat("gh-benchmark"), RowFormat::GithubBenchmark);
    EXPECT_EQ(RowExport::format(sampleTable(), RowFormat::GoogleBenchmark),
              DashboardExport::googleBenchmark(sampleTable()));
    const CsvTable notRows{{"a", "b"}, {{"1", "2"}}};
    try {
        DashboardExport::googleBenchmark(notRows);
        ADD_FAILURE() << "a table without wall_ms_median was exported";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        EXPECT_NE(std::string(e.what()).find("wall_ms_median"), std::string::npos);
    }
}

TEST(DashboardExportTest, SubnormalTimeIsASmallNumberAndBadCellsNameRowAndColumn) {
    // A subnormal wall time is a valid number (it failed with the bare message "stod"); the JSON holds
    // the same double, compared exactly: both sides parse the same decimal text.
    const CsvTable tiny{{"status", "frames", "wall_ms_median"}, {{"ok", "3", "4.9e-320"}}};
    const json doc = json::parse(DashboardExport::googleBenchmark(tiny));
    EXPECT_EQ(doc["benchmarks"][0]["real_time"].get<double>(), 4.9e-320);
    EXPECT_EQ(doc["benchmarks"][0]["iterations"].get<long long>(), 3);
    // Counts that would be written wrong (-3 kept, 1e30 wrapped to -9223372036854775808) and text
    // that is not UTF-8 are refused, naming the row's line and the column.
    const std::vector<std::pair<CsvTable, std::string>> bad = {
        {{{"status", "frames", "wall_ms_median"}, {{"ok", "-3", "1.5"}}}, "(rows):2: column 'frames'"},
        {{{"status", "frames", "wall_ms_median"}, {{"ok", "1", "1.5"}, {"ok", "1e30", "1.5"}}},
         "(rows):3: column 'frames'"},
        {{{"status", "frames", "wall_ms_median", "load_vertices"}, {{"ok", "1", "1.5", "-2"}}},
         "(rows):2: column 'load_vertices'"},
        {{{"status", "scene", "frames", "wall_ms_median"}, {{"ok", "caf\xE9", "1", "1.5"}}},
         "(rows):2: column 'scene': invalid UTF-8"},
    };
    for (const auto& [table, where] : bad) {
        try {
            DashboardExport::googleBenchmark(table);
            ADD_FAILURE() << where << ": accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ExitCode::BadInput);
            EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
        }
    }
}
