#pragma once
// SPIR-V from the project's GLSL (shaders/), compiled at run time with the glslang library, cached by
// (file, defines, stage) as gl/ProgramCache caches programs. The source is assembled by the same
// gl/ShaderPreprocessor (defines, stage define, #include expansion, #line mapping) with "#version 450"
// instead of the compatibility profile; glslang targeting Vulkan predefines VULKAN, so a shader keeps
// one source and puts its Vulkan-only layout (push constants, descriptor sets) in small `#ifdef VULKAN`
// blocks. Compile errors throw sb::Error(Failure) naming the file and line as the GL cache does.
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <vulkan/vulkan.h>

#include "gl/ProgramCache.h"

namespace sb {

class VulkanContext;

class ShaderModuleCache {
public:
    /// `shaderRoot` as for ProgramCache ("" = the shaders/ directory of Paths::searchRoots()).
    ShaderModuleCache(VulkanContext& context, std::string shaderRoot = "");
    ~ShaderModuleCache();
    ShaderModuleCache(const ShaderModuleCache&) = delete;
    ShaderModuleCache& operator=(const ShaderModuleCache&) = delete;

    /// The module for `file` (relative to shaders/) in `stage` (GL_VERTEX_SHADER, GL_FRAGMENT_SHADER,
    /// GL_GEOMETRY_SHADER: the preprocessor's stage names) with `defines`; compiled on first use.
    VkShaderModule get(const std::string& file, const Defines& defines, GLenum stage);
    /// SPIR-V of a GLSL source already assembled (tests); throws sb::Error(Failure) with glslang's log.
    static std::vector<uint32_t> compile(const std::string& source, GLenum stage, const std::string& name);
    size_t compileCount() const { return mCompiles; }

private:
    VulkanContext& mContext;
    std::string mRoot;
    std::map<std::tuple<std::string, std::string, GLenum>, VkShaderModule> mModules;
    size_t mCompiles = 0;
};

} // namespace sb
