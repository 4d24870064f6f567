// Result rows as CSV, JSON and Markdown (bench/lib/output/RowExport.h). Every expected text is written out by
// hand and compared exactly: JSON typing per column, escaping, the Markdown common-value list, padding
// and alignment.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/RowExport.h"
#include "core/Error.h"

using namespace sb;
using test::readFile;
namespace fs = std::filesystem;

namespace {

class RowExportTest : public ::testing::Test {
protected:
    void SetUp() override { mDir = test::freshTestDir("rowexport"); }
    void TearDown() override { fs::remove_all(mDir); }
    std::string mDir;
};

// ---------------------------------------------------------------------------------------------------
// Format names

TEST_F(RowExportTest, ParseRowFormatAcceptsTheDocumentedNames) {
    EXPECT_EQ(parseRowFormat("console"), RowFormat::Console);
    EXPECT_EQ(parseRowFormat("csv"), RowFormat::Csv);
    EXPECT_EQ(parseRowFormat("json"), RowFormat::Json);
    EXPECT_EQ(parseRowFormat("md"), RowFormat::Markdown);
    EXPECT_EQ(parseRowFormat("markdown"), RowFormat::Markdown);
}

TEST_F(RowExportTest, ParseRowFormatRejectsOthersListingTheValidNames) {
    // Names are exact: "JSON" and "" are refused like any unknown word, with exit code 2.
    for (const char* bad : {"xml", "JSON", ""}) {
        try {
            parseRowFormat(bad);
            ADD_FAILURE() << "'" << bad << "' accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ExitCode::BadInput);
            EXPECT_EQ(std::string(e.what()), "unknown output format '" + std::string(bad) +
                                                 "' (valid: console, csv, json, md, markdown, gbench, gh-benchmark)");
        }
    }
}

TEST_F(RowExportTest, FormatDispatchesAndRefusesConsole) {
    // format() is the same text as the specific functions; console has no text export.
    CsvTable table{{"technique", "frames"}, {{"pcf", "60"}}};
    EXPECT_EQ(RowExport::format(table, RowFormat::Csv), "technique,frames\npcf,60\n");
    EXPECT_EQ(RowExport::format(table, RowFormat::Json),
              "{\n  \"columns\": [\n    \"technique\",\n    \"frames\"\n  ],\n"
              "  \"rows\": [\n    {\n      \"technique\": \"pcf\",\n      \"frames\": 60\n    }\n  ]\n}\n");
    EXPECT_EQ(RowExport::format(table, RowFormat::Markdown), "| technique | frames |\n"
                                                             "| --------- | -----: |\n"
                                                             "| pcf       |     60 |\n");
    EXPECT_THROW(RowExport::format(table, RowFormat::Console), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------------
// CSV

TEST_F(RowExportTest, CsvIsByteIdenticalToTheFileCsvWriterWrites) {
    // The same rows written by CsvWriter and exported by toCsv: one serializer, identical bytes.
    std::string path = mDir + "/r.csv";
    CsvWriter::appendRows(path, {{{"technique", "pcf"}, {"note", "a,b"}, {"error", "say \"hi\"\nbye"}},
                                 {{"technique", "none"}}});
    CsvTable table = CsvWriter::read(path);
    const std::string expected = "technique,note,error\n"
                                 "pcf,\"a,b\",\"say \"\"hi\"\"\nbye\"\n"
                                 "none,,\n";
    EXPECT_EQ(readFile(path), expected);
    EXPECT_EQ(RowExport::toCsv(table), expected);
}

// ---------------------------------------------------------------------------------------------------
// JSON

struct NumberCase {
    const char* cell;
    bool number;
};
const NumberCase kNumberCases[] = {
    {"0", true},      {"-0", true},   {"7", true},      {"-12", true},   {"0.5", true},    {"1.2500", true},
    {"1e5", true},    {"1E+5", true}, {"2.5e-3", true}, {"0123", false}, {"00", false},    {"-0123", false},
    {"00.5", false},  {"+1", false},  {"0x1A", false},  {"inf", false},  {"-inf", false},  {"nan", false},
    {".5", false},    {"1.", false},  {" 1", false},    {"1 ", false},   {"1e", false},    {"1e+", false},
    {"1e999", false}, {"", false},    {"-", false},     {"1,5", false},  {"1.2.3", false}, {"12abc", false},
};

TEST_F(RowExportTest, NumberRuleIsTheJsonLiteralGrammarWithFiniteValue) {
    // Leading zeros, '+', hex, inf/nan, ".5"/"1." and overflowing exponents are not numbers.
    for (const NumberCase& c : kNumberCases)
        EXPECT_EQ(RowExport::isNumber(c.cell), c.number) << "'" << c.cell << "'";
}

TEST_F(RowExportTest, JsonTypesEachColumnAsAWhole) {
    // wall_ms_median/frames/sci/big are numeric columns (an empty cell is null, "1.2500" becomes 1.25,
    // "1e5" 100000.0); "0123" makes its whole column strings, as does one text cell in "mixed";
    // git_commit looks numeric but is an identifier; an all-empty column is all null.
    CsvTable table{
        {"wall_ms_median", "frames", "scene", "git_commit", "padded", "sci", "mixed", "big", "note"},
        {{"1.2500", "60", "a", "1234567", "0123", "1e5", "5", "18446744073709551615", ""},
         {"-0.5", "", "b", "7654321", "7", "2E-2", "x", "99999999999999999999", ""}}};
    EXPECT_EQ(RowExport::toJson(table), R"({
  "columns": [
    "wall_ms_median",
    "frames",
    "scene",
    "git_commit",
    "padded",
    "sci",
    "mixed",
    "big",
    "note"
  ],
  "rows": [
    {
      "wall_ms_median": 1.25,
      "frames": 60,
      "scene": "a",
      "git_commit": "1234567",
      "padded": "0123",
      "sci": 100000.0,
      "mixed": "5",
      "big": 18446744073709551615,
      "note": null
    },
    {
      "wall_ms_median": -0.5,
      "frames": null,
      "scene": "b",
      "git_commit": "7654321",
      "padded": "7",
      "sci": 0.02,
      "mixed": "x",
      "big": 1e+20,
      "note": null
    }
  ]
}
)");
}

TEST_F(RowExportTest, JsonKeepsIdentifierColumnsAsStrings) {
    // Every named identifier and every *_hash / *_id column stays a string; config_index, which
    // merely contains "_id" inside, and "ids" are ordinary numeric columns.
    CsvTable table{{"git_commit", "scene_hash", "sweep_id", "seed", "shard", "config_key", "mesh_hash",
                    "light_id", "config_index", "ids"},
                   {{"1234567", "42", "99", "7", "1", "3", "5", "6", "8", "9"}}};
    EXPECT_EQ(RowExport::toJson(table), R"({
  "columns": [
    "git_commit",
    "scene_hash",
    "sweep_id",
    "seed",
    "shard",
    "config_key",
    "mesh_hash",
    "light_id",
    "config_index",
    "ids"
  ],
  "rows": [
    {
      "git_commit": "1234567",
      "scene_hash": "42",
      "sweep_id": "99",
      "seed": "7",
      "shard": "1",
      "config_key": "3",
      "mesh_hash": "5",
      "light_id": "6",
      "config_index": 8,
      "ids": 9
    }
  ]
}
)");
}

TEST_F(RowExportTest, JsonEscapesQuotesNewlinesAndBackslashesInKeysAndValues) {
    // nlohmann does the escaping: \" \n \r \t \\ and control characters as \u00XX; UTF-8 passes through.
    CsvTable table{{"say \"col\"", "error"}, {{"a\"b\\c", "line1\nline2\r\tend\x01 \xC2\xB5s"}}};
    EXPECT_EQ(RowExport::toJson(table), "{\n"
                                        "  \"columns\": [\n"
                                        "    \"say \\\"col\\\"\",\n"
                                        "    \"error\"\n"
                                        "  ],\n"
                                        "  \"rows\": [\n"
                                        "    {\n"
                                        "      \"say \\\"col\\\"\": \"a\\\"b\\\\c\",\n"
                                        "      \"error\": \"line1\\nline2\\r\\tend\\u0001 \xC2\xB5s\"\n"
                                        "    }\n"
                                        "  ]\n"
                                        "}\n");
}

TEST_F(RowExportTest, JsonOfEmptyTables) {
    // No header at all, and a header without rows.
    EXPECT_EQ(RowExport::toJson(CsvTable{}), "{\n  \"columns\": [],\n  \"rows\": []\n}\n");
    EXPECT_EQ(RowExport::toJson(CsvTable{{"a"}, {}}),
              "{\n  \"columns\": [\n    \"a\"\n  ],\n  \"rows\": []\n}\n");
}

// ---------------------------------------------------------------------------------------------------
// Markdown

const CsvTable kTwoRuns{{"renderer", "technique", "scene", "status", "wall_ms_median", "error", "unlisted"},
                        {{"Mesa llvmpipe", "shadowmap", "a", "ok", "1.2000", "", "zzz"},
                         {"Mesa llvmpipe", "pcf", "a", "ok", "12.5000", "", "yyy"}}};

TEST_F(RowExportTest, MarkdownMovesConstantColumnsAboveTheTable) {
    // Curated order (status, technique, scene, wall_ms_median, renderer); status, scene and renderer
    // are the same in both rows, error is always empty, "unlisted" is not curated. Numbers right-aligned.
    EXPECT_EQ(RowExport::toMarkdown(kTwoRuns), "Common to all 2 rows:\n"
                                               "- status: ok\n"
                                               "- scene: a\n"
                                               "- renderer: Mesa llvmpipe\n"
                                               "\n"
                                               "| technique | wall_ms_median |\n"
                                               "| --------- | -------------: |\n"
                                               "| shadowmap |         1.2000 |\n"
                                               "| pcf       |        12.5000 |\n");
}

TEST_F(RowExportTest, MarkdownAllColumnsUsesHeaderOrder) {
    // Same table, every column considered in header order; the same constant/empty handling.
    EXPECT_EQ(RowExport::toMarkdown(kTwoRuns, true), "Common to all 2 rows:\n"
                                                     "- renderer: Mesa llvmpipe\n"
                                                     "- scene: a\n"
                                                     "- status: ok\n"
                                                     "\n"
                                                     "| technique | wall_ms_median | unlisted |\n"
                                                     "| --------- | -------------: | -------- |\n"
                                                     "| shadowmap |         1.2000 | zzz      |\n"
                                                     "| pcf       |        12.5000 | yyy      |\n");
}

TEST_F(RowExportTest, MarkdownEscapesPipesAndFlattensLineBreaks) {
    // '|' becomes '\|' in cells and in the list; LF, CRLF and CR each become one space. Widths count
    // the escaped text, so the raw table stays aligned.
    CsvTable table{{"technique", "properties", "error", "scene"},
                   {{"pcf", "kernel=3|bias=0.1", "line1\nline2", "x|y"}, {"vsm", "a|b", "x\r\ny\rz", "x|y"}}};
    EXPECT_EQ(RowExport::toMarkdown(table), "Common to all 2 rows:\n"
                                            "- scene: x\\|y\n"
                                            "\n"
                                            "| error       | technique | properties         |\n"
                                            "| ----------- | --------- | ------------------ |\n"
                                            "| line1 line2 | pcf       | kernel=3\\|bias=0.1 |\n"
                                            "| x y z       | vsm       | a\\|b               |\n");
}

TEST_F(RowExportTest, MarkdownPadsByCodePointsNotBytes) {
    // "µs" is 3 bytes but 2 characters wide, so "µs" gets one space of padding next to "abc".
    CsvTable table{{"technique"}, {{"\xC2\xB5s"}, {"abc"}}};
    EXPECT_EQ(RowExport::toMarkdown(table), "| technique |\n"
                                            "| --------- |\n"
                                            "| \xC2\xB5s        |\n"
                                            "| abc       |\n");
}

TEST_F(RowExportTest, MarkdownSingleRowIsAOneRowTable) {
    // With one row everything is "constant"; it stays a table rather than a list. Empty error dropped.
    CsvTable table{{"technique", "wall_ms_median", "error"}, {{"pcf", "1.0000", ""}}};
    EXPECT_EQ(RowExport::toMarkdown(table), "| technique | wall_ms_median |\n"
                                            "| --------- | -------------: |\n"
                                            "| pcf       |         1.0000 |\n");
}

TEST_F(RowExportTest, MarkdownOfIdenticalRowsIsOnlyTheList) {
    // Two identical rows: no column varies, so there is no table.
    CsvTable table{{"technique", "scene"}, {{"pcf", "a"}, {"pcf", "a"}}};
    EXPECT_EQ(RowExport::toMarkdown(table), "Common to all 2 rows:\n- technique: pcf\n- scene: a\n");
}

TEST_F(RowExportTest, MarkdownWithoutRowsOrShowableColumns) {
    // No rows (with or without header) gives "(no rows)"; rows whose curated columns are absent or
    // empty say so instead of printing nothing; allColumns then shows the uncurated column.
    EXPECT_EQ(RowExport::toMarkdown(CsvTable{}), "(no rows)\n");
    EXPECT_EQ(RowExport::toMarkdown(CsvTable{{"technique"}, {}}), "(no rows)\n");
    CsvTable table{{"foo", "error"}, {{"1", ""}, {"2", ""}}};
    EXPECT_EQ(RowExport::toMarkdown(table), "(2 rows, no column to show)\n");
    EXPECT_EQ(RowExport::toMarkdown(table, true), "| foo |\n"
                                                  "| --: |\n"
                                                  "|   1 |\n"
                                                  "|   2 |\n");
}

TEST_F(RowExportTest, MarkdownColumnsAreTheDocumentedList) {
    // The list the README points to, in order.
    const std::vector<std::string> expected = {"status",
                                               "error",
                                               "technique",
                                               "properties",
                                               "scene",
                                               "instances",
                                               "scale",
                                               "tessellation",
                                               "submit",
                                               "camera",
                                               "width",
                                               "height",
                                               "lights",
                                               "perturbation",
                                               "repeat",
                                               "frames",
                                               "wall_ms_median",
                                               "wall_ms_p5",
                                               "wall_ms_p95",
                                               "wall_ms_mad",
                                               "cpu_submit_ms_median",
                                               "fps_median",
                                               "gpu_ms_median",
                                               "wall_ratio_vs_baseline",
                                               "timer_verdict",
                                               "acc_wrong_pct",
                                               "acc_wrong_no_edge_pct",
                                               "acc_rmse",
                                               "acc_nan",
                                               "acc_inf",
                                               "acc_out_of_range",
                                               "acc_gain_camera",
                                               "acc_gain_light",
                                               "acc_flicker",
                                               "load_gl_calls",
                                               "load_vertices",
                                               "load_fragments",
                                               "renderer"};
    EXPECT_EQ(RowExport::markdownColumns(), expected);
}

} // namespace
