// A real run's CSV header against the column table (bench/lib/output/ResultColumns.h): the smallest run
// writes exactly the table's "every run" columns, in the table's order, with each family spelt out for
// the technique's passes and counters. docs/CSV.md is held to the same table by CsvDocTest.
#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;

namespace {

/// The table's columns written by `writers`, families spelt out: `gpu_<pass>_ms_median` once per pass,
/// `counter_<name>` once per counter, and the `work_<pass>_*` block pass by pass (ResultRow writes all
/// of one pass's work before the next pass's).
std::vector<std::string> expected(unsigned writers, const std::vector<std::string>& passes,
                                  const std::vector<std::string>& counters) {
    const std::vector<ColumnInfo> table = ResultColumns::writtenBy(writers);
    std::vector<std::string> out;
    for (size_t i = 0; i < table.size(); ++i) {
        const ColumnInfo& c = table[i];
        if (!c.isFamily()) {
            out.emplace_back(c.name);
        } else if (c.name == col::kCounter) {
            for (const std::string& n : counters) out.push_back(col::member(c.name, n));
        } else if (c.name.substr(0, 5) == "work_") {
            size_t end = i;
            while (end < table.size() && table[end].name.substr(0, 5) == "work_") ++end;
            for (const std::string& p : passes)
                for (size_t k = i; k < end; ++k) out.push_back(col::member(table[k].name, p));
            i = end - 1;
        } else {
            for (const std::string& p : passes) out.push_back(col::member(c.name, p));
        }
    }
    return out;
}

} // namespace

TEST(CsvColumnsCli, SmallestRunWritesTheTablesColumnsInOrder) {
    const std::string dir = test::freshTestDir("csv-columns");
    const std::string csv = dir + "/r.csv";
    auto r = test::runCommand(
        std::string(SB_BENCH_BINARY) +
        " -t none --frames 3 --warmup 1 --size 64x64 --instances 4 --no-timer-check --csv " + csv);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const CsvTable t = CsvWriter::read(csv);
    ASSERT_EQ(t.rows.size(), 1u);
    // `none` (bench --list): one pass, lighting; counters draw_calls and triangles.
    const std::vector<std::string> want = expected(kEveryRun, {"lighting"}, {"draw_calls", "triangles"});
    EXPECT_EQ(t.header, want);
    // 86 columns: 75 fixed, one CPU pass, one GPU pass, two counters, seven work counters of one pass
    // (counted by hand from docs/CSV.md), so a family dropped from both the table and the file is caught
    // as well.
    EXPECT_EQ(t.header.size(), 86u);
    EXPECT_EQ(t.cell(t.rows[0], col::kStatus), col::kStatusOk);
    EXPECT_EQ(t.cell(t.rows[0], col::kFrames), "3");
    EXPECT_EQ(t.cell(t.rows[0], col::kWidth), "64");
}
