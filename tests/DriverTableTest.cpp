// The driver table (core/DriverTable.h) on prefixes laid out by hand in a temporary folder: which
// variables each layout yields, what each wrong name or path says and its exit code, and that activating
// a driver and then the system one gives back the environment as it was. The libraries are empty files:
// the table only looks for them, it never loads them (the CLI tests run real drivers).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "core/DriverTable.h"
#include "core/Error.h"

namespace fs = std::filesystem;
using sb::DriverTable;

namespace {

void touch(const fs::path& p) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << "x";
}

class DriverTableTest : public ::testing::Test {
protected:
    void SetUp() override {
        root = fs::temp_directory_path() / ("sb-driver-table-" + std::to_string(::getpid()));
        fs::remove_all(root);
        for (const char* v : {"SHADOWBENCH_DRIVER", "SHADOWBENCH_DRIVER_UNSET", "LIBGL_DRIVERS_PATH",
                              "__EGL_VENDOR_LIBRARY_FILENAMES", "VK_ICD_FILENAMES", "VK_DRIVER_FILES",
                              "GBM_BACKENDS_PATH", "SHADOWBENCH_DRIVER_SAVED_LD_LIBRARY_PATH"})
            ::unsetenv(v);
        ::setenv("LD_LIBRARY_PATH", "/before", 1);
        ::setenv("SHADOWBENCH_DRIVERS_DIR", root.c_str(), 1);
    }
    void TearDown() override {
        fs::remove_all(root);
        ::unsetenv("SHADOWBENCH_DRIVERS_DIR");
    }
    /// A prefix as `dpkg -x` of Debian's Mesa packages and scripts/install-deps.sh leave it.
    fs::path debianPrefix(const std::string& name) {
        const fs::path p = root / name, lib = p / "usr/lib/x86_64-linux-gnu";
        touch(lib / "libEGL_mesa.so.0");
        touch(lib / "libvulkan_lvp.so");
        touch(lib / "dri/swrast_dri.so");
        touch(lib / "gbm/dri_gbm.so");
        touch(p / "etc/egl_vendor.json");
        touch(p / "etc/lvp_icd.json");
        return p;
    }
    static std::map<std::string, std::string>
    asMap(const std::vector<std::pair<std::string, std::string>>& e) {
        return {e.begin(), e.end()};
    }
    fs::path root;
};

sb::ExitCode codeOf(const std::string& nameOrPath) {
    try {
        DriverTable::resolve(nameOrPath);
    } catch (const sb::Error& e) {
        return e.code();
    }
    return sb::ExitCode::Ok;
}

std::string messageOf(const std::string& nameOrPath) {
    try {
        DriverTable::resolve(nameOrPath);
    } catch (const sb::Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_F(DriverTableTest, TheSystemDriverSetsNothing) {
    const sb::Driver d = DriverTable::resolve("system");
    EXPECT_EQ(d.name, "system");
    EXPECT_TRUE(d.prefix.empty());
    EXPECT_TRUE(d.environment.empty());
    EXPECT_EQ(DriverTable::current(), "system");
    EXPECT_TRUE(DriverTable::isActive(d));
}

TEST_F(DriverTableTest, ANamedDriverPointsEveryLoaderAtItsPrefix) {
    const fs::path p = debianPrefix("mesa-25.0.7");
    const sb::Driver d = DriverTable::resolve("mesa-25.0.7");
    EXPECT_EQ(d.name, "mesa-25.0.7");
    const auto e = asMap(d.environment);
    const std::string lib = (p / "usr/lib/x86_64-linux-gnu").string();
    // The prefix's libraries first, then what the user had.
    EXPECT_EQ(e.at("LD_LIBRARY_PATH"), lib + ":/before");
    EXPECT_EQ(e.at("LIBGL_DRIVERS_PATH"), lib + "/dri");
    EXPECT_EQ(e.at("GBM_BACKENDS_PATH"), lib + "/gbm");
    EXPECT_EQ(e.at("__EGL_VENDOR_LIBRARY_FILENAMES"), (p / "etc/egl_vendor.json").string());
    EXPECT_EQ(e.at("VK_ICD_FILENAMES"), (p / "etc/lvp_icd.json").string());
    EXPECT_EQ(e.at("VK_DRIVER_FILES"), (p / "etc/lvp_icd.json").string());
}

TEST_F(DriverTableTest, AMesonPrefixIsFoundByItsOwnVendorAndIcdFiles) {
    const fs::path p = root / "my-mesa", lib = p / "lib/x86_64-linux-gnu";
    touch(lib / "libEGL_mesa.so.0");
    touch(lib / "libvulkan_lvp.so");
    touch(p / "share/glvnd/egl_vendor.d/50_mesa.json");
    touch(p / "share/vulkan/icd.d/lvp_icd.x86_64.json");
    const sb::Driver d = DriverTable::resolve(p.string());
    EXPECT_EQ(d.name, fs::weakly_canonical(p).string());
    const auto e = asMap(d.environment);
    EXPECT_EQ(e.at("__EGL_VENDOR_LIBRARY_FILENAMES"), (p / "share/glvnd/egl_vendor.d/50_mesa.json").string());
    EXPECT_EQ(e.at("VK_ICD_FILENAMES"), (p / "share/vulkan/icd.d/lvp_icd.x86_64.json").string());
    EXPECT_EQ(e.count("LIBGL_DRIVERS_PATH"), 0u); // no dri/ folder in this prefix
}

TEST_F(DriverTableTest, WrongNamesAndPathsAreBadInputAndMissingDriversAreUnsupported) {
    EXPECT_EQ(codeOf("mesa-25.0.8"), sb::ExitCode::BadInput);
    EXPECT_NE(messageOf("mesa-25.0.8").find("mesa-25.0.7"), std::string::npos); // did you mean
    EXPECT_EQ(codeOf((root / "nowhere").string()), sb::ExitCode::BadInput);
    // Named but not installed: exit 3, saying how to install it.
    EXPECT_EQ(codeOf("mesa-25.0.7"), sb::ExitCode::Unsupported);
    EXPECT_NE(messageOf("mesa-25.0.7").find("scripts/install-deps.sh driver"), std::string::npos);
    // A folder with no Mesa in it.
    fs::create_directories(root / "empty");
    EXPECT_EQ(codeOf((root / "empty").string()), sb::ExitCode::Unsupported);
}

TEST_F(DriverTableTest, TheOptionIsFoundBeforeTheSeparatorOnly) {
    auto requested = [](std::vector<std::string> args) {
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        return DriverTable::requested(int(argv.size()), argv.data());
    };
    EXPECT_EQ(requested({"bench", "-t", "none"}), "");
    EXPECT_EQ(requested({"bench", "golden", "--driver", "mesa-25.0.7", "--check"}), "mesa-25.0.7");
    EXPECT_EQ(requested({"bench", "--driver=/opt/x"}), "/opt/x");
    EXPECT_EQ(requested({"bench", "bisect", "a", "b", "--", "--driver", "x"}), "");
    EXPECT_THROW(requested({"bench", "--driver"}), sb::Error);
    EXPECT_THROW(requested({"bench", "--driver="}), sb::Error);
}

TEST_F(DriverTableTest, ActivatingADriverThenTheSystemRestoresTheEnvironment) {
    debianPrefix("mesa-25.0.7");
    const sb::Driver d = DriverTable::resolve("mesa-25.0.7");
    DriverTable::activate(d);
    EXPECT_EQ(DriverTable::current(), "mesa-25.0.7");
    EXPECT_TRUE(DriverTable::isActive(d));
    EXPECT_NE(std::getenv("VK_ICD_FILENAMES"), nullptr);
    DriverTable::activate(DriverTable::resolve("system"));
    EXPECT_EQ(DriverTable::current(), "system");
    EXPECT_STREQ(std::getenv("LD_LIBRARY_PATH"), "/before");
    for (const char* v : {"VK_ICD_FILENAMES", "__EGL_VENDOR_LIBRARY_FILENAMES", "LIBGL_DRIVERS_PATH"})
        EXPECT_EQ(std::getenv(v), nullptr) << v;
}

TEST_F(DriverTableTest, VariablesSetByHandAreNotCalledTheSystemDriver) {
    ::setenv("VK_ICD_FILENAMES", "/somewhere/icd.json", 1);
    EXPECT_EQ(DriverTable::current(), "environment");
    // A comparison of drivers starts from the system's libraries.
    debianPrefix("mesa-25.0.7");
    EXPECT_THROW(DriverTable::childEnvironment(DriverTable::resolve("mesa-25.0.7")), sb::Error);
    ::unsetenv("VK_ICD_FILENAMES");
    const auto child = asMap(DriverTable::childEnvironment(DriverTable::resolve("mesa-25.0.7")));
    EXPECT_EQ(child.at("SHADOWBENCH_DRIVER"), "mesa-25.0.7");
}
