#include "vk/ShaderModuleCache.h"

#include <filesystem>
#include <mutex>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "core/Error.h"
#include "core/Paths.h"
#include "shading/CompileLog.h"
#include "shading/ShaderPreprocessor.h"
#include "vk/VulkanContext.h"

namespace sb {
namespace {

constexpr const char* kVersionLine = "#version 450\n";
/// GL_EXT_ray_query exists from GLSL 460 on; a stage that enables it (shaders/raytraced/) is compiled
/// as 460, every other stays 450, so their SPIR-V is the same as before ray queries came.
constexpr const char* kRayQueryVersionLine = "#version 460\n";
constexpr const char* kRayQueryExtension = "#extension GL_EXT_ray_query";

/// The stage's source as compiled: `preprocessor`'s, its version raised to 460 where it enables ray queries.
std::string assemble(ShaderPreprocessor& preprocessor, const std::string& file, const Defines& defines,
                     ShaderStage stage) {
    preprocessor.setVersionLine(kVersionLine);
    std::string source = preprocessor.build(file, defines, stage);
    if (source.find(kRayQueryExtension) != std::string::npos)
        source.replace(0, std::string(kVersionLine).size(), kRayQueryVersionLine);
    return source;
}

/// glslang's process-wide tables, built once (never finalized: they live until exit).
void initializeGlslang() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

EShLanguage language(ShaderStage stage) {
    switch (stage) {
    case ShaderStage::Vertex:
        return EShLangVertex;
    case ShaderStage::Fragment:
        return EShLangFragment;
    case ShaderStage::Geometry:
        return EShLangGeometry;
    case ShaderStage::Compute:
        return EShLangCompute;
    case ShaderStage::Mesh:
        return EShLangMesh;
    }
    throw Error("vulkan: unknown shader stage", ExitCode::Failure);
}

/// Compiles `source` to SPIR-V for Vulkan 1.2; false with glslang's log in `log` on failure.
bool compileToSpirv(const std::string& source, ShaderStage stage, std::vector<uint32_t>& spirv,
                    std::string& log) {
    initializeGlslang();
    const EShLanguage lang = language(stage);
    glslang::TShader shader(lang);
    const char* text = source.c_str();
    shader.setStrings(&text, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
    // The project's varyings carry no locations (GL matches them by name); Vulkan matches by location,
    // so they are numbered in declaration order, the same in every stage that declares them in the same
    // order (common/scene.vert and the fragment shaders it feeds).
    shader.setAutoMapLocations(true);
    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 450, false, messages)) {
        log = std::string(shader.getInfoLog()) + shader.getInfoDebugLog();
        return false;
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages) || !program.mapIO()) {
        log = std::string(program.getInfoLog()) + program.getInfoDebugLog();
        return false;
    }
    spirv.clear();
    glslang::SpvOptions options;
    options.validate = false;
    glslang::GlslangToSpv(*program.getIntermediate(lang), spirv, &options);
    return true;
}

} // namespace

ShaderModuleCache::ShaderModuleCache(VulkanContext& context, std::string shaderRoot)
    : mContext(context),
      mRoot(shaderRoot.empty() ? Paths::findResourceDirectory("shaders") : std::move(shaderRoot)) {}

ShaderModuleCache::~ShaderModuleCache() {
    for (auto& [key, module] : mModules) vkDestroyShaderModule(mContext.device(), module, nullptr);
}

std::vector<uint32_t> ShaderModuleCache::compile(const std::string& source, ShaderStage stage,
                                                 const std::string& name) {
    std::vector<uint32_t> spirv;
    std::string log;
    if (!compileToSpirv(source, stage, spirv, log))
        throw Error("vulkan: cannot compile " + std::string(stageName(stage)) + " shader '" + name +
                        "': " + leadWithFirstError(log),
                    ExitCode::Failure);
    return spirv;
}

ShaderModules ShaderModuleCache::get(const ShaderSources& sources, const Defines& defines) {
    mDump.record(sources, defines, [&](const std::string& file, ShaderStage stage) {
        return preprocess(file, defines, stage);
    });
    ShaderModules modules;
    for (const auto& [stage, file] : sources.stages()) {
        const VkShaderModule module = get(*file, defines, stage);
        (stage == ShaderStage::Vertex     ? modules.vertex
         : stage == ShaderStage::Geometry ? modules.geometry
         : stage == ShaderStage::Mesh     ? modules.mesh
                                          : modules.fragment) = module;
    }
    return modules;
}

std::string ShaderModuleCache::preprocess(const std::string& file, const Defines& defines,
                                          ShaderStage stage) const {
    ShaderPreprocessor preprocessor(mRoot);
    return assemble(preprocessor, file, defines, stage);
}

VkShaderModule ShaderModuleCache::get(const std::string& file, const Defines& defines, ShaderStage stage) {
    auto key = std::make_tuple(file, fullDefinesKey(defines), stage);
    if (auto it = mModules.find(key); it != mModules.end()) return it->second;

    ShaderPreprocessor preprocessor(mRoot);
    const std::string source = assemble(preprocessor, file, defines, stage);
    std::vector<uint32_t> spirv;
    std::string log;
    ++mCompiles;
    if (!compileToSpirv(source, stage, spirv, log)) {
        const std::string permutation = definesKey(defines);
        throw Error("vulkan: cannot compile " + std::string(stageName(stage)) + " shader '" + file + "'" +
                        (permutation.empty() ? "" : " [" + permutation + "]") + ": " +
                        leadWithFirstError(preprocessor.mapLog(log)),
                    ExitCode::Failure);
    }
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size() * sizeof(uint32_t);
    info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateShaderModule(mContext.device(), &info, nullptr, &module),
                         "vkCreateShaderModule");
    mModules.emplace(key, module);
    return module;
}

} // namespace sb
