#pragma once
// The second driver of the tests (core/DriverTable.h, docs/USAGE.md "Drivers"): Mesa 25.0.7, the one
// whose lavapipe offers ray queries. Whether it is installed where the program looks for it, and the
// skip a test that needs it takes: where it is missing the test skips, naming the command that installs
// it, unless SHADOWBENCH_REQUIRE_DRIVERS=1 (CI: scripts/test.sh installs the driver and sets it), where
// it fails instead. One home for what tests/DriverCliTest.cpp and the ray-traced tests ask.
#include <cstdlib>
#include <filesystem>
#include <string>

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

/// CI sets SHADOWBENCH_REQUIRE_DRIVERS=1: there a missing driver fails instead of skipping.
inline bool driversRequired() {
    const char* v = std::getenv("SHADOWBENCH_REQUIRE_DRIVERS");
    return v && std::string(v) == "1";
}

} // namespace sb::test

/// At the top of a test that needs the second driver: skips (or, under SHADOWBENCH_REQUIRE_DRIVERS=1,
/// fails) where it is not installed.
#define REQUIRE_SECOND_DRIVER()                                                                              \
    if (!sb::test::secondDriverInstalled()) {                                                                \
        if (sb::test::driversRequired())                                                                     \
            FAIL() << sb::test::kSecondDriver                                                                \
                   << " is not installed; install it with: " << sb::test::kSecondDriverInstall;              \
        GTEST_SKIP() << sb::test::kSecondDriver << " is not installed in " << sb::test::driversDirectory()   \
                     << "; install it with: " << sb::test::kSecondDriverInstall;                             \
    }
