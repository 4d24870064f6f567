// scripts/raytraced-study.sh, the measurements of results/raytraced/README.md: its refusals (exit 2 for
// wrong input, 3 for a missing bench, before anything is measured or written) and which raytraced modes
// it measures, read from `bench --list`, against a stand-in bench (a shell script that prints a listing
// and records its arguments), so that no frame is rendered and no summary is made (--no-summary: python3
// is not started). About 1 s in all.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "TestSupport.h"

using namespace sb;
using test::runCommand;

namespace {

std::string script() {
    return std::string(SB_SOURCE_DIR) + "/scripts/raytraced-study.sh";
}

std::string readAll(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// A build folder whose bench answers --list with `listing` and records every other call's arguments,
/// one line each, in <dir>/calls.txt.
std::string fakeBuild(const std::string& dir, const std::string& listing) {
    const std::string build = dir + "/build";
    std::filesystem::create_directories(build);
    test::writeFile(dir + "/listing.txt", listing);
    test::writeFile(build + "/bench", "#!/bin/sh\n"
                                      "case \" $* \" in *\" --list \"*) cat '" +
                                          dir +
                                          "/listing.txt'; exit 0 ;; esac\n"
                                          "echo \"$*\" >> '" +
                                          dir + "/calls.txt'\n");
    std::filesystem::permissions(build + "/bench", std::filesystem::perms::owner_all);
    return build;
}

} // namespace

TEST(RaytracedStudy, HelpNamesTheCommittedResultsFolder) {
    auto r = runCommand("bash " + script() + " --help");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Usage: bash scripts/raytraced-study.sh"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--out results/raytraced"), std::string::npos) << r.output;
}

// One row per wrong input: the option named, exit 2, nothing run (the bench named does not exist, so a
// case that got past the checks would exit 3 instead).
TEST(RaytracedStudy, WrongInputIsExit2NamingTheOption) {
    const struct {
        const char* args;
        const char* named;
    } cases[] = {
        {"--rounds 0", "--rounds: expected a positive integer, got '0'"},
        {"--size 512", "--size: expected WxH (512x512), got '512'"},
        {"--sections accuracy,speed", "--sections: unknown section 'speed'"},
        {"--out", "--out: expected a value"},
        {"--colour red", "unknown option '--colour'"},
    };
    for (const auto& c : cases) {
        auto r = runCommand("bash " + script() + " --build /nonexistent " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.named), std::string::npos) << c.args << "\n" << r.output;
    }
    auto noBench = runCommand("bash " + script() + " --build /nonexistent");
    EXPECT_EQ(noBench.exitCode, 3) << noBench.output;
    EXPECT_NE(noBench.output.find("/nonexistent/bench is missing"), std::string::npos) << noBench.output;
}

// The soft rays the build's range allows and guided are measured; a count outside the range is skipped
// and said so. The listing is the shape bench --list prints (techniques/Property.h's columns).
TEST(RaytracedStudy, MeasuresTheModesTheListingOffers) {
    const std::string dir = test::freshTestDir("raytraced-study");
    const std::string build = fakeBuild(dir, "raytraced  ray-traced shadows\n"
                                             "  passes:   structures, lighting\n"
                                             "  mode  enum  default hard  {hard, soft, guided}  modes\n"
                                             "  rays  int   default 4     [1, 16]             rays\n"
                                             "\n"
                                             "reference  exact visibility\n"
                                             "  rays  int   default 9     [1, 4096]   not raytraced's\n");
    auto r = runCommand("bash " + script() + " --quick --no-summary --sections soft --build " + build +
                        " --out " + dir + "/out");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("skipped raytraced:mode=soft:rays=64 (rays range [1, 16])"), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("skipped raytraced:mode=guided"), std::string::npos) << r.output;
    const std::string calls = readAll(dir + "/calls.txt");
    EXPECT_NE(calls.find("-t raytraced:mode=hard -t raytraced:mode=soft:rays=1 -t raytraced:mode=soft:rays=4 "
                         "-t raytraced:mode=soft:rays=16 -t raytraced:mode=guided"),
              std::string::npos)
        << calls;
    EXPECT_EQ(calls.find("rays=64"), std::string::npos) << calls;
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/machine.txt"));
    EXPECT_FALSE(std::filesystem::exists(dir + "/out/tables.md"));
}

// A rerun of some sections into a folder keeps the earlier run's machine.txt and appends its own block
// (the load of the sections it left as they were stays beside their CSVs); a first run starts the file.
TEST(RaytracedStudy, SomeSectionsAppendToMachineTxt) {
    const std::string dir = test::freshTestDir("raytraced-study-machine");
    const std::string build = fakeBuild(dir, "raytraced  ray-traced shadows\n"
                                             "  mode  enum  default hard  {hard}  modes\n");
    const std::string run =
        "bash " + script() + " --quick --no-summary --build " + build + " --out " + dir + "/out --sections ";
    auto first = runCommand(run + "build");
    ASSERT_EQ(first.exitCode, 0) << first.output;
    auto second = runCommand(run + "motion");
    ASSERT_EQ(second.exitCode, 0) << second.output;
    const std::string machine = readAll(dir + "/out/machine.txt");
    const size_t build_block = machine.find("sections: build\n");
    const size_t motion_block = machine.find("\nsections: motion\n");
    ASSERT_EQ(build_block, 0u) << machine;
    ASSERT_NE(motion_block, std::string::npos) << machine;
    EXPECT_NE(machine.find("build ends: load average"), std::string::npos) << machine;
    EXPECT_LT(machine.find("build ends: load average"), motion_block) << machine;
    EXPECT_GT(machine.find("motion ends: load average"), motion_block) << machine;
}
