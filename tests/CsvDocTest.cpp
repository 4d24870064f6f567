// docs/CSV.md against the column table of bench/lib/output/ResultColumns.h: every column on both sides,
// the same unit and the same "written by". The document is hand-written for readers; this test is what
// keeps it from drifting when a column is added, renamed or changes unit. Also the table's own lookups
// (families, members), against hand-spelt names.
#include <filesystem>
#include <map>
#include <regex>
#include <set>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;

namespace {

struct DocRow {
    std::string unit;    ///< "" where the document writes "-"
    std::string writers; ///< the "written by" cell
};

/// The rows of the document's "## The columns" table, by column name; a name listed twice is reported.
std::map<std::string, DocRow> docColumns(const std::string& doc, std::vector<std::string>& duplicates) {
    const size_t start = doc.find("## The columns");
    EXPECT_NE(start, std::string::npos) << "docs/CSV.md has no '## The columns' section";
    if (start == std::string::npos) return {};
    const size_t end = doc.find("\n## ", start + 5);
    const std::string section = doc.substr(start, end == std::string::npos ? std::string::npos : end - start);
    std::map<std::string, DocRow> out;
    const std::regex row(R"(\n\| `([a-z0-9_<>]+)` \| ([^|]*) \| ([^|]*) \|)");
    for (auto it = std::sregex_iterator(section.begin(), section.end(), row); it != std::sregex_iterator();
         ++it) {
        const std::string unit = (*it)[2];
        if (!out.emplace((*it)[1], DocRow{unit == "-" ? "" : unit, (*it)[3]}).second)
            duplicates.push_back((*it)[1]);
    }
    return out;
}

/// Every way the document and the table disagree, one line each; empty when they agree.
std::vector<std::string> disagreements(const std::string& doc) {
    std::vector<std::string> out;
    std::vector<std::string> duplicates;
    const auto documented = docColumns(doc, duplicates);
    for (const std::string& d : duplicates) out.push_back("listed twice in docs/CSV.md: " + d);
    std::set<std::string> inTable;
    for (const ColumnInfo& c : ResultColumns::all()) {
        const std::string name(c.name);
        if (!inTable.insert(name).second) out.push_back("listed twice in the table: " + name);
        const auto it = documented.find(name);
        if (it == documented.end()) {
            out.push_back("missing from docs/CSV.md: " + name);
            continue;
        }
        if (it->second.unit != c.unit)
            out.push_back(name + ": unit '" + it->second.unit + "' in docs/CSV.md, '" + std::string(c.unit) +
                          "' in the table");
        if (it->second.writers != ResultColumns::writersText(c.writers))
            out.push_back(name + ": written by '" + it->second.writers + "' in docs/CSV.md, '" +
                          ResultColumns::writersText(c.writers) + "' in the table");
    }
    for (const auto& [name, row] : documented)
        if (!inTable.count(name)) out.push_back("missing from the table: " + name);
    return out;
}

std::string csvDoc() {
    return test::readFile(std::string(SB_SOURCE_DIR) + "/docs/CSV.md");
}

/// `doc` with the first occurrence of `from` replaced by `to` (which must be there).
std::string edited(std::string doc, const std::string& from, const std::string& to) {
    const size_t at = doc.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? doc : doc.replace(at, from.size(), to);
}

} // namespace

TEST(CsvDoc, DocumentAndTableAgree) {
    const std::vector<std::string> found = disagreements(csvDoc());
    for (const std::string& line : found) ADD_FAILURE() << line;
    // 124 columns when this test was written (README's list at the time, every one of them).
    EXPECT_GE(ResultColumns::all().size(), 124u);
}

// The comparison itself catches each kind of drift: a column gone from the document, a unit changed, a
// writer changed, a column the table does not know.
TEST(CsvDoc, EachKindOfDriftIsReported) {
    const std::string doc = csvDoc();
    const std::string wall = "| `wall_ms_median` | ms | every run |";
    auto reports = [](const std::vector<std::string>& lines, const std::string& text) {
        return std::any_of(lines.begin(), lines.end(),
                           [&](const std::string& l) { return l.find(text) != std::string::npos; });
    };
    EXPECT_TRUE(reports(disagreements(edited(doc, wall, "| `wall_ms_medain` | ms | every run |")),
                        "missing from docs/CSV.md: wall_ms_median"));
    EXPECT_TRUE(reports(disagreements(edited(doc, wall, "| `wall_ms_medain` | ms | every run |")),
                        "missing from the table: wall_ms_medain"));
    EXPECT_TRUE(reports(disagreements(edited(doc, wall, "| `wall_ms_median` | s | every run |")),
                        "wall_ms_median: unit 's'"));
    EXPECT_TRUE(reports(disagreements(edited(doc, wall, "| `wall_ms_median` | ms | sweeps |")),
                        "wall_ms_median: written by 'sweeps'"));
    EXPECT_TRUE(
        reports(disagreements(edited(doc, "| `acc_rmse` | - |", "| `acc_rmse` | % |")), "acc_rmse: unit"));
}

TEST(CsvDoc, FamiliesAndMembers) {
    EXPECT_EQ(col::member(col::kGpuPassMsMedian, "depth"), "gpu_depth_ms_median");
    EXPECT_EQ(col::member(col::kCounter, "shadow_map_texels"), "counter_shadow_map_texels");
    EXPECT_EQ(col::member(col::kWorkClippedPrimitives, "lighting"), "work_lighting_clipped_primitives");

    const ColumnInfo* wall = ResultColumns::find("wall_ms_median");
    ASSERT_NE(wall, nullptr);
    EXPECT_EQ(wall->unit, "ms");
    EXPECT_EQ(wall->type, ColumnType::Number);
    // A member is found as its family; the longest family wins ("work_depth_clipped_primitives" also ends
    // in "_primitives").
    const ColumnInfo* clipped = ResultColumns::find("work_depth_clipped_primitives");
    ASSERT_NE(clipped, nullptr);
    EXPECT_EQ(clipped->name, "work_<pass>_clipped_primitives");
    const ColumnInfo* pass = ResultColumns::find("gpu_depth_ms_median");
    ASSERT_NE(pass, nullptr);
    EXPECT_EQ(pass->name, "gpu_<pass>_ms_median");
    // gpu_ms_median is a column of its own, not the family with an empty pass.
    EXPECT_EQ(ResultColumns::find("gpu_ms_median")->name, "gpu_ms_median");
    EXPECT_EQ(ResultColumns::find("gpu__ms_median"), nullptr);
    EXPECT_EQ(ResultColumns::find("wall_ms_medain"), nullptr);

    EXPECT_EQ(ResultColumns::writersText(kEveryRun), "every run");
    EXPECT_EQ(ResultColumns::writersText(kSweep | kFailed), "sweeps, failed rows");
    // Every accuracy column and nothing else is written by bench accuracy alone.
    for (const ColumnInfo& c : ResultColumns::writtenBy(kAccuracy))
        EXPECT_TRUE(c.name.substr(0, 4) == "acc_" || c.name.substr(0, 4) == "ref_") << c.name;
}

// The committed result files under results/ (runs, sweeps, figures, the gate's baselines) were written by
// older builds: every column of every one of them is in the table, so the table (and docs/CSV.md) covers
// what a reader of the repository meets. Files without wall_ms_median are other tables (a bottleneck
// study's classes, a calibration) and are left out.
TEST(CsvDoc, EveryCommittedResultColumnIsInTheTable) {
    size_t files = 0;
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(std::string(SB_SOURCE_DIR) + "/results")) {
        if (!entry.is_regular_file() || entry.path().extension() != ".csv") continue;
        const CsvTable t = CsvWriter::read(entry.path().string());
        if (!t.hasColumn(col::kWallMsMedian)) continue;
        ++files;
        for (const std::string& column : t.header)
            EXPECT_NE(ResultColumns::find(column), nullptr) << entry.path() << ": " << column;
    }
    EXPECT_GT(files, 10u) << "results/ holds fewer result CSVs than expected";
}
