// VulkanContext on Mesa's lavapipe: the default device, the device listing, the exit codes of a bad index
// and of a machine without a Vulkan driver, and that the validation layer's check can fail.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "VkTestSupport.h"
#include "core/Error.h"
#include "vk/VulkanContext.h"

namespace sb {
namespace {

using test::VulkanTest;

class VulkanContextVkTest : public VulkanTest {};

TEST_F(VulkanContextVkTest, DefaultDeviceIsLavapipe) {
    const VulkanDeviceInfo& info = context().info();
    EXPECT_NE(info.name.find("llvmpipe"), std::string::npos) << info.name;
    EXPECT_EQ(info.type, "cpu");
    EXPECT_NE(info.driver.find("llvmpipe"), std::string::npos) << info.driver;
    EXPECT_NE(info.driver.find("Mesa"), std::string::npos) << info.driver;
    EXPECT_EQ(info.apiVersion.rfind("1.", 0), 0u) << info.apiVersion;
    EXPECT_TRUE(context().validationEnabled());
    EXPECT_TRUE(context().depthClamp());
    EXPECT_NE(context().device(), VK_NULL_HANDLE);
    EXPECT_NE(context().queue(), VK_NULL_HANDLE);
    EXPECT_NE(context().commandPool(), VK_NULL_HANDLE);
    const VkFormat depth = context().depthStencilFormat();
    EXPECT_TRUE(depth == VK_FORMAT_D24_UNORM_S8_UINT || depth == VK_FORMAT_D32_SFLOAT_S8_UINT) << depth;
}

TEST_F(VulkanContextVkTest, ListDevicesSeesTheDefault) {
    std::vector<VulkanDeviceInfo> devices = VulkanContext::listDevices();
    ASSERT_FALSE(devices.empty());
    bool found = false;
    for (size_t i = 0; i < devices.size(); ++i) {
        EXPECT_EQ(devices[i].index, int(i));
        found |= devices[i].name == context().info().name && devices[i].index == context().info().index;
    }
    EXPECT_TRUE(found) << context().info().name;
}

TEST_F(VulkanContextVkTest, ExplicitIndexPicksThatDevice) {
    VulkanOptions options;
    options.device = context().info().index;
    VulkanContext other(options);
    EXPECT_EQ(other.info().name, context().info().name);
    EXPECT_FALSE(other.validationEnabled());
    EXPECT_TRUE(other.validationMessages().empty());
}

TEST_F(VulkanContextVkTest, IndexOutOfRangeIsBadInputListingTheDevices) {
    const size_t count = VulkanContext::listDevices().size();
    VulkanOptions options;
    options.device = int(count); // one past the last
    try {
        VulkanContext bad(options);
        FAIL() << "device " << count << " accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput) << e.what();
        const std::string message = e.what();
        EXPECT_EQ(
            message.rfind("vulkan: --vk-device " + std::to_string(count) + ": out of range (devices: 0 ", 0),
            0u)
            << message;
        EXPECT_NE(message.find("llvmpipe"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

/// In a fresh process (the loader reads VK_ICD_FILENAMES when it builds its driver list): creates a
/// context and exits with the sb::Error's exit code, its message on stderr.
[[noreturn]] void createWithoutDriver(bool validation) {
    setenv("VK_ICD_FILENAMES", "/nonexistent.json", 1);
    setenv("VK_DRIVER_FILES", "/nonexistent.json", 1);
    try {
        VulkanOptions options;
        options.validation = validation;
        VulkanContext context(options);
    } catch (const Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        std::_Exit(static_cast<int>(e.code()));
    }
    std::_Exit(0);
}

[[noreturn]] void listWithoutDriver() {
    setenv("VK_ICD_FILENAMES", "/nonexistent.json", 1);
    setenv("VK_DRIVER_FILES", "/nonexistent.json", 1);
    try {
        VulkanContext::listDevices();
    } catch (const Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        std::_Exit(static_cast<int>(e.code()));
    }
    std::_Exit(0);
}

TEST_F(VulkanContextVkTest, NoDriverIsUnsupported) {
    // "threadsafe" re-executes the test binary for the child: a fork would inherit the loader's state.
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(createWithoutDriver(false), ::testing::ExitedWithCode(3), "^vulkan: no Vulkan driver");
    EXPECT_EXIT(createWithoutDriver(true), ::testing::ExitedWithCode(3), "^vulkan: no Vulkan driver");
    EXPECT_EXIT(listWithoutDriver(), ::testing::ExitedWithCode(3), "^vulkan: no Vulkan driver");
}

TEST_F(VulkanContextVkTest, SubmitNowRunsTheRecording) {
    bool recorded = false;
    context().submitNow([&](VkCommandBuffer cmd) {
        EXPECT_NE(cmd, VK_NULL_HANDLE);
        recorded = true;
    });
    EXPECT_TRUE(recorded);
}

// The negative control of every Vulkan test's "validationErrors() == 0": an invalid command must be
// reported. vkCmdSetViewport with viewportCount 0 breaks VUID-vkCmdSetViewport-viewportCount-arraylength;
// lavapipe copies zero viewports, so the call is harmless to the driver.
TEST_F(VulkanContextVkTest, ValidationReportsAnInvalidCommand) {
    ASSERT_EQ(context().validationErrors(), 0u) << test::validationLog(context());
    context().submitNow([](VkCommandBuffer cmd) { vkCmdSetViewport(cmd, 0, 0, nullptr); });
    EXPECT_GT(context().validationErrors(), 0u);
    bool named = false;
    for (const std::string& m : context().validationMessages())
        named |= m.rfind("error: ", 0) == 0 &&
                 m.find("VUID-vkCmdSetViewport-viewportCount-arraylength") != std::string::npos;
    EXPECT_TRUE(named) << test::validationLog(context());
    context().clearValidationMessages();
    EXPECT_EQ(context().validationErrors(), 0u);
    EXPECT_TRUE(context().validationMessages().empty());
}

} // namespace
} // namespace sb
