// The driver axis through the bench binary (core/DriverTable.h, docs/USAGE.md "Drivers"): which driver
// a row says it ran on and the version that driver reports, on GL and on Vulkan; what a wrong name, a
// named driver that is not installed and a prefix whose libraries cannot load each say (one line, the
// exit code of the README's "Exit codes"); that a command which renders nothing refuses --driver; and
// that a sweep's workers and golden's cells run on the driver the command was given.
//
// The independent answers: the system driver's version is the one dpkg installed (dpkg-query, the Debian
// version's upstream part); the second driver's is its name's. The runs are 32x32, one frame, no
// warm-up: only the recorded strings are asserted. Cases that need the second driver skip, naming the
// command that installs it, where it is not installed.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "SecondDriver.h"
#include "TestSupport.h"

namespace fs = std::filesystem;
using sb::test::runCommand;

namespace {

constexpr const char* kSecond = sb::test::kSecondDriver;
const std::string kTiny = " -t none --scene sphere_plane --size 32x32 --frames 1 --warmup 0 --no-timer-check";

std::string bench() {
    return SB_BENCH_BINARY;
}

using sb::test::driversDirectory;

/// The upstream version dpkg installed `package` at ("22.3.6" of "22.3.6-1+deb12u2"), "" without dpkg.
std::string debianUpstreamVersion(const std::string& package) {
    const auto r = runCommand("dpkg-query -W -f='${Version}' " + package);
    if (r.exitCode != 0) return "";
    std::string v = r.output.substr(r.output.find(':') == std::string::npos ? 0 : r.output.find(':') + 1);
    return v.substr(0, v.find('-'));
}

/// The one row a tiny run writes, on `driver` ("" for none given) and `api`.
std::map<std::string, std::string> tinyRow(const std::string& driver, const std::string& api) {
    const std::string dir = sb::test::freshTestDir("driver-cli");
    const std::string csv = dir + "/" + api + ".csv";
    const auto r = runCommand(bench() + (driver.empty() ? "" : " --driver " + driver) + " --api " + api +
                              kTiny + " --csv " + csv);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const auto rows = sb::test::csvRowMaps(csv);
    EXPECT_EQ(rows.size(), 1u) << r.output;
    return rows.empty() ? std::map<std::string, std::string>{} : rows[0];
}

/// The lines of `text` that are not empty.
int lineCount(const std::string& text) {
    int n = 0;
    size_t at = 0;
    while (at < text.size()) {
        const size_t end = std::min(text.find('\n', at), text.size());
        n += end > at;
        at = end + 1;
    }
    return n;
}

/// A prefix laid out like a Mesa install whose GL (EGL vendor) and Vulkan (ICD) libraries are empty
/// files: found by the table, refused by the loader ("file too short").
fs::path unloadablePrefix() {
    const fs::path p = sb::test::freshTestDir("driver-cli-broken"), lib = p / "usr/lib/x86_64-linux-gnu";
    fs::create_directories(lib);
    fs::create_directories(p / "etc");
    sb::test::writeFile((lib / "libEGL_mesa.so.0").string(), "");
    sb::test::writeFile((lib / "libvulkan_lvp.so").string(), "");
    sb::test::writeFile((p / "etc/egl_vendor.json").string(),
                        R"({"file_format_version":"1.0.0","ICD":{"library_path":")" +
                            (lib / "libEGL_mesa.so.0").string() + R"("}})");
    sb::test::writeFile((p / "etc/lvp_icd.json").string(),
                        R"({"file_format_version":"1.0.0","ICD":{"api_version":"1.3.0","library_path":")" +
                            (lib / "libvulkan_lvp.so").string() + R"("}})");
    return p;
}

} // namespace

TEST(DriverCli, SystemRowsNameTheSystemDriverAndItsInstalledVersion) {
    for (const auto& [api, package] :
         {std::pair{"gl", "libgl1-mesa-dri"}, {"vulkan", "mesa-vulkan-drivers"}}) {
        const auto row = tinyRow("", api);
        EXPECT_EQ(row.at("driver"), "system") << api;
        const std::string installed = debianUpstreamVersion(package);
        if (installed.empty()) continue; // not a Debian system: the name is all there is to check
        EXPECT_EQ(row.at("driver_version").rfind("Mesa " + installed, 0), 0u)
            << api << ": driver_version '" << row.at("driver_version") << "', dpkg says " << installed;
    }
}

TEST(DriverCli, SecondDriverRowsNameItAndItsVersionOnBothApis) {
    REQUIRE_SECOND_DRIVER();
    for (const char* api : {"gl", "vulkan"}) {
        const auto row = tinyRow(kSecond, api);
        EXPECT_EQ(row.at("driver"), kSecond) << api;
        EXPECT_EQ(row.at("driver_version").rfind("Mesa 25.0.7", 0), 0u)
            << api << ": " << row.at("driver_version");
    }
    // The system driver's run after it is the system again: the two versions differ.
    EXPECT_NE(tinyRow("system", "vulkan").at("driver_version"),
              tinyRow(kSecond, "vulkan").at("driver_version"));
}

TEST(DriverCli, SweepWorkersAndGoldenCellsRunOnTheDriverGiven) {
    REQUIRE_SECOND_DRIVER();
    const std::string dir = sb::test::freshTestDir("driver-cli-sweep");
    // Before the subcommand: the driver is a choice for the whole program.
    auto r =
        runCommand(bench() + " --driver " + kSecond + " sweep" + kTiny.substr(0, kTiny.find(" --no-timer")) +
                   " --no-progress --csv " + dir + "/s.csv");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = sb::test::csvRowMaps(dir + "/s.csv");
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].at("driver"), kSecond);
    EXPECT_EQ(rows[0].at("driver_version").rfind("Mesa 25.0.7", 0), 0u) << rows[0].at("driver_version");
    r = runCommand(bench() + " golden --check --technique none --scene sphere_plane --driver " + kSecond);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("on the driver mesa-25.0.7"), std::string::npos) << r.output;
}

TEST(DriverCli, UnknownDriverIsBadInputInOneLine) {
    const auto r = runCommand(bench() + " --driver mesa-9" + kTiny);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_EQ(lineCount(r.output), 1) << r.output;
    EXPECT_NE(r.output.find("unknown driver"), std::string::npos) << r.output;
}

TEST(DriverCli, NamedDriverNotInstalledSaysHowToInstallIt) {
    const std::string empty = sb::test::freshTestDir("driver-cli-empty");
    const auto r =
        runCommand("SHADOWBENCH_DRIVERS_DIR=" + empty + " " + bench() + " --driver " + kSecond + kTiny);
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_EQ(lineCount(r.output), 1) << r.output;
    EXPECT_NE(r.output.find(sb::test::kSecondDriverInstall), std::string::npos) << r.output;
}

TEST(DriverCli, UnloadablePrefixIsRefusedInOneLineOnEachApi) {
    const fs::path prefix = unloadablePrefix();
    for (const auto& [api, library] : {std::pair{"gl", "libEGL_mesa.so.0"}, {"vulkan", "libvulkan_lvp.so"}}) {
        const auto r = runCommand(bench() + " --driver " + prefix.string() + " --api " + api + kTiny);
        EXPECT_EQ(r.exitCode, 3) << api << ": " << r.output;
        EXPECT_EQ(lineCount(r.output), 1) << api << ": " << r.output;
        EXPECT_NE(r.output.find(prefix.string()), std::string::npos) << r.output; // names the driver
        EXPECT_NE(r.output.find(library), std::string::npos) << r.output;         // and what failed
    }
}

TEST(DriverCli, PrefixWhoseLibrariesBreakTheProgramsStartIsRefusedInOneLine) {
    // A library the program links (OSMesa) truncated in the prefix: the dynamic loader refuses to start.
    const fs::path prefix = unloadablePrefix();
    sb::test::writeFile((prefix / "usr/lib/x86_64-linux-gnu/libOSMesa.so.8").string(), "");
    const auto r = runCommand(bench() + " --driver " + prefix.string() + kTiny);
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_EQ(lineCount(r.output), 1) << r.output;
    EXPECT_NE(r.output.find("libOSMesa.so.8"), std::string::npos) << r.output;
}

TEST(DriverCli, CommandsThatRenderListItAndTheOthersRefuseIt) {
    for (const char* sub :
         {"", " accuracy", " sweep", " bottleneck", " figures", " golden", " ci", " explain"}) {
        const auto r = runCommand(bench() + sub + " --help");
        EXPECT_EQ(r.exitCode, 0) << sub;
        EXPECT_NE(r.output.find("--driver"), std::string::npos) << "bench" << sub << " --help";
    }
    for (const char* args : {" compare a.csv b.csv --driver system", " --driver system merge -o m.csv a.csv",
                             " export a.csv --driver system", " report . --driver system"}) {
        const auto r = runCommand(bench() + args);
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.output;
        EXPECT_NE(r.output.find("--driver"), std::string::npos) << args << ": " << r.output;
    }
}

TEST(DriverCli, CiSidesRunOnTheDriversGiven) {
    REQUIRE_SECOND_DRIVER();
    const std::string dir = sb::test::freshTestDir("driver-cli-ci");
    // One Vulkan configuration of the committed suite: the rows of each side, not the verdict (the
    // judging of a driver A/B is bench/lib/gate's), are what this asserts.
    const auto r = runCommand(bench() + " ci --base-driver system --head-driver " + kSecond +
                              " --layers A --configs none_vulkan --out " + dir);
    const auto head = sb::test::csvRowMaps(dir + "/work.csv"),
               base = sb::test::csvRowMaps(dir + "/work_base.csv");
    ASSERT_EQ(head.size(), 1u) << r.output;
    ASSERT_EQ(base.size(), 1u) << r.output;
    EXPECT_EQ(head[0].at("driver"), kSecond);
    EXPECT_EQ(head[0].at("driver_version").rfind("Mesa 25.0.7", 0), 0u) << head[0].at("driver_version");
    EXPECT_EQ(base[0].at("driver"), "system");
}

TEST(DriverCli, CiOnADriverWithoutItsBaselineIsBadInputNamingTheFolder) {
    REQUIRE_SECOND_DRIVER();
    // A suite beside which no baseline was committed: the system's and the second driver's are missing.
    const std::string dir = sb::test::freshTestDir("driver-cli-ci-baseline");
    fs::copy_file(std::string(SB_SOURCE_DIR) + "/results/ci/suite.json", dir + "/suite.json");
    const auto r = runCommand(bench() + " --driver " + kSecond + " ci --quick --suite " + dir +
                              "/suite.json --out " + dir + "/out");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_EQ(lineCount(r.output), 1) << r.output;
    EXPECT_NE(r.output.find(dir + "/baseline/mesa-25.0.7/work.csv"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("bench ci --update --driver mesa-25.0.7"), std::string::npos) << r.output;
}
