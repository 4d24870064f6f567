#include "vk/ShaderModuleCache.h"

#include <filesystem>
#include <mutex>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "core/Error.h"
#include "core/Paths.h"
#include "gl/ShaderPreprocessor.h"
#include "vk/VulkanContext.h"

namespace sb {
namespace {

constexpr const char* kVersionLine = "#version 450\n";

/// glslang's process-wide tables, built once (never finalized: they live until exit).
void initializeGlslang() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

EShLanguage language(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER:
        return EShLangVertex;
    case GL_FRAGMENT_SHADER:
        return EShLangFragment;
    case GL_GEOMETRY_SHADER:
        return EShLangGeometry;
    default:
        throw Error("vulkan: unknown shader stage 0x" + std::to_string(stage), ExitCode::Failure);
    }
}

/// Compiles `source` to SPIR-V for Vulkan 1.2; false with glslang's log in `log` on failure.
bool compileToSpirv(const std::string& source, GLenum stage, std::vector<uint32_t>& spirv, std::string& log) {
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

/// The first line that says "error" leads (the one line a user sees); the whole log follows.
std::string leadWithFirstError(std::string log) {
    log.erase(log.find_last_not_of(" \n\r\t") + 1);
    size_t start = 0;
    while (start < log.size()) {
        size_t end = log.find('\n', start);
        std::string line = log.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (line.find("error") != std::string::npos || line.find("ERROR") != std::string::npos)
            return line + (log == line ? "" : "\nfull log:\n" + log);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return log;
}

std::string fullKey(const Defines& defines) {
    std::string key;
    for (const auto& [name, value] : defines) key += name + "=" + (value.empty() ? "1" : value) + ";";
    return key;
}

} // namespace

ShaderModuleCache::ShaderModuleCache(VulkanContext& context, std::string shaderRoot)
    : mContext(context),
      mRoot(shaderRoot.empty() ? Paths::findResourceDirectory("shaders") : std::move(shaderRoot)) {}

ShaderModuleCache::~ShaderModuleCache() {
    for (auto& [key, module] : mModules) vkDestroyShaderModule(mContext.device(), module, nullptr);
}

std::vector<uint32_t> ShaderModuleCache::compile(const std::string& source, GLenum stage,
                                                 const std::string& name) {
    std::vector<uint32_t> spirv;
    std::string log;
    if (!compileToSpirv(source, stage, spirv, log))
        throw Error("vulkan: cannot compile " + std::string(ShaderPreprocessor::stageName(stage)) +
                        " shader '" + name + "': " + leadWithFirstError(log),
                    ExitCode::Failure);
    return spirv;
}

VkShaderModule ShaderModuleCache::get(const std::string& file, const Defines& defines, GLenum stage) {
    auto key = std::make_tuple(file, fullKey(defines), stage);
    if (auto it = mModules.find(key); it != mModules.end()) return it->second;

    ShaderPreprocessor preprocessor(mRoot);
    preprocessor.setVersionLine(kVersionLine);
    const std::string source = preprocessor.build(file, defines, stage);
    std::vector<uint32_t> spirv;
    std::string log;
    ++mCompiles;
    if (!compileToSpirv(source, stage, spirv, log)) {
        const std::string permutation = definesKey(defines);
        throw Error("vulkan: cannot compile " + std::string(ShaderPreprocessor::stageName(stage)) +
                        " shader '" + file + "'" + (permutation.empty() ? "" : " [" + permutation + "]") +
                        ": " + leadWithFirstError(preprocessor.mapLog(log)),
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
