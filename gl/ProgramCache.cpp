#include "gl/ProgramCache.h"

#include <algorithm>
#include <utility>

#include "core/Error.h"
#include "core/Paths.h"
#include "shading/CompileLog.h"
#include "shading/ShaderPreprocessor.h"

namespace sb {
namespace {

constexpr const char* kShaderDirectory = "shaders";

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    if (isProgram) {
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    } else {
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    }
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    if (isProgram) {
        glGetProgramInfoLog(object, length, nullptr, log.data());
    } else {
        glGetShaderInfoLog(object, length, nullptr, log.data());
    }
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

std::string cacheKey(const ShaderSources& sources, const Defines& defines) {
    return sources.vertex + "|" + sources.fragment + "|" + sources.geometry + "|" + sources.compute + "|" +
           fullDefinesKey(defines);
}

/// Compiles one stage; throws with the log mapped back to file:line through the #line table.
GLuint compileStage(const std::string& root, const std::string& file, const Defines& defines,
                    ShaderStage stage) {
    ShaderPreprocessor preprocessor(root);
    std::string source = preprocessor.build(file, defines, stage);
    GLuint shader = glCreateShader(glStage(stage));
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok) return shader;
    std::string log = preprocessor.mapLog(infoLog(shader, false));
    glDeleteShader(shader);
    std::string key = definesKey(defines);
    throw Error("cannot compile " + std::string(stageName(stage)) + " shader '" + file + "'" +
                    (key.empty() ? "" : " [" + key + "]") + ": " + leadWithFirstError(log),
                ExitCode::Failure);
}

GLuint link(const std::vector<GLuint>& shaders, const std::string& what) {
    GLuint program = glCreateProgram();
    for (GLuint shader : shaders) glAttachShader(program, shader);
    glLinkProgram(program);
    for (GLuint shader : shaders) {
        glDetachShader(program, shader);
        glDeleteShader(shader);
    }
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok) return program;
    std::string log = infoLog(program, true);
    glDeleteProgram(program);
    throw Error("cannot link program (" + what + "): " + leadWithFirstError(log), ExitCode::Failure);
}

} // namespace

GLenum glStage(ShaderStage stage) {
    switch (stage) {
    case ShaderStage::Vertex:
        return GL_VERTEX_SHADER;
    case ShaderStage::Geometry:
        return GL_GEOMETRY_SHADER;
    case ShaderStage::Fragment:
        return GL_FRAGMENT_SHADER;
    case ShaderStage::Compute:
        return GL_COMPUTE_SHADER;
    case ShaderStage::Mesh: // VK_EXT_mesh_shader's stage: no GL program has one
        throw Error("gl: a mesh shader stage is Vulkan only", ExitCode::Unsupported);
    }
    return GL_NONE;
}

ProgramCache::ProgramCache(std::string shaderRoot)
    : mRoot(shaderRoot.empty() ? Paths::findResourceDirectory(kShaderDirectory) : std::move(shaderRoot)) {}

const Program& ProgramCache::get(const ShaderSources& sources, const Defines& defines) {
    mDump.record(sources, defines, [&](const std::string& file, ShaderStage stage) {
        return preprocess(file, defines, stage);
    });
    std::string key = cacheKey(sources, defines);
    auto it = mPrograms.find(key);
    if (it != mPrograms.end()) return *it->second;
    ++mCompiles;
    std::vector<GLuint> shaders;
    try {
        for (const auto& [stage, file] : sources.stages())
            shaders.push_back(compileStage(mRoot, *file, defines, stage));
    } catch (...) {
        for (GLuint shader : shaders) glDeleteShader(shader);
        throw;
    }
    GLuint id = link(shaders, sources.describe() + ", defines '" + definesKey(defines) + "'");
    auto program = std::make_unique<Program>(id, definesKey(defines));
    return *mPrograms.emplace(key, std::move(program)).first->second;
}

void ProgramCache::clear() {
    mPrograms.clear();
}

std::string ProgramCache::preprocess(const std::string& file, const Defines& defines,
                                     ShaderStage stage) const {
    return ShaderPreprocessor(mRoot).build(file, defines, stage);
}

} // namespace sb
