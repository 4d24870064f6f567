// `bench bottleneck` end to end: the classifier must name the bottleneck of workloads whose
// bottleneck is known by construction (the independent answer), on whatever GL the test runs on:
//   fill:   a full-screen pass of 100 arithmetic steps per pixel, no geometry;
//   vertex: a million tiny triangles (synthetic_triangles: 256 spheres x 4032 triangles, a few pixels each);
//   cpu:    10000 two-triangle quads in immediate mode (synthetic_draws: draw calls, next to no work).
// The same three on Vulkan (--api vulkan: every run of the study draws with the Vulkan forms).
// The label needs a share >= 0.5; measured margins on llvmpipe are wide (fill 0.91-0.94, vertex 0.91-0.98,
// cpu 0.89-0.95 at 128^2-512^2), so timing noise from tests running beside this one cannot flip it.
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"

using namespace sb;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;

struct KnownWorkload {
    const char* name;
    const char* args;
    const char* expected;
};

const KnownWorkload kWorkloads[] = {
    {"fill", "-t synthetic:fragment_iterations=100:draw_scene=false --scene sphere_plane", "fill"},
    {"vertex", "-t synthetic --scene synthetic_triangles", "vertex"},
    {"cpu", "-t synthetic --scene synthetic_draws --submit immediate", "cpu"},
    // The same claim on Vulkan (lavapipe): the workloads' Vulkan forms, the study's Vulkan submission
    // switch (instanced), and retained submission as the CPU workload (Vulkan has no immediate mode: its
    // 10000 per-instance draws are the CPU's work). Measured shares on lavapipe at 256^2 on a loaded
    // machine: fill 0.93, vertex 0.75, cpu 0.94.
    {"vulkan_fill", "--api vulkan -t synthetic:fragment_iterations=100:draw_scene=false --scene sphere_plane",
     "fill"},
    {"vulkan_vertex", "--api vulkan -t synthetic --scene synthetic_triangles", "vertex"},
    {"vulkan_cpu", "--api vulkan -t synthetic --scene synthetic_draws", "cpu"},
};

void PrintTo(const KnownWorkload& w, std::ostream* os) {
    *os << w.name;
}

std::string column(const CsvTable& t, size_t row, const std::string& name) {
    const auto it = std::find(t.header.begin(), t.header.end(), name);
    return it == t.header.end() ? "<no column " + name + ">" : t.rows[row][size_t(it - t.header.begin())];
}

/// The cells of line `line` of a Markdown table ("| a | b |" -> {"a", "b"}), trimmed.
std::vector<std::string> markdownCells(const std::string& text, size_t line) {
    std::istringstream in(text);
    std::string l;
    for (size_t i = 0; i <= line; ++i)
        if (!std::getline(in, l)) return {};
    std::vector<std::string> cells;
    std::istringstream row(l);
    std::string cell;
    std::getline(row, cell, '|'); // before the first bar
    while (std::getline(row, cell, '|')) {
        const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
        cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
    }
    if (!cells.empty() && cells.back().empty()) cells.pop_back(); // after the last bar
    return cells;
}

class KnownBottleneck : public ::testing::TestWithParam<KnownWorkload> {};

TEST_P(KnownBottleneck, IsNamedCorrectly) {
    const KnownWorkload& w = GetParam();
    const std::string dir = test::freshDir(std::string("bottleneck-") + w.name);
    const std::string csv = dir + "/bn.csv";
    auto r = runCommand(kBench + " bottleneck " + w.args +
                        " --size 256x256 --frames 4 --warmup 1 --no-progress --csv " + csv);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const CsvTable rows = CsvWriter::read(csv);
    // baseline, the submission switch, two scale runs, two sizes, two tessellations (+ LP_NO_RAST on
    // llvmpipe).
    const bool llvmpipe = column(rows, 0, "renderer").find("llvmpipe") != std::string::npos;
    EXPECT_EQ(rows.rows.size(), llvmpipe ? 9u : 8u);
    const CsvTable classes = CsvWriter::read(dir + "/bn_classes.csv");
    ASSERT_EQ(classes.rows.size(), 1u);
    EXPECT_EQ(column(classes, 0, "class"), w.expected) << r.output;
    const double share = std::stod(column(classes, 0, std::string("share_") + w.expected));
    EXPECT_GE(share, 0.5) << r.output;
    const double sum = std::stod(column(classes, 0, "share_cpu")) +
                       std::stod(column(classes, 0, "share_vertex")) +
                       std::stod(column(classes, 0, "share_fill"));
    EXPECT_NEAR(sum, 1.0, 3e-4) << "shares add up (4-decimal CSV rounding)";
    EXPECT_NE(r.output.find(std::string(w.expected)), std::string::npos);
    // --from reclassifies the same rows to the same answer.
    auto again = runCommand(kBench + " bottleneck --from " + csv + " --classes " + dir + "/again.csv");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(column(CsvWriter::read(dir + "/again.csv"), 0, "class"), w.expected);
    // --format md prints the classification the console table prints: the class and the shares, the
    // same values as the classes CSV.
    auto md = runCommand("(" + kBench + " bottleneck --from " + csv + " --classes " + dir +
                         "/md.csv --format md 2>/dev/null)");
    ASSERT_EQ(md.exitCode, 0) << md.output;
    const std::vector<std::string> header = markdownCells(md.output, 0), cells = markdownCells(md.output, 2);
    for (const std::string name : {"class", "share_cpu", "share_vertex", "share_fill", "technique_spec"}) {
        const auto at = std::find(header.begin(), header.end(), name);
        ASSERT_NE(at, header.end()) << "no column " << name << " in:\n" << md.output;
        ASSERT_LT(size_t(at - header.begin()), cells.size()) << md.output;
        EXPECT_EQ(cells[size_t(at - header.begin())], column(classes, 0, name)) << md.output;
    }
}

INSTANTIATE_TEST_SUITE_P(Synthetic, KnownBottleneck, ::testing::ValuesIn(kWorkloads),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(BottleneckCli, FromACsvWithoutStudyRowsIsAClearError) {
    const std::string dir = test::freshDir("bottleneck-from");
    auto run = runCommand(kBench + " -t none --instances 2 --size 64x64 --frames 2 --warmup 1 --csv " + dir +
                          "/r.csv");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto r = runCommand(kBench + " bottleneck --from " + dir + "/r.csv");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("no bottleneck rows"), std::string::npos) << r.output;
    // A dashboard format has nothing to chart in a classification: refused before anything runs.
    auto gbench = runCommand(kBench + " bottleneck -t none --format gbench --csv " + dir + "/never.csv");
    EXPECT_EQ(gbench.exitCode, 2) << gbench.output;
    EXPECT_NE(gbench.output.find("bench export"), std::string::npos) << gbench.output;
    EXPECT_FALSE(std::filesystem::exists(dir + "/never.csv"));
}

// What each stage's load is, as --help says it and as docs/USAGE.md says it: the same definitions,
// compared as words (line breaks and its backticks aside), and both the ones the classifier
// uses (bench/lib/bottleneck/BottleneckStudy.cpp reads load_gl_calls, load_primitives, load_fragments).
TEST(BottleneckCli, HelpAndReadmeDefineTheLoadsAlike) {
    auto squash = [](std::string text) {
        std::string out;
        for (char c : text) {
            if (c == '`') continue;
            const char d = c == '\n' ? ' ' : c;
            if (d == ' ' && !out.empty() && out.back() == ' ') continue;
            out += d;
        }
        return out;
    };
    const auto help = runCommand(kBench + " bottleneck --help");
    ASSERT_EQ(help.exitCode, 0) << help.output;
    const std::string readme = squash(test::readFile(std::string(SB_SOURCE_DIR) + "/docs/USAGE.md"));
    for (const char* definition :
         {"CPU load = GL calls issued", "vertex load = primitives submitted (not vertex shader invocations",
          "fill load = fragment shader invocations"}) {
        EXPECT_NE(squash(help.output).find(definition), std::string::npos) << definition << "\n"
                                                                           << help.output;
        EXPECT_NE(readme.find(definition), std::string::npos) << definition << " is not in docs/USAGE.md";
    }
}

} // namespace
