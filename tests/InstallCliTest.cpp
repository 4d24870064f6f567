// Installing, as a user of a C++/CMake tool would: `cmake --install` into a temporary prefix gives a
// bench that finds its own shaders, scenes, tools and figure catalogue there (its --version names the
// folder, so a silent fall-back to the source tree would show) and whose subcommands that read them
// run from the prefix alone; the commit a binary reports is the one it was built from, whatever
// happens to the tree after the build. The .deb is tests/PackageCliTest.cpp's. About 20 s in all (the
// install copies ~3 MB; the smallest reduced figure measures 12 rows at 128x128 and plots them).
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestPaths.h"
#include "TestSupport.h"

using namespace sb;
namespace fs = std::filesystem;

namespace {

const fs::path kBuildDir = fs::path(SB_BENCH_BINARY).parent_path();

std::string shellQuoted(const fs::path& p) {
    return "'" + p.string() + "'";
}

/// The value of "KEY VALUE" lines in `bench --version`'s output.
std::string versionField(const std::string& text, const std::string& key) {
    std::smatch m;
    const std::regex line("(^|\\n)" + key + " ([^\\n]*)");
    return std::regex_search(text, m, line) ? m[2].str() : "";
}

class InstallCliTest : public ::testing::Test {
protected:
    void SetUp() override { mDir = test::freshTestDir("install"); }
    void TearDown() override { fs::remove_all(mDir); }
    std::string mDir;
};

/// Restores a file's bytes when it goes out of scope, so a failed assertion never leaves the tree
/// edited.
class RestoreFile {
public:
    explicit RestoreFile(fs::path path) : mPath(std::move(path)), mText(test::readFile(mPath.string())) {}
    ~RestoreFile() { test::writeFile(mPath.string(), mText); }
    const std::string& original() const { return mText; }

private:
    fs::path mPath;
    std::string mText;
};

} // namespace

TEST_F(InstallCliTest, InstalledBenchFindsItsShadersScenesAndTools) {
    const fs::path prefix = fs::path(mDir) / "prefix";
    const auto install =
        test::runCommand("cmake --install " + shellQuoted(kBuildDir) + " --prefix " + shellQuoted(prefix));
    ASSERT_EQ(install.exitCode, 0) << install.output;
    const fs::path share = prefix / "share" / "shadowbench";
    for (const fs::path& f :
         {prefix / "bin" / "bench", prefix / "bin" / "handloop", prefix / "bin" / "handshadow",
          share / "shaders" / "common" / "lighting.glsl", share / "scenes" / "data" / "aircraft.json",
          share / "tools" / "plot.py", share / "results" / "ci" / "suite.json",
          share / "results" / "goldens" / "bounds.json", share / "results" / "figures" / "figures.json",
          share / "sweeps", share / "tools" / "report.py",
          prefix / "share" / "doc" / "shadowbench" / "copyright"})
        EXPECT_TRUE(fs::exists(f)) << f << " not installed";

    const fs::path bench = prefix / "bin" / "bench";
    const auto version = test::runCommand(shellQuoted(bench) + " --version");
    ASSERT_EQ(version.exitCode, 0) << version.output;
    // The installed binary reads its own prefix: not the build tree, not the source tree.
    EXPECT_EQ(fs::weakly_canonical(versionField(version.output, "data")), fs::weakly_canonical(share))
        << version.output;
    // A run of a built-in scene file and a shader-heavy technique from the prefix alone.
    const auto run = test::runCommand("cd " + shellQuoted(mDir) + " && " + shellQuoted(bench) +
                                      " -t shadowmap --scene sphere_plane --frames 2 --warmup 0 --size 64x64"
                                      " --no-timer-check -q --format json");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto rows = nlohmann::json::parse(run.output.substr(run.output.find('{')));
    ASSERT_EQ(rows["rows"].size(), 1u) << run.output;
    EXPECT_EQ(rows["rows"][0]["status"], "ok");
    EXPECT_EQ(rows["rows"][0]["scene"], "sphere_plane");

    // `man bench` and the completion after the install: the page renders from the prefix without a
    // warning and names the plain run's options, and the installed completion is the one the binary
    // writes (ManPageCliTest and CompletionCliTest check their content).
    const fs::path page = prefix / "share" / "man" / "man1" / "bench.1.gz";
    const auto man = test::runCommand("MANWIDTH=80 man --warnings -l " + shellQuoted(page) + " 2>&1");
    ASSERT_EQ(man.exitCode, 0) << man.output;
    EXPECT_NE(man.output.find("--technique"), std::string::npos) << man.output.substr(0, 2000);
    // groff's and man's complaints start with their names; the page itself may say "warning".
    EXPECT_EQ(man.output.find("troff:"), std::string::npos) << man.output.substr(0, 2000);
    EXPECT_EQ(man.output.find("man:"), std::string::npos) << man.output.substr(0, 2000);
    const auto completion = test::runCommand(shellQuoted(bench) + " --completion bash");
    ASSERT_EQ(completion.exitCode, 0) << completion.output;
    EXPECT_EQ(test::readFile((prefix / "share" / "bash-completion" / "completions" / "bench").string()),
              completion.output);
}

TEST_F(InstallCliTest, FiguresAndReportRunFromThePrefix) {
    const fs::path prefix = fs::path(mDir) / "prefix";
    const auto install =
        test::runCommand("cmake --install " + shellQuoted(kBuildDir) + " --prefix " + shellQuoted(prefix));
    ASSERT_EQ(install.exitCode, 0) << install.output;
    const std::string bench = shellQuoted(prefix / "bin" / "bench");
    const std::string inDir = "cd " + shellQuoted(mDir) + " && ";

    // The installed catalogue is the source tree's: --list names every figure it declares.
    const auto catalog = nlohmann::json::parse(
        test::readFile((fs::path(SB_SOURCE_DIR) / "results" / "figures" / "figures.json").string()), nullptr,
        true, /*ignore_comments=*/true);
    ASSERT_FALSE(catalog.empty());
    const auto list = test::runCommand(inDir + bench + " figures --list");
    ASSERT_EQ(list.exitCode, 0) << list.output;
    for (const auto& f : catalog)
        EXPECT_NE(list.output.find(f["name"].get<std::string>() + "  "), std::string::npos)
            << f["name"] << " not listed:\n"
            << list.output;
    EXPECT_EQ(test::runCommand(inDir + bench + " figures --help").exitCode, 0);

    // The smallest real run: the first figure's reduced sweep measured and plotted by the installed
    // tools/plot.py.
    const std::string first = catalog[0]["name"];
    const auto figure =
        test::runCommand(inDir + bench + " figures --reduced --no-progress --out figs --only " + first);
    ASSERT_EQ(figure.exitCode, 0) << figure.output;
    const fs::path dir = fs::path(mDir) / "figs" / first;
    for (const char* f : {"data.csv", "figure.png", "figure.svg", "summary.md"})
        EXPECT_TRUE(fs::exists(dir / f)) << f << " not written:\n" << figure.output;

    // The report page of that folder, written by the installed tools/report.py.
    const auto report = test::runCommand(inDir + bench + " report figs -o page.html");
    ASSERT_EQ(report.exitCode, 0) << report.output;
    // The figure's rows are a table of the page, captioned with their file.
    const std::string caption = "<caption>figs/" + first + "/data.csv</caption>";
    EXPECT_NE(test::readFile((fs::path(mDir) / "page.html").string()).find(caption), std::string::npos)
        << report.output;
}

TEST_F(InstallCliTest, FiguresWithoutThePlotLibrariesSaysWhatToInstallBeforeMeasuring) {
    // The plots are optional at run time (scripts/install-deps.sh's plot group): without an interpreter,
    // or with one that cannot import matplotlib (python3 -S: no site packages), bench figures stops
    // with exit 3 and the packages to install, before any figure is measured.
    const fs::path wrapper = fs::path(mDir) / "python3-no-site";
    test::writeFile(wrapper.string(), "#!/bin/sh\nexec /usr/bin/python3 -S \"$@\"\n");
    fs::permissions(wrapper, fs::perms::owner_all);
    for (const fs::path& interpreter : {fs::path(mDir) / "no-such-python3", wrapper}) {
        const auto run = test::runCommand(
            "cd " + shellQuoted(mDir) + " && SHADOWBENCH_PYTHON=" + shellQuoted(interpreter) + " " +
            shellQuoted(SB_BENCH_BINARY) + " figures --reduced --no-progress --out figs");
        EXPECT_EQ(run.exitCode, 3) << run.output;
        EXPECT_NE(run.output.find("apt-get install python3-matplotlib python3-pandas"), std::string::npos)
            << run.output;
        EXPECT_FALSE(fs::exists(fs::path(mDir) / "figs")) << "measured before checking:\n" << run.output;
    }
}

TEST_F(InstallCliTest, ReportsTheCommitItWasBuiltFromAfterTheTreeChanges) {
    const fs::path source = SB_SOURCE_DIR;
    if (!fs::exists(source / ".git"))
        GTEST_SKIP() << "the source tree is not a git checkout: commit is 'unknown'";
    const auto before = test::runCommand(shellQuoted(SB_BENCH_BINARY) + " --version");
    ASSERT_EQ(before.exitCode, 0) << before.output;
    const std::string built = versionField(before.output, "commit");
    // The build stamped HEAD of the tree it compiled (a "-dirty" suffix when that tree had edits).
    const auto head = test::runCommand("git -C " + shellQuoted(source) + " rev-parse --short=12 HEAD");
    ASSERT_EQ(head.exitCode, 0) << head.output;
    EXPECT_EQ(built.substr(0, 12), head.output.substr(0, 12)) << before.output;

    std::string describedAfterEdit;
    {
        // Edit a tracked file no test reads, then ask again: the tree is now dirty, the binary is not.
        RestoreFile changelog(source / "CHANGELOG.md");
        test::writeFile((source / "CHANGELOG.md").string(),
                        changelog.original() + "\nedited by InstallCliTest\n");
        describedAfterEdit =
            test::runCommand("git -C " + shellQuoted(source) + " describe --always --dirty --abbrev=12")
                .output;
        const auto after = test::runCommand(shellQuoted(SB_BENCH_BINARY) + " --version");
        EXPECT_EQ(versionField(after.output, "commit"), built) << after.output;
        // A row measured now records the same commit.
        const auto run =
            test::runCommand(shellQuoted(SB_BENCH_BINARY) +
                             " -t none --frames 1 --warmup 0 --size 32x32 --no-timer-check -q --format json");
        ASSERT_EQ(run.exitCode, 0) << run.output;
        const auto rows = nlohmann::json::parse(run.output.substr(run.output.find('{')));
        EXPECT_EQ(rows["rows"][0]["git_commit"], built);
    }
    EXPECT_NE(describedAfterEdit.find("-dirty"), std::string::npos)
        << "the edit did not make the tree dirty, so the check above proved nothing: " << describedAfterEdit;
}

TEST_F(InstallCliTest, VersionAgreesWithCitationAndChangelog) {
    const auto version = test::runCommand(shellQuoted(SB_BENCH_BINARY) + " --version");
    ASSERT_EQ(version.exitCode, 0);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(version.output, m, std::regex("^shadowbench ([0-9]+\\.[0-9]+\\.[0-9]+)")))
        << version.output;
    const std::string v = m[1].str();
    const std::string citation = test::readFile((fs::path(SB_SOURCE_DIR) / "CITATION.cff").string());
    EXPECT_NE(citation.find("\nversion: " + v + "\n"), std::string::npos)
        << "CITATION.cff's version is not " << v;
    const std::string changelog = test::readFile((fs::path(SB_SOURCE_DIR) / "CHANGELOG.md").string());
    EXPECT_NE(changelog.find(v), std::string::npos) << "CHANGELOG.md has no entry for " << v;
    EXPECT_NE(test::readFile((fs::path(SB_SOURCE_DIR) / "LICENSE").string()).find("Apache License"),
              std::string::npos);
    // --version takes nothing else: a stray argument is the user's mistake (exit 2).
    EXPECT_EQ(test::runCommand(shellQuoted(SB_BENCH_BINARY) + " --version extra").exitCode, 2);
}
