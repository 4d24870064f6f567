#pragma once
// SPIR-V from the project's GLSL (shaders/), compiled at run time with the glslang library, cached by
// (file, defines, stage) as gl/ProgramCache caches programs. The source is assembled by the same
// shading/ShaderPreprocessor (defines, stage define, #include expansion, #line mapping) with "#version 450"
// instead of the compatibility profile; glslang targeting Vulkan predefines VULKAN, so a shader keeps
// one source and puts its Vulkan-only layout (push constants, descriptor sets) in small `#ifdef VULKAN`
// blocks. A stage that enables GL_EXT_ray_query (`#extension GL_EXT_ray_query : require`, which needs
// GLSL 460) is compiled as "#version 460"; a mesh stage (ShaderStage::Mesh, GL_EXT_mesh_shader) stays 450;
// every stage targets Vulkan 1.2 and SPIR-V 1.5, which ray queries need (SPIR-V 1.4 or later). Compile errors
// throw sb::Error(Failure) naming the file and line as the GL cache does. With a dump directory (bench
// --dump-shaders DIR) every stage handed out is written as compiled, in the GL cache's layout
// (shading/ShaderDump.h).
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <vulkan/vulkan.h>

#include "shading/Defines.h"
#include "shading/ShaderDump.h"
#include "shading/ShaderSources.h"
#include "shading/ShaderStage.h"

namespace sb {

class VulkanContext;

/// The modules of one pipeline's stages (VK_NULL_HANDLE where the sources have none).
struct ShaderModules {
    VkShaderModule vertex = VK_NULL_HANDLE, geometry = VK_NULL_HANDLE, fragment = VK_NULL_HANDLE,
                   mesh = VK_NULL_HANDLE;
};

class ShaderModuleCache {
public:
    /// `shaderRoot` as for ProgramCache ("" = the shaders/ directory of Paths::searchRoots()).
    ShaderModuleCache(VulkanContext& context, std::string shaderRoot = "");
    ~ShaderModuleCache();
    ShaderModuleCache(const ShaderModuleCache&) = delete;
    ShaderModuleCache& operator=(const ShaderModuleCache&) = delete;

    /// The modules of a pipeline's stages with `defines`, each compiled on first use; the stages are
    /// dumped as one program, in the layout the GL cache writes.
    ShaderModules get(const ShaderSources& sources, const Defines& defines);
    /// One stage's module (not dumped: a pipeline's stages go through get(sources, defines)).
    VkShaderModule get(const std::string& file, const Defines& defines, ShaderStage stage);
    /// The source of one stage as it is compiled (for tests and the dump).
    std::string preprocess(const std::string& file, const Defines& defines, ShaderStage stage) const;
    /// SPIR-V of a GLSL source already assembled (tests); throws sb::Error(Failure) with glslang's log.
    static std::vector<uint32_t> compile(const std::string& source, ShaderStage stage,
                                         const std::string& name);
    size_t compileCount() const { return mCompiles; }

    /// As ProgramCache's: `--dump-shaders DIR` (created; "" stops), the technique label, and the paths
    /// of the stages handed out since the last call.
    void setDumpDirectory(const std::string& directory) { mDump.setDirectory(directory); }
    void setDumpLabel(const std::string& label) { mDump.setLabel(label); }
    std::vector<std::string> takeDumpLog() { return mDump.takeLog(); }

private:
    VulkanContext& mContext;
    std::string mRoot;
    ShaderDump mDump;
    std::map<std::tuple<std::string, std::string, ShaderStage>, VkShaderModule> mModules;
    size_t mCompiles = 0;
};

} // namespace sb
