#pragma once
// Shared fixture of the Vulkan tests (FooVkTest): one context per suite on the default device (lavapipe)
// with the Khronos validation layer on, and after every test the check that the layer reported no error
// (its messages printed when it did), so a test that passes also used the API correctly.
#include <exception>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "TestPaths.h"
#include "vk/VulkanContext.h"

namespace sb::test {

/// tests/shaders/, the fixture shaders (tests/shaders/vk/ holds the Vulkan ones).
inline std::string testShaderRoot() {
    return std::string(SB_SOURCE_DIR) + "/tests/shaders";
}

/// Every message the layer recorded, one per line, for a failure's output.
inline std::string validationLog(const VulkanContext& context) {
    std::string out;
    for (const std::string& m : context.validationMessages()) out += m + "\n";
    return out;
}

/// The layer's error messages only (those starting "error"), one per line; "" when there were none.
inline std::string validationErrorLog(const VulkanContext& context) {
    std::string out;
    for (const std::string& m : context.validationMessages())
        if (m.rfind("error", 0) == 0) out += m + "\n";
    return out;
}

class VulkanTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        // gtest turns an exception here into skipped tests; every test fails with the message instead.
        try {
            VulkanOptions options;
            options.validation = true;
            sContext = std::make_unique<VulkanContext>(options);
        } catch (const std::exception& e) {
            sSetUpError = e.what();
        }
    }
    static void TearDownTestSuite() { sContext.reset(); }
    void SetUp() override {
        if (!sContext) FAIL() << "no Vulkan context: " << sSetUpError;
    }
    void TearDown() override {
        if (!sContext) return;
        EXPECT_EQ(sContext->validationErrors(), 0u) << validationLog(*sContext);
        sContext->clearValidationMessages();
    }
    static VulkanContext& context() { return *sContext; }

private:
    static inline std::unique_ptr<VulkanContext> sContext;
    static inline std::string sSetUpError;
};

} // namespace sb::test
