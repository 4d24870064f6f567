// The console output of the bench binary end to end: the side-by-side ratios of `--repeat` against
// the CSV rows the same run wrote, and the tables' layout (no two cells ever run together). The
// independent answers are the CSV's own wall medians (the ratio recomputed here, round by round) and
// the technique registry's property declarations.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;
// Tiny and quick: the layout and the arithmetic are checked, not the performance.
const std::string kQuick = " --instances 20 --size 64x64 --frames 3 --warmup 1 --no-timer-check -q";

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

/// A console table found by its heading line: the cell of column `heading` in each of the `count`
/// lines below it, read from where the heading starts to the next space (cells are left-aligned under
/// their heading).
std::vector<std::string> columnBelow(const std::vector<std::string>& text, size_t headingLine,
                                     const std::string& heading, size_t count) {
    const size_t at = text[headingLine].find(heading);
    std::vector<std::string> cells;
    if (at == std::string::npos) return cells;
    for (size_t i = headingLine + 1; i <= headingLine + count && i < text.size(); ++i) {
        const std::string& line = text[i];
        cells.push_back(at < line.size() ? line.substr(at, line.find(' ', at) - at) : "");
    }
    return cells;
}

/// The index of the first line from `from` on that starts with "technique" and contains `heading`.
size_t findHeading(const std::vector<std::string>& text, const std::string& heading, size_t from = 0) {
    for (size_t i = from; i < text.size(); ++i)
        if (text[i].rfind("technique", 0) == 0 && text[i].find(heading) != std::string::npos) return i;
    return text.size();
}

/// "1.45x" -> 1.45 (NaN when it is not a number followed by x).
double ratioCell(const std::string& cell) {
    if (cell.empty() || cell.back() != 'x') return std::nan("");
    try {
        return std::stod(cell.substr(0, cell.size() - 1));
    } catch (const std::logic_error&) {
        return std::nan("");
    }
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct RepeatCase {
    const char* name;
    const char* techniques; ///< the first is the baseline of every ratio
    const char* baseline;   ///< its technique name, as the ratio column's heading says it
};

const RepeatCase kRepeatCases[] = {
    {"NoneFirst", "-t none -t shadowmap", "none"},
    // Not `none` first: the CSV's baseline is the first technique, so the console's must be too.
    {"ShadowmapFirst", "-t shadowmap -t none", "shadowmap"},
};

void PrintTo(const RepeatCase& c, std::ostream* os) {
    *os << c.name;
}

class RepeatRatios : public ::testing::TestWithParam<RepeatCase> {};

// Every row's ratio in the console table is its wall median over that of the first technique of the
// same round, recomputed here from the CSV's wall_ms_median; the paired summary is the median, min
// and max of those per-round ratios.
TEST_P(RepeatRatios, ConsoleAgreesWithTheCsvRoundByRound) {
    const RepeatCase& c = GetParam();
    constexpr size_t kRounds = 3, kTechniques = 2;
    const std::string dir = test::freshTestDir("console");
    const std::string csv = dir + "/r.csv";
    const auto r = runCommand(kBench + " " + c.techniques + " --repeat " + std::to_string(kRounds) + kQuick +
                              " --csv " + csv);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const CsvTable t = CsvWriter::read(csv);
    ASSERT_EQ(t.rows.size(), kRounds * kTechniques);
    auto col = [&](const std::string& name) {
        const auto it = std::find(t.header.begin(), t.header.end(), name);
        EXPECT_NE(it, t.header.end()) << name;
        return size_t(it - t.header.begin());
    };
    const size_t wall = col(col::kWallMsMedian), round = col(col::kRepeat);
    // The independent answer: per row, its wall median over the first row's of its round.
    std::vector<double> expected;
    std::map<size_t, std::vector<double>> perTechnique; // position in the round -> ratios over rounds
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const size_t first = i - i % kTechniques;
        ASSERT_EQ(t.rows[i][round], t.rows[first][round]) << "rows of one round are next to each other";
        expected.push_back(std::stod(t.rows[i][wall]) / std::stod(t.rows[first][wall]));
        perTechnique[i % kTechniques].push_back(expected.back());
    }

    const std::vector<std::string> text = lines(r.output);
    const std::string heading = std::string("vs ") + c.baseline;
    const size_t table = findHeading(text, heading);
    ASSERT_LT(table, text.size()) << "no table with a '" << heading << "' column in:\n" << r.output;
    const std::vector<std::string> cells = columnBelow(text, table, heading, t.rows.size());
    ASSERT_EQ(cells.size(), t.rows.size()) << r.output;
    for (size_t i = 0; i < cells.size(); ++i)
        // The console prints 2 decimals (half a unit of rounding, 0.005); the CSV's wall medians have 4
        // decimals of milliseconds, so the ratio recomputed from them is exact to ~1e-5 here.
        EXPECT_NEAR(ratioCell(cells[i]), expected[i], 0.0051)
            << "row " << i << " (" << text[table + 1 + i] << ")\n"
            << r.output;

    const size_t paired = findHeading(text, heading, table + 1);
    ASSERT_LT(paired, text.size()) << "no paired summary in:\n" << r.output;
    const std::vector<std::string> medians = columnBelow(text, paired, heading, kTechniques);
    ASSERT_EQ(medians.size(), kTechniques) << r.output;
    for (size_t k = 0; k < kTechniques; ++k) {
        const std::vector<double>& q = perTechnique[k];
        // Three decimals printed: half a unit, 0.0005, plus the ~1e-5 of the recomputation.
        EXPECT_NEAR(ratioCell(medians[k]), median(q), 0.00051) << r.output;
        const std::string range = text[paired + 1 + k].substr(text[paired].find("[min, max]"));
        double lo = 0, hi = 0;
        ASSERT_EQ(std::sscanf(range.c_str(), "[%lf, %lf]", &lo, &hi), 2) << range;
        EXPECT_NEAR(lo, *std::min_element(q.begin(), q.end()), 0.00051) << r.output;
        EXPECT_NEAR(hi, *std::max_element(q.begin(), q.end()), 0.00051) << r.output;
    }
}

INSTANTIATE_TEST_SUITE_P(Console, RepeatRatios, ::testing::ValuesIn(kRepeatCases),
                         [](const auto& p) { return std::string(p.param.name); });

// `bench --list`: every declared property is one line whose name, type, default and range are cells
// separated by at least one space, however long the name (the registry's declarations are the answer).
TEST(Console, ListSeparatesEveryPropertyCell) {
    const auto r = runCommand(kBench + " --list");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::vector<std::string> text = lines(r.output);
    size_t checked = 0;
    for (const auto& entry : TechniqueRegistry::entries()) {
        const auto technique = TechniqueRegistry::describe(TechniqueSpec{entry.name, {}});
        // The technique's block: from its "<name>  <description>" line to the blank line after it
        // (several techniques declare a property of the same name).
        const std::string title = technique->info().name + "  ";
        const auto block = std::find_if(text.begin(), text.end(),
                                        [&](const std::string& l) { return l.rfind(title, 0) == 0; });
        ASSERT_NE(block, text.end()) << "no block for " << technique->info().name << " in:\n" << r.output;
        const auto blockEnd = std::find(block, text.end(), std::string());
        for (const PropertyDesc& p : technique->info().properties) {
            const std::string start = "  " + p.name + " ";
            const auto line =
                std::find_if(block, blockEnd, [&](const std::string& l) { return l.rfind(start, 0) == 0; });
            ASSERT_NE(line, blockEnd) << "no line '" << start << "...' for " << technique->info().name
                                      << " (a cell run into the next?) in:\n"
                                      << r.output;
            std::istringstream cells(*line);
            std::string name, type, defaultWord, value;
            cells >> name >> type >> defaultWord >> value;
            EXPECT_EQ(name, p.name) << *line;
            EXPECT_EQ(type, propertyTypeName(p.type)) << *line;
            EXPECT_EQ(defaultWord, "default") << *line;
            EXPECT_EQ(value, p.defaultValue) << *line;
            const std::string range = " " + p.rangeText();
            const size_t at = line->find(range);
            ASSERT_NE(at, std::string::npos) << *line;
            const size_t after = at + range.size();
            EXPECT_TRUE(after == line->size() || (*line)[after] == ' ')
                << "range runs into the description: " << *line;
            ++checked;
        }
    }
    EXPECT_GT(checked, 40u) << "the registry declares dozens of properties";
}

} // namespace
