// bench(1) as `bench --man` writes it: it renders without a single groff or man warning, has one section
// per mode of `bench --help`, every option that each mode's --help lists, every registered technique and
// built-in scene, and the build folder's bench.1.gz (what `cmake --install` installs) is the same page.
#include <cctype>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "CliHelpOptions.h"
#include "TestSupport.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/SceneLoader.h"

namespace {

const std::string kBench = SB_BENCH_BINARY;

/// The modes `bench --help` lists ("  bench NAME ..." under "Modes:"); "" for the plain run.
std::vector<std::string> helpModes() {
    const auto help = sb::test::runCommand(kBench + " --help");
    std::vector<std::string> modes;
    std::istringstream lines(help.output.substr(help.output.find("Modes:")));
    std::string heading;
    std::getline(lines, heading);
    for (std::string l; std::getline(lines, l) && !l.empty();) {
        if (l.rfind("  bench ", 0) != 0) continue; // a summary's continuation
        std::string word = l.substr(8, l.find(' ', 8) - 8);
        modes.push_back(word[0] == '[' || word[0] == '-' ? "" : word);
    }
    return modes;
}

/// `name` as the roff source spells it: every '-' escaped.
std::string roff(const std::string& name) {
    std::string out;
    for (char c : name) out += c == '-' ? std::string("\\-") : std::string(1, c);
    return out;
}

class ManPageCli : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = sb::test::freshTestDir("man");
        mPage = mDir + "/bench.1";
        const auto r = sb::test::runCommand(kBench + " --man > " + mPage);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        mSource = sb::test::readFile(mPage);
    }
    std::string mDir, mPage, mSource;
};

} // namespace

TEST_F(ManPageCli, RendersWithoutWarnings) {
    // -ww: every warning groff has; the output itself is discarded, what remains is its complaints.
    const auto groff = sb::test::runCommand("groff -ww -man -Tutf8 " + mPage + " > /dev/null");
    EXPECT_EQ(groff.exitCode, 0) << groff.output;
    EXPECT_EQ(groff.output, "");
    if (sb::test::runCommand("command -v man").exitCode != 0) GTEST_SKIP() << "no man here";
    const auto man = sb::test::runCommand("MANWIDTH=80 man --warnings -l " + mPage + " > /dev/null");
    EXPECT_EQ(man.exitCode, 0) << man.output;
    EXPECT_EQ(man.output, "");
}

TEST_F(ManPageCli, EveryModeAndEveryOptionOfItsHelp) {
    const std::vector<std::string> modes = helpModes();
    ASSERT_GE(modes.size(), 10u); // the plain run, accuracy, sweep ... report
    for (const std::string& mode : modes) {
        SCOPED_TRACE("mode '" + mode + "'");
        std::string heading = ".SH OPTIONS\n";
        if (!mode.empty()) {
            heading = ".SH BENCH ";
            for (char c : mode) heading += char(std::toupper(static_cast<unsigned char>(c)));
            heading += "\n";
        }
        const size_t section = mSource.find(heading);
        ASSERT_NE(section, std::string::npos);
        const std::string body = mSource.substr(section, mSource.find("\n.SH ", section + 1) - section);
        const auto help = sb::test::runCommand(kBench + " " + mode + " --help");
        const std::set<std::string> options = sb::test::helpOptionNames(help.output);
        ASSERT_GE(options.size(), 3u) << help.output;
        for (const std::string& o : options)
            EXPECT_NE(body.find("\\fB" + roff(o) + "\\fR"), std::string::npos) << o << " missing";
    }
}

TEST_F(ManPageCli, TechniquesScenesExitStatusAndExamples) {
    for (const std::string& t : sb::TechniqueRegistry::names())
        EXPECT_NE(mSource.find(".TP\n\\fB" + roff(t) + "\\fR\n"), std::string::npos) << t;
    for (const std::string& s : sb::SceneLoader::listBuiltinScenes())
        EXPECT_NE(mSource.find(roff(s)), std::string::npos) << s;
    for (const char* section :
         {".SH NAME\n", ".SH SYNOPSIS\n", ".SH DESCRIPTION\n", ".SH TECHNIQUES\n", ".SH SCENES\n",
          ".SH EXIT STATUS\n", ".SH EXAMPLES\n", ".SH FILES\n", ".SH SEE ALSO\n"})
        EXPECT_NE(mSource.find(section), std::string::npos) << section;
    // The exit codes as README's "Exit codes" promise them.
    for (const char* code : {"0 ok", "1 run failed", "2 the input is wrong", "3 this machine"})
        EXPECT_NE(mSource.find(code), std::string::npos) << code;
}

TEST_F(ManPageCli, TheBuildsCompressedPageIsThisPage) {
    const std::string gz = (std::filesystem::path(kBench).parent_path() / "bench.1.gz").string();
    if (!std::filesystem::exists(gz)) GTEST_SKIP() << "no gzip at configure time: " << gz << " not built";
    const auto r = sb::test::runCommand("gzip -dc " + gz + " | cmp - " + mPage);
    EXPECT_EQ(r.exitCode, 0) << r.output;
}
