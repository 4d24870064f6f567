#pragma once
// The second driver of the driver table (core/DriverTable.h: mesa-25.0.7, what `bench --driver mesa-25.0.7`
// runs on) as the CLI tests that need it see it: whether it is installed, and the skip (or, where CI
// requires the drivers, the failure) of a test that needs it and does not find it.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

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
