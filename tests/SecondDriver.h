#pragma once
// The second driver of the driver table (core/DriverTable.h: mesa-25.0.7, what `bench --driver mesa-25.0.7`
// runs on) as the CLI tests that need it see it: whether it is installed, and the skip (or, where CI
// requires the drivers, the failure) of a test that needs it and does not find it.
//
// A test case that must run on another driver than the one its test process runs on (core/DriverTable.h),
// such as a hard-case row of a technique whose Vulkan form needs a capability only Mesa 25.0.7's lavapipe
// offers (tests/hard/HardCases.h, HardCase::driver). The loaders read their search paths when a process
// starts, so a process cannot change its driver: the case runs again in a child process of the same test
// binary, filtered to the same test, with that driver's environment (DriverTable::childEnvironment), and
// the parent reports what the child found. Inside the child the case runs in process as any other.
//
//   if (c.driver && !test::runsOnDriver(c.driver)) return test::runThisTestOnDriver(c.driver, c.name);
//
// A driver that is not installed skips the case naming the install command, as MatrixOnSecondDriver
// does (tests/CMakeLists.txt), unless SHADOWBENCH_REQUIRE_DRIVERS=1 (scripts/test.sh sets it in CI),
// where it fails.
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bench/lib/sweep/ChildProcess.h"
#include "core/DriverTable.h"
#include "core/Error.h"

namespace sb::test {

inline constexpr const char* kSecondDriver = "mesa-25.0.7";
inline constexpr const char* kSecondDriverInstall = "bash scripts/install-deps.sh driver";

/// Where named drivers live, as the program reads it.
inline std::filesystem::path driversDirectory() {
    const char* dir = std::getenv("SHADOWBENCH_DRIVERS_DIR");
    return dir && *dir ? dir : "/opt/shadowbench/drivers";
}

inline bool secondDriverInstalled() {
    return std::filesystem::exists(driversDirectory() / kSecondDriver / "etc/lvp_icd.json");
}

/// CI (scripts/test.sh installs the driver) sets SHADOWBENCH_REQUIRE_DRIVERS=1: there a missing driver
/// fails instead of skipping.
inline bool driversRequired() {
    const char* v = std::getenv("SHADOWBENCH_REQUIRE_DRIVERS");
    return v && std::string(v) == "1";
}

/// Whether this process runs on `driver` (a name of the driver table).
inline bool runsOnDriver(const std::string& driver) {
    return DriverTable::current() == driver;
}

/// The lines of a child's gtest output from its test's start to its verdict: the assertions that failed
/// and what the test printed, without gtest's banner.
inline std::string childTestOutput(const std::vector<std::string>& lines) {
    std::string out;
    bool inside = false;
    for (const std::string& line : lines) {
        inside |= line.rfind("[ RUN      ]", 0) == 0;
        if (inside) out += "  | " + line + "\n";
        if (line.rfind("[       OK ]", 0) == 0 || line.rfind("[  FAILED  ]", 0) == 0) break;
    }
    return out;
}

/// Runs the current test again in a child of this test binary on `driver` and holds it to the child's
/// verdict: a failure names `caseName`, the driver, how the child ended and what its test printed. The
/// child must have run exactly this one test and passed it (a filter that matched nothing exits 0 too).
inline void runThisTestOnDriver(const std::string& driver, const std::string& caseName) {
    Driver resolved;
    try {
        resolved = DriverTable::resolve(driver);
    } catch (const Error& e) {
        if (driversRequired()) FAIL() << caseName << " needs the driver " << driver << ": " << e.what();
        GTEST_SKIP() << caseName << " needs the driver " << driver << ": " << e.what();
    }
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string test = std::string(info->test_suite_name()) + "." + info->name();
    std::vector<std::string> lines;
    const ChildExit exit = ChildProcess::run(
        {ChildProcess::selfExecutable(), "--gtest_filter=" + test, "--gtest_color=no"},
        DriverTable::childEnvironment(resolved), [&](const std::string& line) { lines.push_back(line); });
    const std::string output = childTestOutput(lines);
    bool ranAndPassed = false;
    for (const std::string& line : lines) ranAndPassed |= line.rfind("[       OK ] " + test, 0) == 0;
    if (exit.ok() && ranAndPassed) // what it measured there; a failure below carries the same lines
        std::cout << caseName << " ran on the driver " << driver << " in a child process:\n" << output;
    EXPECT_TRUE(exit.ok() && ranAndPassed)
        << caseName << " failed on the driver " << driver << " (child process " << test << ": "
        << exit.describe() << (ranAndPassed ? "" : ", the test did not pass there") << "):\n"
        << output << (exit.stderrTail.empty() ? "" : "  its stderr ends: " + exit.stderrTail);
}

} // namespace sb::test

/// At the top of a test that needs the second driver: skips it, naming the install command, where the
/// driver is not installed (fails where SHADOWBENCH_REQUIRE_DRIVERS=1).
#define REQUIRE_SECOND_DRIVER()                                                                              \
    if (!::sb::test::secondDriverInstalled()) {                                                              \
        if (::sb::test::driversRequired())                                                                   \
            FAIL() << ::sb::test::kSecondDriver                                                              \
                   << " is not installed; install it with: " << ::sb::test::kSecondDriverInstall;            \
        GTEST_SKIP() << ::sb::test::kSecondDriver << " is not installed in "                                 \
                     << ::sb::test::driversDirectory()                                                       \
                     << "; install it with: " << ::sb::test::kSecondDriverInstall;                           \
    }
