#include "gl/ProgramCache.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
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

constexpr const char* kUntagged = "untagged";

/// "vertex.vert" etc.: the stage's name with the extension glslangValidator reads the stage from.
std::string stageFileName(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER:
        return "vertex.vert";
    case GL_FRAGMENT_SHADER:
        return "fragment.frag";
    case GL_GEOMETRY_SHADER:
        return "geometry.geom";
    case GL_COMPUTE_SHADER:
        return "compute.comp";
    default:
        return std::string(ShaderPreprocessor::stageName(stage)) + ".glsl";
    }
}

std::string programName(const ShaderSources& sources) {
    std::string name;
    for (const std::string* file : {&sources.vertex, &sources.geometry, &sources.fragment}) {
        if (file->empty()) continue;
        std::string part = *file;
        std::replace(part.begin(), part.end(), '/', '-');
        name += (name.empty() ? "" : "+") + part;
    }
    return name;
}

/// The stages of a program in compile order, each with its file.
std::vector<std::pair<GLenum, const std::string*>> stagesOf(const ShaderSources& sources) {
    std::vector<std::pair<GLenum, const std::string*>> stages = {{GL_VERTEX_SHADER, &sources.vertex}};
    if (!sources.geometry.empty()) stages.emplace_back(GL_GEOMETRY_SHADER, &sources.geometry);
    if (!sources.fragment.empty()) stages.emplace_back(GL_FRAGMENT_SHADER, &sources.fragment);
    return stages;
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::error_code error;
    std::filesystem::create_directories(path.parent_path(), error);
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (error || !out)
        throw Error("--dump-shaders: cannot write '" + path.string() + "'" +
                        (error ? " (" + error.message() + ")" : ""),
                    ExitCode::BadInput);
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
    : mRoot(shaderRoot.empty() ? Paths::findResourceDirectory(kShaderDirectory) : std::move(shaderRoot)) {}

const Program& ProgramCache::get(const ShaderSources& sources, const Defines& defines) {
    if (!mDumpDirectory.empty()) dump(sources, defines);
    std::string key = cacheKey(sources, defines);
    auto it = mPrograms.find(key);
    if (it != mPrograms.end()) return *it->second;
    ++mCompiles;
    std::vector<GLuint> shaders;
    try {
        for (const auto& [stage, file] : stagesOf(sources))
            shaders.push_back(compileStage(mRoot, *file, defines, stage));
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

void ProgramCache::setDumpDirectory(const std::string& directory) {
    mDumpDirectory = directory;
    mDumped.clear();
    mDumpLog.clear();
    if (directory.empty()) return;
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory))
        throw Error("--dump-shaders " + directory + ": cannot create the directory" +
                        (error ? " (" + error.message() + ")" : ""),
                    ExitCode::BadInput);
}

std::vector<std::string> ProgramCache::takeDumpLog() {
    return std::exchange(mDumpLog, {});
}

std::string ProgramCache::dumpPath(const std::string& label, const ShaderSources& sources,
                                   const Defines& defines, GLenum stage) {
    std::string permutation = definesKey(defines);
    return (label.empty() ? kUntagged : label) + "/" + programName(sources) + "/" +
           (permutation.empty() ? "default" : permutation) + "/" + stageFileName(stage);
}

/// Writes each stage not yet written under this label; the source is the one compileStage builds.
void ProgramCache::dump(const ShaderSources& sources, const Defines& defines) {
    for (const auto& [stage, file] : stagesOf(sources)) {
        std::string path = dumpPath(mDumpLabel, sources, defines, stage);
        mDumpLog.push_back(path);
        if (!mDumped.insert(path).second) continue;
        writeText(std::filesystem::path(mDumpDirectory) / path, preprocess(*file, defines, stage));
    }
}

std::string ProgramCache::preprocess(const std::string& file, const Defines& defines, GLenum stage) const {
    return ShaderPreprocessor(mRoot).build(file, defines, stage);
}

} // namespace sb
