// `bench merge` (bench/lib/output/CsvMerge.h): shard CSVs of one sweep joined into one file, sorted by
// config_index with the union of the headers, and every way inputs can fail to fit together refused
// with a message naming the file. Expected files are written out by hand and compared exactly; every
// refusal also checks that nothing was written (no output, no temporary file).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvMerge.h"
#include "bench/lib/output/CsvWriter.h"
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
    MergeReport report = CsvMerge::merge(paths({"a.csv", "b.csv"}), path("all.csv"), {});
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
    EXPECT_EQ(listDir(), (std::vector<std::string>{"a.csv", "all.csv", "b.csv"}));
}

TEST_F(CsvMergeTest, QuotedCellsSurviveTheMerge) {
    // A multi-line error with quotes and commas is re-quoted exactly as CsvWriter writes it.
    writeFile(path("a.csv"), "sweep_id,sweep_configs,config_index,shard,status,error\n"
                             "s1,2,1,1/2,failed,\"GL_OUT_OF_MEMORY, \"\"fbo\"\"\nat pass 2\"\n");
    writeFile(path("b.csv"), std::string(kHeader) + "s1,2,0,2/2,ok\n");
    CsvMerge::merge(paths({"a.csv", "b.csv"}), path("all.csv"), {});
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
    // failedRows counts rows whose status is not "ok"; without the column no row is known to be ok.
    writeFile(path("a.csv"), "sweep_id,sweep_configs,config_index,shard\ns1,2,0,1/1\ns1,2,1,1/1\n");
    EXPECT_EQ(CsvMerge::merge({path("a.csv")}, path("out.csv"), {}).failedRows, 2u);
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
    {"Incomplete",
     {{"a.csv", rows("s1,6,0,1/2,ok\ns1,6,2,1/2,ok\n")}, {"b.csv", rows("s1,6,3,2/2,ok\n")}},
     {"a.csv", "b.csv"},
     "out.csv",
     {"incomplete: 3 of 6 configurations missing (indices 1, 4-5); rerun the shards that wrote them, or "
      "pass --allow-incomplete"}},
    {"IncompleteListsRanges",
     {{"a.csv", rows("s1,20,0,1/1,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"incomplete: 19 of 20 configurations missing (indices 1-19); rerun"}},
    {"IncompleteListsAtMostTenRanges",
     {{"a.csv",
       rows("s1,30,0,1/1,ok\ns1,30,2,1/1,ok\ns1,30,4,1/1,ok\ns1,30,6,1/1,ok\ns1,30,8,1/1,ok\ns1,30,10,1/1,"
            "ok\ns1,30,12,1/1,ok\ns1,30,14,1/1,ok\ns1,30,16,1/1,ok\ns1,30,18,1/1,ok\ns1,30,20,1/1,ok\n")}},
     {"a.csv"},
     "out.csv",
     {"incomplete: 19 of 30 configurations missing (indices 1, 3, 5, 7, 9, 11, 13, 15, 17, 19, ...); rerun"}},
    // A damaged cell claiming a billion configurations: one line with the gaps as ranges, not a list
    // of a billion indices (which took past 4 GiB).
    {"IncompleteOfABillionIsOneRange",
     {{"a.csv", rows("s1,1000000000,0,1/2,ok\n")}, {"b.csv", rows("s1,1000000000,1,2/2,ok\n")}},
     {"a.csv", "b.csv"},
     "out.csv",
     {"incomplete: 999999998 of 1000000000 configurations missing (indices 2-999999999); rerun"}},
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

} // namespace
