// `bench figures --plot-only` is reproducible byte for byte: replotting the committed CSVs twice, and in
// two different folders, gives identical PNG and SVG files, so regenerating the committed figures
// leaves git clean unless the data or tools/plot.py changed. One figure of each plot kind of
// tools/plot.py (lines, pareto, bottleneck, bars) is replotted from the rows committed under
// results/figures/. Skipped when Debian's python3 lacks matplotlib or pandas (python3-matplotlib,
// python3-pandas).
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"

using namespace sb;
using test::runCommand;

namespace {

namespace fs = std::filesystem;

const std::string kBench = SB_BENCH_BINARY;
// lines (with rounds), pareto (numbered points), bottleneck (classes.csv from data.csv), bars.
const std::vector<std::string> kFigures = {"instances_teapot", "accuracy_aircraft", "bottleneck_calibration",
                                           "proxy_offset"};

bool havePlotting() {
    return runCommand("/usr/bin/python3 -c 'import matplotlib, pandas'").exitCode == 0;
}

/// A folder holding the committed rows of kFigures only, as `bench figures --plot-only --out` reads them.
std::string copyRows(const std::string& dir) {
    for (const std::string& name : kFigures) {
        fs::create_directories(dir + "/" + name);
        fs::copy_file(std::string(SB_SOURCE_DIR) + "/results/figures/" + name + "/data.csv",
                      dir + "/" + name + "/data.csv", fs::copy_options::overwrite_existing);
    }
    return dir;
}

test::CommandResult replot(const std::string& dir) {
    std::string only;
    for (const std::string& name : kFigures) only += (only.empty() ? "" : ",") + name;
    return runCommand(kBench + " figures --plot-only --only " + only + " --out " + dir);
}

} // namespace

TEST(PlotCli, ReplotIsIdenticalByteForByte) {
    if (!havePlotting())
        GTEST_SKIP() << "/usr/bin/python3 needs matplotlib and pandas: apt-get install python3-matplotlib "
                        "python3-pandas";
    const std::string root = test::freshTestDir("plot");
    const std::string a = copyRows(root + "/a"), b = copyRows(root + "/b");
    auto first = replot(a);
    ASSERT_EQ(first.exitCode, 0) << first.output;
    std::vector<std::pair<std::string, std::string>> firstFiles;
    for (const std::string& name : kFigures)
        for (const char* ext : {"png", "svg"}) {
            const std::string path = a + "/" + name + "/figure." + ext;
            firstFiles.emplace_back(path, test::readFile(path));
        }
    auto again = replot(a);
    ASSERT_EQ(again.exitCode, 0) << again.output;
    auto elsewhere = replot(b);
    ASSERT_EQ(elsewhere.exitCode, 0) << elsewhere.output;
    for (const auto& [path, bytes] : firstFiles) {
        SCOPED_TRACE(path);
        ASSERT_GT(bytes.size(), 1000u);
        EXPECT_TRUE(test::readFile(path) == bytes) << "a replot in the same folder changed the file";
        const std::string other = b + path.substr(a.size());
        EXPECT_TRUE(test::readFile(other) == bytes) << "a replot in another folder differs: " << other;
        if (path.ends_with(".svg")) {
            EXPECT_EQ(bytes.find("<dc:date>"), std::string::npos) << "no date in the SVG metadata";
            EXPECT_NE(bytes.find("shadowbench tools/plot.py"), std::string::npos) << "the fixed creator";
        }
    }
    // The rows behind the summaries and classifications are rewritten identically too.
    for (const std::string& name : kFigures) {
        EXPECT_EQ(test::readFile(a + "/" + name + "/summary.md"),
                  test::readFile(b + "/" + name + "/summary.md"))
            << name;
    }
}
