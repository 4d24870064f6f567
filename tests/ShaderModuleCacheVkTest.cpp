// ShaderModuleCache: the project's GLSL through shading/ShaderPreprocessor and glslang to SPIR-V modules on
// lavapipe: caching by (file, defines, stage), the VULKAN predefine, and compile errors that name the
// fixture file and line (tests/shaders/, shared with ProgramCacheGLTest).
#include <gtest/gtest.h>

#include <string>

#include "VkTestSupport.h"
#include "core/Error.h"
#include "vk/ShaderModuleCache.h"

namespace sb {
namespace {

using test::VulkanTest;

class ShaderModuleCacheVkTest : public VulkanTest {
protected:
    /// The sb::Error message of `get`, or "" when it did not throw.
    std::string errorOf(ShaderModuleCache& cache, const std::string& file, ShaderStage stage,
                        const Defines& defines = {}) {
        try {
            cache.get(file, defines, stage);
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ExitCode::Failure) << e.what();
            return e.what();
        }
        return "";
    }
};

TEST_F(ShaderModuleCacheVkTest, CompilesAndCaches) {
    ShaderModuleCache cache(context(), test::testShaderRoot());
    VkShaderModule vertex = cache.get("vk/triangle.vert", {}, ShaderStage::Vertex);
    VkShaderModule fragment = cache.get("vk/triangle.frag", {}, ShaderStage::Fragment);
    EXPECT_NE(vertex, VK_NULL_HANDLE);
    EXPECT_NE(fragment, VK_NULL_HANDLE);
    EXPECT_NE(vertex, fragment);
    EXPECT_EQ(cache.compileCount(), 2u);
    // Hits: no compile.
    EXPECT_EQ(cache.get("vk/triangle.vert", {}, ShaderStage::Vertex), vertex);
    EXPECT_EQ(cache.get("vk/triangle.frag", {}, ShaderStage::Fragment), fragment);
    EXPECT_EQ(cache.compileCount(), 2u);
    // Another permutation is another module; "" and "1" are the same define.
    VkShaderModule half = cache.get("vk/triangle.frag", {{"VIS_VALUE", "0.25"}}, ShaderStage::Fragment);
    EXPECT_NE(half, fragment);
    EXPECT_EQ(cache.compileCount(), 3u);
    EXPECT_EQ(cache.get("vk/triangle.frag", {{"VIS_VALUE", "0.25"}}, ShaderStage::Fragment), half);
    EXPECT_EQ(cache.get("vk/triangle.frag", {{"FLAG", ""}}, ShaderStage::Fragment),
              cache.get("vk/triangle.frag", {{"FLAG", "1"}}, ShaderStage::Fragment));
    EXPECT_EQ(cache.compileCount(), 4u);
}

TEST_F(ShaderModuleCacheVkTest, DefaultRootIsTheProjectsShaders) {
    ShaderModuleCache cache(context()); // shaders/ next to the binary or in the source tree
    const std::string message = errorOf(cache, "no/such/file.vert", ShaderStage::Vertex);
    EXPECT_NE(message.find("shaders/no/such/file.vert"), std::string::npos) << message;
}

TEST_F(ShaderModuleCacheVkTest, VulkanIsPredefined) {
    ShaderModuleCache cache(context(), test::testShaderRoot());
    EXPECT_EQ(errorOf(cache, "vk/vulkan_only.frag", ShaderStage::Fragment), "");
    // The same source without the Vulkan target would hit its #error: compile() sees the same predefine.
    const std::string source = "#version 450\n#ifndef VULKAN\n#error no VULKAN\n#endif\n"
                               "layout(location = 0) out vec4 o;\nvoid main() { o = vec4(VULKAN); }\n";
    EXPECT_FALSE(ShaderModuleCache::compile(source, ShaderStage::Fragment, "inline").empty());
}

TEST_F(ShaderModuleCacheVkTest, CompileProducesSpirv) {
    const std::string source = "#version 450\nvoid main() { gl_Position = vec4(float(gl_VertexIndex)); }\n";
    std::vector<uint32_t> spirv = ShaderModuleCache::compile(source, ShaderStage::Vertex, "inline.vert");
    ASSERT_GT(spirv.size(), 5u);
    EXPECT_EQ(spirv[0], 0x07230203u); // the SPIR-V magic number
}

TEST_F(ShaderModuleCacheVkTest, InlineErrorNamesTheSource) {
    try {
        ShaderModuleCache::compile("#version 450\nvoid main() { x = 1; }\n", ShaderStage::Vertex,
                                   "inline.vert");
        FAIL() << "compiled";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::Failure);
        const std::string message = e.what();
        EXPECT_NE(message.find("vertex shader 'inline.vert'"), std::string::npos) << message;
        EXPECT_NE(message.find("'x' : undeclared identifier"), std::string::npos) << message;
    }
}

// The GL fixture's error is plain GLSL 450 (and includes a file before it), so the same line must come
// back: string 0 line 7 after the include's #line bookkeeping.
TEST_F(ShaderModuleCacheVkTest, SyntaxErrorNamesFileAndLine) {
    ShaderModuleCache cache(context(), test::testShaderRoot());
    const std::string message =
        errorOf(cache, "errors/syntax_error.frag", ShaderStage::Fragment, {{"VIS_VALUE", "0.5"}});
    EXPECT_EQ(
        message.rfind("vulkan: cannot compile fragment shader 'errors/syntax_error.frag' [VIS_VALUE=0.5]: "
                      "errors/syntax_error.frag:7: error: ",
                      0),
        0u)
        << message;
    EXPECT_EQ(message.find("ERROR: 0:7"), std::string::npos) << "unmapped glslang location in: " << message;
    EXPECT_EQ(cache.compileCount(), 1u);
}

TEST_F(ShaderModuleCacheVkTest, ErrorInIncludedFileNamesThatFile) {
    ShaderModuleCache cache(context(), test::testShaderRoot());
    const std::string message = errorOf(cache, "errors/include_error.frag", ShaderStage::Fragment);
    EXPECT_NE(message.find("common/test_broken.glsl:4: error: "), std::string::npos) << message;
}

TEST_F(ShaderModuleCacheVkTest, MissingFileNamesIt) {
    ShaderModuleCache cache(context(), test::testShaderRoot());
    const std::string message = errorOf(cache, "vk/absent.vert", ShaderStage::Vertex);
    EXPECT_NE(message.find("'vk/absent.vert' not found"), std::string::npos) << message;
}

} // namespace
} // namespace sb
