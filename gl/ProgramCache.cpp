#include "gl/ProgramCache.h"

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <utility>

#include "core/Error.h"
#include "core/Paths.h"
#include "gl/ShaderPreprocessor.h"

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

/// The first line that says "error" leads the message (it is the one line a user sees); the rest of the
/// log follows on further lines.
std::string leadWithFirstError(std::string log) {
    log.erase(log.find_last_not_of(" \n\r\t") + 1);
    size_t start = 0;
    while (start < log.size()) {
        size_t end = log.find('\n', start);
        std::string line = log.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (line.find("error") != std::string::npos) return line + (log == line ? "" : "\nfull log:\n" + log);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return log;
}

std::string describe(const ShaderSources& sources, const Defines& defines) {
    std::string text = "vertex '" + sources.vertex + "'";
    if (!sources.fragment.empty()) text += ", fragment '" + sources.fragment + "'";
    if (!sources.geometry.empty()) text += ", geometry '" + sources.geometry + "'";
    return text + ", defines '" + definesKey(defines) + "'";
}

std::string cacheKey(const ShaderSources& sources, const Defines& defines) {
    std::string key = sources.vertex + "|" + sources.fragment + "|" + sources.geometry + "|";
    for (const auto& [name, value] : defines) key += name + "=" + (value.empty() ? "1" : value) + ";";
    return key;
}

/// Paths::findResource matches regular files only, so the directory is looked for in its search roots.
std::string findShaderRoot() {
    std::string searched;
    for (const std::string& root : Paths::searchRoots()) {
        std::filesystem::path candidate = std::filesystem::path(root) / kShaderDirectory;
        std::error_code error;
        if (std::filesystem::is_directory(candidate, error)) return candidate.string();
        searched += (searched.empty() ? "" : ", ") + root;
    }
    throw Error("shader directory 'shaders/' not found (searched: " + searched + ")", ExitCode::Failure);
}

/// Compiles one stage; throws with the log mapped back to file:line through the #line table.
GLuint compileStage(const std::string& root, const std::string& file, const Defines& defines, GLenum stage) {
    ShaderPreprocessor preprocessor(root);
    std::string source = preprocessor.build(file, defines, stage);
    GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok) return shader;
    std::string log = preprocessor.mapLog(infoLog(shader, false));
    glDeleteShader(shader);
    std::string key = definesKey(defines);
    throw Error("cannot compile " + std::string(ShaderPreprocessor::stageName(stage)) + " shader '" + file +
                    "'" + (key.empty() ? "" : " [" + key + "]") + ": " + leadWithFirstError(log),
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

std::string definesKey(const Defines& d) {
    std::string key;
    for (const auto& [name, value] : d) {
        if (!key.empty()) key += ",";
        key += name;
        if (!value.empty() && value != "1") key += "=" + value;
    }
    return key;
}

ProgramCache::ProgramCache(std::string shaderRoot)
    : mRoot(shaderRoot.empty() ? findShaderRoot() : std::move(shaderRoot)) {}

const Program& ProgramCache::get(const ShaderSources& sources, const Defines& defines) {
    std::string key = cacheKey(sources, defines);
    auto it = mPrograms.find(key);
    if (it != mPrograms.end()) return *it->second;
    ++mCompiles;
    std::vector<GLuint> shaders;
    try {
        shaders.push_back(compileStage(mRoot, sources.vertex, defines, GL_VERTEX_SHADER));
        if (!sources.geometry.empty())
            shaders.push_back(compileStage(mRoot, sources.geometry, defines, GL_GEOMETRY_SHADER));
        if (!sources.fragment.empty())
            shaders.push_back(compileStage(mRoot, sources.fragment, defines, GL_FRAGMENT_SHADER));
    } catch (...) {
        for (GLuint shader : shaders) glDeleteShader(shader);
        throw;
    }
    GLuint id = link(shaders, describe(sources, defines));
    auto program = std::make_unique<Program>(id, definesKey(defines));
    return *mPrograms.emplace(key, std::move(program)).first->second;
}

void ProgramCache::clear() {
    mPrograms.clear();
}

std::string ProgramCache::preprocess(const std::string& file, const Defines& defines, GLenum stage) const {
    return ShaderPreprocessor(mRoot).build(file, defines, stage);
}

} // namespace sb
