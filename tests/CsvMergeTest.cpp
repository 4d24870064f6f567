// `bench merge` (bench/lib/output/CsvMerge.h): shard CSVs of one sweep joined into one file, sorted by
// config_index with the union of the headers, and every way inputs can fail to fit together refused
// with a message naming the file, rows of different measurements (commit, CPU model, driver, renderer)
// among them; what is missing or failed listed under the shard that runs it, checked against the split
// worked out by hand and against SweepPlan's own. Expected files are written out by hand and compared
// exactly; every refusal and incomplete merge also checks that nothing was written (no output, no
// temporary file).
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvMerge.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/MeasurementIdentity.h"
#include "bench/lib/output/ShardGaps.h"
#include "bench/lib/sweep/SweepPlan.h"
#include "core/Error.h"

using namespace sb;
using test::readFile;
using test::writeFile;
namespace fs = std::filesystem;

namespace {

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
    for (size_t pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size()))
        s.replace(pos, from.size(), to);
    return s;
}

/// The sweep columns in the order the bench writes them, plus status.
constexpr const char* kHeader = "sweep_id,sweep_configs,config_index,shard,status\n";

/// A fresh directory per test; helpers take names relative to it.
class MergeFixture {
protected:
    void makeDir() { mDir = test::freshTestDir("merge"); }
    void removeDir() {
        std::error_code ec;
        fs::remove_all(mDir, ec);
    }
    std::string path(const std::string& name) const { return mDir + "/" + name; }
    std::vector<std::string> paths(const std::vector<std::string>& names) const {
        std::vector<std::string> out;
        for (const std::string& name : names) out.push_back(path(name));
        return out;
    }
    /// Names in the directory, sorted: after a refusal they must be exactly the inputs.
    std::vector<std::string> listDir() const {
        std::vector<std::string> out;
        for (const auto& e : fs::directory_iterator(mDir)) out.push_back(e.path().filename().string());
        std::sort(out.begin(), out.end());
        return out;
    }
    /// The message of the sb::Error merge throws; checks its exit code.
    std::string errorOf(const std::vector<std::string>& inputs, const std::string& output,
                        MergeOptions options, ExitCode code) {
        try {
            CsvMerge::merge(inputs, output, options);
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), code) << e.what();
            return e.what();
        }
        ADD_FAILURE() << "merge did not throw";
        return "";
    }
    std::string mDir;
};

class CsvMergeTest : public MergeFixture, public ::testing::Test {
protected:
    void SetUp() override { makeDir(); }
    void TearDown() override { removeDir(); }
};

// ---------------------------------------------------------------------------------------------------
// Merging

TEST_F(CsvMergeTest, ShardsWithDifferentHeadersMergeSortedByConfigIndex) {
    // Round-robin split of 4 configurations. Shard 1 lists its rows out of order and has
    // wall_ms_median; shard 2 orders its columns differently and has gpu_ms_median instead. The
    // header is the union in first-seen order, absent cells are empty, rows sorted by config_index.
    writeFile(path("a.csv"), "sweep_id,sweep_configs,config_index,shard,status,technique,wall_ms_median\n"
                             "ab12,4,2,1/2,ok,pcf,2.0000\n"
                             "ab12,4,0,1/2,ok,none,1.0000\n");
    writeFile(path("b.csv"), "technique,sweep_id,shard,config_index,sweep_configs,status,gpu_ms_median\n"
                             "vsm,ab12,2/2,1,4,failed,0.5000\n"
                             "csm,ab12,2/2,3,4,ok,0.7000\n");
    MergeOptions options;
    options.allowIncomplete = true; // the failed vsm row is kept, as the sweep wrote it
    MergeReport report = CsvMerge::merge(paths({"a.csv", "b.csv"}), path("all.csv"), options);
    EXPECT_EQ(readFile(path("all.csv")),
              "sweep_id,sweep_configs,config_index,shard,status,technique,wall_ms_median,gpu_ms_median\n"
              "ab12,4,0,1/2,ok,none,1.0000,\n"
              "ab12,4,1,2/2,failed,vsm,,0.5000\n"
              "ab12,4,2,1/2,ok,pcf,2.0000,\n"
              "ab12,4,3,2/2,ok,csm,,0.7000\n");
    EXPECT_EQ(report.files, 2u);
    EXPECT_EQ(report.rows, 4u);
    EXPECT_EQ(report.sweepId, "ab12");
    EXPECT_EQ(report.configs, 4u);
    EXPECT_TRUE(report.missing.empty());
    EXPECT_EQ(report.failedRows, 1u); // the vsm row
    EXPECT_EQ(report.failed, (IndexRanges{{1, 1}}));
    EXPECT_TRUE(report.written);
    EXPECT_EQ(listDir(), (std::vector<std::string>{"a.csv", "all.csv", "b.csv"}));
}

TEST_F(CsvMergeTest, QuotedCellsSurviveTheMerge) {
    // A multi-line error with quotes and commas is re-quoted exactly as CsvWriter writes it.
    writeFile(path("a.csv"), "sweep_id,sweep_configs,config_index,shard,status,error\n"
                             "s1,2,1,1/2,failed,\"GL_OUT_OF_MEMORY, \"\"fbo\"\"\nat pass 2\"\n");
    writeFile(path("b.csv"), std::string(kHeader) + "s1,2,0,2/2,ok\n");
    MergeOptions options;
    options.allowIncomplete = true;
    CsvMerge::merge(paths({"a.csv", "b.csv"}), path("all.csv"), options);
    EXPECT_EQ(readFile(path("all.csv")), "sweep_id,sweep_configs,config_index,shard,status,error\n"
                                         "s1,2,0,2/2,ok,\n"
                                         "s1,2,1,1/2,failed,\"GL_OUT_OF_MEMORY, \"\"fbo\"\"\nat pass 2\"\n");
}

TEST_F(CsvMergeTest, AllowIncompleteWritesWhatIsThereAndReportsTheGaps) {
    // Configurations 1, 3 and 4 of 5 were never measured: written anyway, and listed in the report.
    writeFile(path("a.csv"), std::string(kHeader) + "s1,5,2,1/3,ok\ns1,5,0,1/3,ok\n");
    MergeOptions options;
    options.allowIncomplete = true;
    MergeReport report = CsvMerge::merge({path("a.csv")}, path("out.csv"), options);
    EXPECT_EQ(readFile(path("out.csv")), std::string(kHeader) + "s1,5,0,1/3,ok\ns1,5,2,1/3,ok\n");
    EXPECT_EQ(report.missingCount, 3u);
    EXPECT_EQ(report.missing, (std::vector<std::pair<size_t, size_t>>{{1, 1}, {3, 4}}));
    EXPECT_EQ(report.rows, 2u);
    EXPECT_EQ(report.configs, 5u);
    EXPECT_EQ(report.failedRows, 0u);
}

TEST_F(CsvMergeTest, ForceReplacesAnExistingOutputAndOnlyThen) {
    // Without --force the existing file is refused and left alone; with it, replaced completely.
    writeFile(path("a.csv"), std::string(kHeader) + "s1,1,0,1/1,ok\n");
    writeFile(path("out.csv"), "old,content\n1,2\n");
    std::string e = errorOf({path("a.csv")}, path("out.csv"), {}, ExitCode::BadInput);
    EXPECT_EQ(e, "output '" + path("out.csv") + "' exists; pass --force to replace it");
    EXPECT_EQ(readFile(path("out.csv")), "old,content\n1,2\n");
    MergeOptions options;
    options.force = true;
    CsvMerge::merge({path("a.csv")}, path("out.csv"), options);
    EXPECT_EQ(readFile(path("out.csv")), std::string(kHeader) + "s1,1,0,1/1,ok\n");
    EXPECT_EQ(listDir(), (std::vector<std::string>{"a.csv", "out.csv"}));
}

TEST_F(CsvMergeTest, MixedTimerVerdictsMergeOnlyWhenAskedAndAreReported) {
    // Shard 1 calibrated "trusted" (GPU columns filled), shard 2 "untrusted"; the failed row of shard 2
    // has no verdict (never measured) and is not counted. Refused by default (the refusal table below),
    // written with allowMixedTimer, and the report counts rows per verdict in first-seen order.
    const std::string header =
        "sweep_id,sweep_configs,config_index,shard,status,timer_verdict,gpu_ms_median\n";
    writeFile(path("a.csv"), header + "s1,4,0,1/2,ok,trusted,1.5\ns1,4,2,1/2,ok,trusted,2.5\n");
    writeFile(path("b.csv"), header + "s1,4,1,2/2,ok,untrusted,\ns1,4,3,2/2,failed,,\n");
    EXPECT_NE(errorOf(paths({"a.csv", "b.csv"}), path("all.csv"), {}, ExitCode::BadInput)
                  .find("--allow-mixed-timer"),
              std::string::npos);
    MergeOptions options;
    options.allowMixedTimer = true;
    options.allowIncomplete = true; // the failed row
    const MergeReport report = CsvMerge::merge(paths({"a.csv", "b.csv"}), path("all.csv"), options);
    using Counts = std::vector<std::pair<std::string, size_t>>;
    EXPECT_EQ(report.timerVerdicts, (Counts{{"trusted", 2}, {"untrusted", 1}}));
    EXPECT_EQ(readFile(path("all.csv")), header + "s1,4,0,1/2,ok,trusted,1.5\ns1,4,1,2/2,ok,untrusted,\n"
                                                  "s1,4,2,1/2,ok,trusted,2.5\ns1,4,3,2/2,failed,,\n");
}

TEST_F(CsvMergeTest, OneTimerVerdictEverywhereMerges) {
    // Files without the column (older CSVs) and failed rows do not count as a different verdict.
    const std::string header = "sweep_id,sweep_configs,config_index,shard,status,timer_verdict\n";
    writeFile(path("a.csv"), header + "s1,3,0,1/3,ok,untrusted\ns1,3,1,1/3,failed,\n");
    writeFile(path("b.csv"), std::string(kHeader) + "s1,3,2,2/3,ok\n");
    const MergeReport report = CsvMerge::merge(paths({"a.csv", "b.csv"}), path("all.csv"), {});
    EXPECT_EQ(report.timerVerdicts, (std::vector<std::pair<std::string, size_t>>{{"untrusted", 1}}));
}

TEST_F(CsvMergeTest, MissingStatusColumnCountsEveryRowAsFailed) {
    // failedRows counts rows whose status is not "ok"; without the column no row is known to be ok, so
    // the merge is incomplete and writes nothing.
    writeFile(path("a.csv"), "sweep_id,sweep_configs,config_index,shard\ns1,2,0,1/1\ns1,2,1,1/1\n");
    const MergeReport report = CsvMerge::merge({path("a.csv")}, path("out.csv"), {});
    EXPECT_EQ(report.failedRows, 2u);
    EXPECT_FALSE(report.written);
    EXPECT_EQ(listDir(), (std::vector<std::string>{"a.csv"}));
}

// ---------------------------------------------------------------------------------------------------
// I/O failures: exit code 1, path and OS reason in the message, nothing left behind

// A missing input is wrong input (exit 2) like any other path that names nothing (CsvWriter.cpp).
TEST_F(CsvMergeTest, MissingInputIsBadInputNamingIt) {
    std::string e = errorOf({path("nope.csv")}, path("out.csv"), {}, ExitCode::BadInput);
    EXPECT_NE(e.find(path("nope.csv")), std::string::npos) << e;
    EXPECT_NE(e.find("No such file or directory"), std::string::npos) << e;
    EXPECT_TRUE(listDir().empty());
}

TEST_F(CsvMergeTest, TempFileThatCannotBeCreatedLeavesNoOutputAndNoTempFile) {
    // A 253-character name is valid but "<name>.tmp" exceeds NAME_MAX (255): the write fails after all
    // checks passed (works as root too).
    writeFile(path("a.csv"), std::string(kHeader) + "s1,1,0,1/1,ok\n");
    std::string out = path(std::string(249, 'o') + ".csv");
    std::string e = errorOf({path("a.csv")}, out, {}, ExitCode::Failure);
    EXPECT_NE(e.find(out), std::string::npos) << e;
    EXPECT_NE(e.find("File name too long"), std::string::npos) << e;
    EXPECT_EQ(listDir(), (std::vector<std::string>{"a.csv"}));
}

TEST_F(CsvMergeTest, ForceOverADirectoryIsRefusedAndLeavesIt) {
    // --force over a directory: refused before any temp file is written (a directory is not a result
    // file to replace), and the directory is left as it was.
    writeFile(path("a.csv"), std::string(kHeader) + "s1,1,0,1/1,ok\n");
    fs::create_directories(path("out.csv"));
    MergeOptions options;
    options.force = true;
    std::string e = errorOf({path("a.csv")}, path("out.csv"), options, ExitCode::BadInput);
    EXPECT_NE(e.find(path("out.csv")), std::string::npos) << e;
    EXPECT_NE(e.find("it is a directory"), std::string::npos) << e;
    EXPECT_EQ(listDir(), (std::vector<std::string>{"a.csv", "out.csv"}));
    EXPECT_TRUE(fs::is_empty(path("out.csv")));
}

TEST_F(CsvMergeTest, WriteTableRefusesRaggedRowsBeforeWriting) {
    // CsvWriter::writeTable, which merge writes with: a row of the wrong width is a caller bug.
    EXPECT_THROW(CsvWriter::writeTable(path("t.csv"), CsvTable{{"a", "b"}, {{"1"}}}), Error);
    EXPECT_TRUE(listDir().empty());
    CsvWriter::writeTable(path("t.csv"), CsvTable{{"a", "b"}, {{"1", "x,y"}}});
    EXPECT_EQ(readFile(path("t.csv")), "a,b\n1,\"x,y\"\n");
}

// ---------------------------------------------------------------------------------------------------
// Refused inputs: exit code 2, a message naming the file (and line), nothing written

struct BadMerge {
    std::string name;
    std::vector<std::pair<std::string, std::string>> files; ///< name, content
    std::vector<std::string> inputs;                        ///< names; may name absent files
    std::string output;
    std::vector<std::string> expected; ///< substrings of the message; "{dir}" is the test directory
};

/// gtest prints a failing case by this instead of its bytes.
void PrintTo(const BadMerge& c, std::ostream* os) {
    *os << c.name;
}

std::string rows(const std::string& body) {
    return std::string(kHeader) + body;
}

const std::vector<BadMerge> kBadMerges = {
    {"NoInputs", {}, {}, "out.csv", {"no input files"}},
    {"InputIsTheOutput",
     {{"a.csv", rows("s1,1,0,1/1,ok\n")}},
     {"a.csv"},
     "sub/../a.csv", // the same file, spelled differently
     {"input '{dir}/a.csv' is also the output file '{dir}/sub/../a.csv'"}},
    {"InputGivenTwice",
     {{"a.csv", rows("s1,1,0,1/1,ok\n")}},
     {"a.csv", "./a.csv"},
     "out.csv",
     {"'{dir}/./a.csv' is given twice", "'{dir}/a.csv'"}},
    {"OutputExists",
     {{"a.csv", rows("s1,1,0,1/1,ok\n")}, {"out.csv", "x\n1\n"}},
     {"a.csv"},
     "out.csv",
     {"'{dir}/out.csv' exists", "--force"}},
    {"NotASweepCsv",
     {{"a.csv", "sweep_id,sweep_configs,config_index,status\ns1,1,0,ok\n"}},
     {"a.csv"},
     "out.csv",
     {"'{dir}/a.csv' is not a sweep CSV: column 'shard' missing"}},
    {"EmptyFile",
     {{"a.csv", ""}},
     {"a.csv"},
     "out.csv",
     {"'{dir}/a.csv' is not a sweep CSV: column 'sweep_id'"}},
    {"RaggedCsv", {{"a.csv", rows("s1,1,0\n")}}, {"a.csv"}, "out.csv", {"{dir}/a.csv:2", "3 fields"}},
    {"EmptySweepId",
     {{"a.csv", rows(",2,0,1/1,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:2", "empty sweep_id"}},
    {"SweepConfigsZero",
     {{"a.csv", rows("s1,0,0,1/1,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:2", "sweep_configs '0' is not a positive integer"}},
    {"SweepConfigsNotANumber",
     {{"a.csv", rows("s1,many,0,1/1,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:2", "sweep_configs 'many'"}},
    {"ConfigIndexOutOfRange",
     {{"a.csv", rows("s1,2,0,1/1,ok\ns1,2,2,1/1,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:3: config_index '2' is not an integer in [0, 2)"}},
    {"ConfigIndexNegative",
     {{"a.csv", rows("s1,2,-1,1/1,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:2", "config_index '-1'"}},
    {"ConfigIndexNotAnInteger",
     {{"a.csv", rows("s1,2,1.0,1/1,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:2", "config_index '1.0'"}},
    {"ConfigIndexEmpty",
     {{"a.csv", rows("s1,2,,1/1,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:2", "config_index ''"}},
    {"ShardZero",
     {{"a.csv", rows("s1,2,0,0/2,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:2", "shard '0/2' is not \"i/N\" with 1 <= i <= N"}},
    {"ShardAboveCount",
     {{"a.csv", rows("s1,2,0,3/2,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:2", "shard '3/2'"}},
    {"ShardNotAFraction",
     {{"a.csv", rows("s1,2,0,1-2,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:2", "shard '1-2'"}},
    {"ShardEmpty", {{"a.csv", rows("s1,2,0,,ok\n")}}, {"a.csv"}, "out.csv", {"{dir}/a.csv:2", "shard ''"}},
    {"TwoSweepIds",
     {{"a.csv", rows("s1,2,0,1/2,ok\n")}, {"b.csv", rows("s2,2,1,2/2,ok\n")}},
     {"a.csv", "b.csv"},
     "out.csv",
     {"different sweeps", "sweep_id 's1' in '{dir}/a.csv:2' but 's2' in '{dir}/b.csv:2'"}},
    {"TwoSweepConfigs",
     {{"a.csv", rows("s1,2,0,1/2,ok\n")}, {"b.csv", rows("s1,3,1,2/2,ok\n")}},
     {"a.csv", "b.csv"},
     "out.csv",
     {"different sweeps", "sweep_configs '2' in '{dir}/a.csv:2' but '3' in '{dir}/b.csv:2'"}},
    {"MixedShardCounts",
     {{"a.csv", rows("s1,3,0,1/2,ok\n")}, {"b.csv", rows("s1,3,1,2/3,ok\n")}},
     {"a.csv", "b.csv"},
     "out.csv",
     {"shards of different splits", "'2' in '{dir}/a.csv:2' but '3' in '{dir}/b.csv:2'"}},
    {"SameConfigInTwoFiles",
     {{"a.csv", rows("s1,2,0,1/2,ok\ns1,2,1,1/2,ok\n")}, {"b.csv", rows("s1,2,1,2/2,ok\n")}},
     {"a.csv", "b.csv"},
     "out.csv",
     {"configuration 1 appears twice: in '{dir}/a.csv:3' and '{dir}/b.csv:2'"}},
    {"SameConfigTwiceInOneFileAfterMultiLineCell",
     // The quoted error spans lines 2-3, so the repeated row starts on line 4.
     {{"a.csv", "sweep_id,sweep_configs,config_index,shard,error\n"
                "s1,2,0,1/1,\"two\nlines\"\n"
                "s1,2,0,1/1,\n"}},
     {"a.csv"},
     "out.csv",
     {"configuration 0 appears twice: in '{dir}/a.csv:2' and '{dir}/a.csv:4'"}},
    {"MixedTimerVerdicts",
     // The first place of each verdict is named: line 3 of a.csv is where 'untrusted' first appears.
     {{"a.csv", "sweep_id,sweep_configs,config_index,shard,timer_verdict\ns1,3,0,1/2,trusted\n"
                "s1,3,2,1/2,untrusted\n"},
      {"b.csv", "sweep_id,sweep_configs,config_index,shard,timer_verdict\ns1,3,1,2/2,trusted\n"}},
     {"a.csv", "b.csv"},
     "out.csv",
     {"rows measured under different GPU-timer verdicts: 'trusted' in '{dir}/a.csv:2' but 'untrusted' in "
      "'{dir}/a.csv:3'",
      "--allow-mixed-timer"}},
    {"NoRows", {{"a.csv", kHeader}, {"b.csv", kHeader}}, {"a.csv", "b.csv"}, "out.csv", {"hold no rows"}},
    {"SweepConfigsBeyondAnySweep",
     {{"a.csv", rows("s1,1000000000001,0,1/1,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"{dir}/a.csv:2: sweep_configs '1000000000001' is more than 1000000000000 configurations"}},
};

class CsvMergeRefusalTest : public MergeFixture, public ::testing::TestWithParam<BadMerge> {
protected:
    void SetUp() override { makeDir(); }
    void TearDown() override { removeDir(); }
};

TEST_P(CsvMergeRefusalTest, NamesTheProblemAndWritesNothing) {
    // Each case: exit code 2, the hand-written message parts (file and line), and the directory
    // holds exactly the input files afterwards (no output, no temp file, existing output untouched).
    const BadMerge& c = GetParam();
    for (const auto& [name, content] : c.files) writeFile(path(name), content);
    std::vector<std::string> before = listDir();
    std::string e = errorOf(paths(c.inputs), path(c.output), {}, ExitCode::BadInput);
    for (const std::string& part : c.expected)
        EXPECT_NE(e.find(replaceAll(part, "{dir}", mDir)), std::string::npos) << "missing: " << part << "\n"
                                                                              << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line: " << e;
    EXPECT_EQ(listDir(), before);
    for (const auto& [name, content] : c.files) EXPECT_EQ(readFile(path(name)), content) << name;
}

INSTANTIATE_TEST_SUITE_P(Cases, CsvMergeRefusalTest, ::testing::ValuesIn(kBadMerges),
                         [](const ::testing::TestParamInfo<BadMerge>& p) { return p.param.name; });

// ---------------------------------------------------------------------------------------------------
// Incomplete merges: nothing written (bench merge exits 1), the facts in one line of the report

struct IncompleteMerge {
    std::string name;
    std::vector<std::pair<std::string, std::string>> files; ///< name, content; every file is an input
    std::string expected;                                   ///< MergeReport::incomplete, exactly
};

void PrintTo(const IncompleteMerge& c, std::ostream* os) {
    *os << c.name;
}

const std::vector<IncompleteMerge> kIncompleteMerges = {
    {"Missing",
     {{"a.csv", rows("s1,6,0,1/2,ok\ns1,6,2,1/2,ok\n")}, {"b.csv", rows("s1,6,3,2/2,ok\n")}},
     "3 of 6 configurations missing (indices 1, 4-5)"},
    {"MissingAsRanges",
     {{"a.csv", rows("s1,20,0,1/1,ok\n")}},
     "19 of 20 configurations missing (indices 1-19)"},
    {"AtMostTenRanges",
     {{"a.csv",
       rows("s1,30,0,1/1,ok\ns1,30,2,1/1,ok\ns1,30,4,1/1,ok\ns1,30,6,1/1,ok\ns1,30,8,1/1,ok\ns1,30,10,1/1,"
            "ok\ns1,30,12,1/1,ok\ns1,30,14,1/1,ok\ns1,30,16,1/1,ok\ns1,30,18,1/1,ok\ns1,30,20,1/1,ok\n")}},
     "19 of 30 configurations missing (indices 1, 3, 5, 7, 9, 11, 13, 15, 17, 19, ...)"},
    // A damaged cell claiming a billion configurations: the gaps as ranges, not a list of a billion
    // indices (which took past 4 GiB).
    {"OfABillionIsOneRange",
     {{"a.csv", rows("s1,1000000000,0,1/2,ok\n")}, {"b.csv", rows("s1,1000000000,1,2/2,ok\n")}},
     "999999998 of 1000000000 configurations missing (indices 2-999999999)"},
    // An empty status is not ok: the worker never said the row was measured.
    {"FailedOnly",
     {{"a.csv", rows("s1,3,0,1/1,ok\ns1,3,1,1/1,failed\ns1,3,2,1/1,\n")}},
     "2 of 3 configurations failed (indices 1-2)"},
    {"MissingAndFailed",
     {{"a.csv", rows("s1,4,0,1/1,failed\ns1,4,3,1/1,ok\n")}},
     "2 of 4 configurations missing (indices 1-2), 1 failed (indices 0)"},
};

class CsvMergeIncompleteTest : public MergeFixture, public ::testing::TestWithParam<IncompleteMerge> {
protected:
    void SetUp() override { makeDir(); }
    void TearDown() override { removeDir(); }
};

TEST_P(CsvMergeIncompleteTest, SaysWhatIsMissingOrFailedAndWritesNothing) {
    // Each case: no exception (the inputs fit together), the report's one line as written by hand, and
    // the directory holds exactly the inputs afterwards.
    const IncompleteMerge& c = GetParam();
    std::vector<std::string> inputs;
    for (const auto& [name, content] : c.files) {
        writeFile(path(name), content);
        inputs.push_back(path(name));
    }
    const std::vector<std::string> before = listDir();
    const MergeReport report = CsvMerge::merge(inputs, path("out.csv"), {});
    EXPECT_FALSE(report.written);
    EXPECT_EQ(report.incomplete, c.expected);
    EXPECT_EQ(listDir(), before);
}

INSTANTIATE_TEST_SUITE_P(Cases, CsvMergeIncompleteTest, ::testing::ValuesIn(kIncompleteMerges),
                         [](const ::testing::TestParamInfo<IncompleteMerge>& p) { return p.param.name; });

TEST_F(CsvMergeTest, UnsupportedRowsAreAnAnswerNotAGap) {
    // `unsupported` means the context lacks what the configuration needs: retrying cannot change it, and
    // the sweep exits 0 for it, so the merge is complete and counts the row apart.
    writeFile(path("a.csv"), rows("s1,2,0,1/1,unsupported\ns1,2,1,1/1,ok\n"));
    const MergeReport report = CsvMerge::merge({path("a.csv")}, path("out.csv"), {});
    EXPECT_TRUE(report.written);
    EXPECT_EQ(report.unsupportedRows, 1u);
    EXPECT_EQ(report.failedRows, 0u);
    EXPECT_EQ(report.incomplete, "");
    EXPECT_TRUE(report.gaps.empty());
}

// ---------------------------------------------------------------------------------------------------
// One measurement: commit, CPU model, driver and, per api, renderer and driver version

/// The identity columns of a row, with values as real rows carry them (one renderer has a comma, so
/// the CSV quotes it).
struct Identity {
    std::string api = "gl";
    std::string renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    std::string driver = "system";
    std::string driverVersion = "Mesa 25.0.7-2~bpo12+1";
    std::string cpu = "AMD EPYC 7B13";
    std::string commit = "fd7aef0";
    std::string host = "node1";
};

constexpr const char* kIdentityHeader =
    "sweep_id,sweep_configs,config_index,shard,status,api,renderer,driver,"
    "driver_version,cpu_model,git_commit,host\n";

std::string csvCell(const std::string& s) {
    return s.find(',') == std::string::npos ? s : "\"" + s + "\"";
}

/// Row `index` of a sweep of `configs` configurations split `shard` ("i/N"), status ok.
std::string identityRow(size_t configs, size_t index, const std::string& shard, const Identity& id) {
    return "s1," + std::to_string(configs) + "," + std::to_string(index) + "," + shard + ",ok," + id.api +
           "," + csvCell(id.renderer) + "," + id.driver + "," + id.driverVersion + "," + csvCell(id.cpu) +
           "," + id.commit + "," + id.host + "\n";
}

/// Two shards of a two-configuration sweep: a.csv as `Identity{}`, b.csv changed by `change`.
template <typename Change>
std::vector<std::pair<std::string, std::string>> twoShards(Change change) {
    Identity b;
    change(b);
    return {{"a.csv", kIdentityHeader + identityRow(2, 0, "1/2", Identity{})},
            {"b.csv", kIdentityHeader + identityRow(2, 1, "2/2", b)}};
}

const std::vector<BadMerge> kMixedMerges = {
    {"CpuModel",
     twoShards([](Identity& b) { b.cpu = "Intel(R) Xeon(R) Gold 6338 CPU @ 2.00GHz"; }),
     {"a.csv", "b.csv"},
     "out.csv",
     {"rows of different measurements mixed: cpu_model 'AMD EPYC 7B13' in '{dir}/a.csv:2' but 'Intel(R) "
      "Xeon(R) Gold 6338 CPU @ 2.00GHz' in '{dir}/b.csv:2'",
      "--allow-mixed"}},
    {"Commit",
     twoShards([](Identity& b) { b.commit = "fd7aef0-dirty"; }),
     {"a.csv", "b.csv"},
     "out.csv",
     {"git_commit 'fd7aef0' in '{dir}/a.csv:2' but 'fd7aef0-dirty' in '{dir}/b.csv:2'", "--allow-mixed"}},
    {"DriverVersion",
     twoShards([](Identity& b) { b.driverVersion = "Mesa 22.3.6"; }),
     {"a.csv", "b.csv"},
     "out.csv",
     {"driver_version (api gl) 'Mesa 25.0.7-2~bpo12+1' in '{dir}/a.csv:2' but 'Mesa 22.3.6' in "
      "'{dir}/b.csv:2'"}},
    {"Renderer",
     twoShards([](Identity& b) { b.renderer = "NVIDIA H100 80GB HBM3/PCIe/SSE2"; }),
     {"a.csv", "b.csv"},
     "out.csv",
     {"renderer (api gl) 'llvmpipe (LLVM 15.0.6, 256 bits)' in '{dir}/a.csv:2' but 'NVIDIA H100 80GB "
      "HBM3/PCIe/SSE2' in '{dir}/b.csv:2'"}},
    {"Driver",
     twoShards([](Identity& b) { b.driver = "mesa-25.0.7"; }),
     {"a.csv", "b.csv"},
     "out.csv",
     {"driver 'system' in '{dir}/a.csv:2' but 'mesa-25.0.7' in '{dir}/b.csv:2'"}},
    {"EveryMixedColumnNamed",
     twoShards([](Identity& b) {
         b.cpu = "Ampere Altra";
         b.commit = "c2b2495";
     }),
     {"a.csv", "b.csv"},
     "out.csv",
     {"git_commit 'fd7aef0' in '{dir}/a.csv:2' but 'c2b2495' in '{dir}/b.csv:2'; cpu_model 'AMD EPYC 7B13' "
      "in "
      "'{dir}/a.csv:2' but 'Ampere Altra' in '{dir}/b.csv:2'; merge"}},
    // Three CPU models; the second first appears on line 3 of a.csv, and that is the place named.
    {"ThreeValuesEachWithItsFirstPlace",
     {{"a.csv", kIdentityHeader + identityRow(3, 0, "1/2", Identity{}) +
                    identityRow(3, 2, "1/2", Identity{.cpu = "Ampere Altra"})},
      {"b.csv", kIdentityHeader + identityRow(3, 1, "2/2", Identity{.cpu = "Apple M2"})}},
     {"a.csv", "b.csv"},
     "out.csv",
     {"cpu_model 'AMD EPYC 7B13' in '{dir}/a.csv:2', 'Ampere Altra' in '{dir}/a.csv:3' and 'Apple M2' in "
      "'{dir}/b.csv:2'"}},
};

INSTANTIATE_TEST_SUITE_P(Mixed, CsvMergeRefusalTest, ::testing::ValuesIn(kMixedMerges),
                         [](const ::testing::TestParamInfo<BadMerge>& p) { return p.param.name; });

TEST_F(CsvMergeTest, WhatMayDifferMerges) {
    // Hosts (a cluster's nodes), GL beside Vulkan rows of one driver (each API names renderer and version
    // its own way), a failed row that was never measured (empty cells) and an older file without the
    // columns: none of them is a mixture.
    Identity vulkan;
    vulkan.api = "vulkan";
    vulkan.driverVersion = "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)";
    vulkan.renderer = "llvmpipe (LLVM 15.0.6, 256 bits) lavapipe";
    vulkan.host = "node2";
    writeFile(path("a.csv"),
              kIdentityHeader + identityRow(5, 0, "1/3", Identity{}) + identityRow(5, 3, "1/3", vulkan));
    writeFile(path("b.csv"), kIdentityHeader + identityRow(5, 1, "2/3", Identity{.host = "node3"}) +
                                 "s1,5,4,2/3,failed,,,,,,fd7aef0,node3\n");
    writeFile(path("c.csv"), rows("s1,5,2,3/3,ok\n"));
    MergeOptions options;
    options.allowIncomplete = true; // the failed row
    const MergeReport report = CsvMerge::merge(paths({"a.csv", "b.csv", "c.csv"}), path("out.csv"), options);
    EXPECT_TRUE(report.written);
    EXPECT_TRUE(report.mixtures.empty());
    EXPECT_EQ(report.hosts, std::optional<size_t>(3));
}

TEST_F(CsvMergeTest, HostsAreNotCountedWithoutTheColumn) {
    // CSVs written before rows said where they ran: no host count rather than "0 hosts".
    writeFile(path("a.csv"), rows("s1,1,0,1/1,ok\n"));
    EXPECT_EQ(CsvMerge::merge({path("a.csv")}, path("out.csv"), {}).hosts, std::nullopt);
}

TEST_F(CsvMergeTest, AllowMixedWritesAndListsEachMixture) {
    // Two machine types and their timer verdicts: --allow-mixed lets both through (it covers
    // --allow-mixed-timer), and the report counts each value's rows with its first place.
    const std::string header =
        std::string(kIdentityHeader).insert(std::strlen(kIdentityHeader) - 1, ",timer_verdict");
    auto row = [](size_t index, const std::string& shard, const Identity& id, const std::string& verdict) {
        std::string r = identityRow(3, index, shard, id);
        return r.insert(r.size() - 1, "," + verdict);
    };
    const Identity xeon{.cpu = "Intel Xeon"};
    writeFile(path("a.csv"),
              header + row(0, "1/2", Identity{}, "untrusted") + row(2, "1/2", Identity{}, "untrusted"));
    writeFile(path("b.csv"), header + row(1, "2/2", xeon, "trusted"));

    MergeOptions timerOnly;
    timerOnly.allowMixedTimer = true; // the narrower flag lets the verdicts through, not the CPUs
    EXPECT_NE(
        errorOf(paths({"a.csv", "b.csv"}), path("out.csv"), timerOnly, ExitCode::BadInput).find("cpu_model"),
        std::string::npos);

    MergeOptions options;
    options.allowMixed = true;
    const MergeReport report = CsvMerge::merge(paths({"a.csv", "b.csv"}), path("out.csv"), options);
    EXPECT_TRUE(report.written);
    ASSERT_EQ(report.mixtures.size(), 1u);
    EXPECT_EQ(MeasurementIdentity::describe(report.mixtures[0]),
              "cpu_model: 'AMD EPYC 7B13' 2 rows (first in '" + path("a.csv") +
                  ":2'), 'Intel Xeon' 1 row (first in '" + path("b.csv") + ":2')");
    using Counts = std::vector<std::pair<std::string, size_t>>;
    EXPECT_EQ(report.timerVerdicts, (Counts{{"untrusted", 2}, {"trusted", 1}}));
    EXPECT_EQ(CsvWriter::read(path("out.csv")).rows.size(), 3u);
}

// ---------------------------------------------------------------------------------------------------
// What is missing or failed, per shard

/// Sweep rows with their group, as the bench writes them.
constexpr const char* kGroupHeader =
    "sweep_id,sweep_name,sweep_configs,config_index,config_group,shard,status\n";

std::string groupRow(size_t configs, size_t index, size_t group, const std::string& shard,
                     const std::string& status = "ok") {
    return "s1,study," + std::to_string(configs) + "," + std::to_string(index) + "," + std::to_string(group) +
           "," + shard + "," + status + "\n";
}

TEST_F(CsvMergeTest, GapsAreListedUnderTheShardThatRunsThem) {
    // Six groups of two configurations (two techniques), split 4 ways. Worked out by hand from
    // SweepPlan::shard's rule (group g runs in shard (g mod 4) + 1): groups 0..5 go to shards 1, 2, 3, 4,
    // 1, 2, so shard 1 holds indices 0-1 and 8-9, shard 2 2-3 and 10-11, shard 3 4-5, shard 4 6-7.
    // Shard 2 never ran, shard 4 was killed after index 6, and index 9 failed in shard 1.
    writeFile(path("part1.csv"), kGroupHeader + groupRow(12, 0, 0, "1/4") + groupRow(12, 1, 0, "1/4") +
                                     groupRow(12, 8, 4, "1/4") + groupRow(12, 9, 4, "1/4", "failed"));
    writeFile(path("part3.csv"), kGroupHeader + groupRow(12, 4, 2, "3/4") + groupRow(12, 5, 2, "3/4"));
    writeFile(path("part4.csv"), kGroupHeader + groupRow(12, 6, 3, "4/4"));
    const MergeReport report =
        CsvMerge::merge(paths({"part1.csv", "part3.csv", "part4.csv"}), path("all.csv"), {});
    EXPECT_FALSE(report.written);
    EXPECT_EQ(report.incomplete,
              "5 of 12 configurations missing (indices 2-3, 7, 10-11), 1 failed (indices 9)");
    EXPECT_EQ(report.shardCount, 4u);
    EXPECT_EQ(report.sweepName, "study");
    ASSERT_EQ(report.gaps.size(), 3u);
    EXPECT_EQ(report.gaps[0].shard, 1u);
    EXPECT_EQ(report.gaps[0].missing, IndexRanges{});
    EXPECT_EQ(report.gaps[0].failed, (IndexRanges{{9, 9}}));
    EXPECT_EQ(report.gaps[0].partFile, path("part1.csv"));
    EXPECT_EQ(report.gaps[1].shard, 2u);
    EXPECT_EQ(report.gaps[1].missing, (IndexRanges{{2, 3}, {10, 11}}));
    EXPECT_EQ(report.gaps[1].missingCount, 4u);
    EXPECT_EQ(report.gaps[1].partFile, path("part2.csv")) << "named as the other parts are";
    EXPECT_EQ(report.gaps[2].shard, 4u);
    EXPECT_EQ(report.gaps[2].missing, (IndexRanges{{7, 7}}));
    EXPECT_EQ(report.gaps[2].partFile, path("part4.csv"));
}

TEST_F(CsvMergeTest, GapsAgreeWithSweepPlansOwnSplit) {
    // Seven groups of three techniques split 3 ways, the shards taken from SweepPlan itself: shard 2
    // never ran, shards 1 and 3 each lost their last configuration. Every missing index must be listed
    // under the shard whose groups SweepPlan::shard gives it, and nothing else listed.
    SweepPlan plan;
    for (int g = 0; g < 7; ++g)
        plan.addGroup({"--instances", std::to_string(g + 1)}, {}, {"none", "shadowmap", "vsm"}, 1);
    const size_t configs = plan.configCount();
    std::map<size_t, std::set<size_t>> planned; // shard -> its config indices
    std::set<size_t> written;
    for (int shard = 1; shard <= 3; ++shard) {
        std::vector<size_t> indices;
        for (const SweepGroup* g : plan.shard(shard, 3))
            for (const PlannedRow& r : g->rows) indices.push_back(r.index);
        planned[size_t(shard)].insert(indices.begin(), indices.end());
        if (shard == 2) continue;
        std::string text = kGroupHeader;
        for (const SweepGroup* g : plan.shard(shard, 3))
            for (const PlannedRow& r : g->rows)
                if (r.index != indices.back()) {
                    text += groupRow(configs, r.index, g->index, std::to_string(shard) + "/3");
                    written.insert(r.index);
                }
        writeFile(path("part" + std::to_string(shard) + ".csv"), text);
    }
    const MergeReport report = CsvMerge::merge(paths({"part1.csv", "part3.csv"}), path("all.csv"), {});
    std::map<size_t, std::set<size_t>> listed;
    for (const ShardGap& gap : report.gaps)
        for (const auto& [first, last] : gap.missing)
            for (size_t i = first; i <= last; ++i) listed[gap.shard].insert(i);
    std::map<size_t, std::set<size_t>> expected;
    for (const auto& [shard, indices] : planned)
        for (size_t i : indices)
            if (!written.count(i)) expected[shard].insert(i);
    EXPECT_EQ(listed, expected);
    EXPECT_EQ(expected.size(), 3u) << "every shard lacks something";
}

TEST_F(CsvMergeTest, AGapTheRowsCannotPlaceIsListedUnderNoShard) {
    // Unlike groups (a figure's plan): group 0 holds index 0, group 1 indices 1-3. With only index 0
    // there, sizes 1, 2 and 4 all fit the rows, so the gap's shard is not known; and no part file is
    // named after a shard number to guess the missing part's name from.
    writeFile(path("first.csv"), kGroupHeader + groupRow(4, 0, 0, "1/2"));
    const MergeReport report = CsvMerge::merge({path("first.csv")}, path("all.csv"), {});
    ASSERT_EQ(report.gaps.size(), 1u);
    EXPECT_EQ(report.gaps[0].shard, 0u);
    EXPECT_EQ(report.gaps[0].missing, (IndexRanges{{1, 3}}));
    EXPECT_EQ(report.gaps[0].partFile, "");
}

TEST_F(CsvMergeTest, AGapInsideOneGroupBelongsToItsShard) {
    // Unlike groups of sizes 1, 3 and 2 (no one size fits): index 2 lies between rows of group 1, so
    // it is group 1's, which shard 2 of 2 runs.
    writeFile(path("p1.csv"),
              kGroupHeader + groupRow(6, 0, 0, "1/2") + groupRow(6, 4, 2, "1/2") + groupRow(6, 5, 2, "1/2"));
    writeFile(path("p2.csv"), kGroupHeader + groupRow(6, 1, 1, "2/2") + groupRow(6, 3, 1, "2/2"));
    const MergeReport report = CsvMerge::merge(paths({"p1.csv", "p2.csv"}), path("all.csv"), {});
    ASSERT_EQ(report.gaps.size(), 1u);
    EXPECT_EQ(report.gaps[0].shard, 2u);
    EXPECT_EQ(report.gaps[0].missing, (IndexRanges{{2, 2}}));
    EXPECT_EQ(report.gaps[0].partFile, path("p2.csv"));
}

TEST(ShardGapsTest, GroupSizeIsTheOneEveryRowAgreesWith) {
    using Rows = std::vector<RowPlace>;
    // Groups of 3 of 12 configurations: index 4 in group 1 needs a size in (2, 4], index 8 in group 2 one
    // in (2, 4], index 11 in group 3 one in (2, 3]: only 3. Without the last row both 3 and 4 fit (and
    // both divide 12), so the rows do not tell.
    EXPECT_EQ(ShardGaps::uniformGroupSize(Rows{{4, 1, 2, false}, {8, 2, 3, false}, {11, 3, 4, false}}, 12),
              std::optional<size_t>(3));
    EXPECT_EQ(ShardGaps::uniformGroupSize(Rows{{4, 1, 2, false}, {8, 2, 3, false}}, 12), std::nullopt)
        << "3 and 4 both fit";
    EXPECT_EQ(ShardGaps::uniformGroupSize(Rows{{0, 1, 1, false}, {1, 0, 1, false}}, 4), std::nullopt)
        << "groups falling as indices rise are damaged";
    EXPECT_EQ(ShardGaps::uniformGroupSize(Rows{{0, std::nullopt, 1, false}}, 4), std::nullopt);
}

TEST(ShardGapsTest, AHugeGapIsSplitOnlySoFar) {
    // sweep_configs says a billion (damaged), groups of one: the first kMaxPieces indices of the gap are
    // placed (alternating shards), the rest is listed under no shard, and the counts add up.
    const std::vector<RowPlace> rows{{0, 0, 1, false}, {1, 1, 2, false}};
    const std::vector<ShardGap> gaps = ShardGaps::compute(rows, {{2, 999999999}}, 1000000000, 2);
    ASSERT_EQ(gaps.size(), 3u);
    EXPECT_EQ(gaps[0].shard, 0u);
    EXPECT_EQ(gaps[0].missing, (IndexRanges{{2 + ShardGaps::kMaxPieces, 999999999}}));
    EXPECT_EQ(gaps[1].missingCount + gaps[2].missingCount, ShardGaps::kMaxPieces);
    EXPECT_EQ(gaps[1].missing.front(), (std::pair<size_t, size_t>{2, 2}));
    EXPECT_EQ(gaps[2].missing.front(), (std::pair<size_t, size_t>{3, 3}));
    EXPECT_EQ(gaps[0].missingCount + ShardGaps::kMaxPieces, 999999998u);
}

} // namespace
