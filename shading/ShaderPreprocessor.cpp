#include "shading/ShaderPreprocessor.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/Error.h"

namespace sb {
namespace {

const std::regex& includePattern() {
    static const std::regex pattern(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re");
    return pattern;
}

const std::regex& identifierPattern() {
    static const std::regex pattern("[A-Za-z_][A-Za-z0-9_]*");
    return pattern;
}

void appendDefines(const Defines& defines, std::string& out) {
    for (const auto& [name, value] : defines) {
        if (!std::regex_match(name, identifierPattern()))
            throw Error("shader define '" + name + "' is not a valid GLSL identifier", ExitCode::Failure);
        out += "#define " + name + " " + (value.empty() ? "1" : value) + "\n";
    }
}

} // namespace

std::string ShaderPreprocessor::build(const std::string& file, const Defines& defines, ShaderStage stage) {
    mFiles.clear();
    mIncluded.clear();
    std::string out = mVersionLine;
    appendDefines(defines, out);
    out += std::string("#define ") + stageDefine(stage) + " 1\n";
    expand(file, "", out);
    return out;
}

void ShaderPreprocessor::expand(const std::string& file, const std::string& includedFrom, std::string& out) {
    std::istringstream lines(readFile(file, includedFrom));
    const int index = static_cast<int>(mFiles.size());
    mFiles.push_back(file);
    mIncluded.insert(file);
    out += "#line 1 " + std::to_string(index) + "\n";
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        std::smatch match;
        if (!std::regex_match(line, match, includePattern())) {
            out += line + "\n";
            continue;
        }
        std::string child = match[1];
        if (mIncluded.count(child)) {
            out += "// already included: " + child + "\n";
            continue;
        }
        expand(child, file + ":" + std::to_string(number), out);
        // Back in this file: the next line is number + 1 of source string `index`.
        out += "#line " + std::to_string(number + 1) + " " + std::to_string(index) + "\n";
    }
}

std::string ShaderPreprocessor::readFile(const std::string& file, const std::string& includedFrom) const {
    std::filesystem::path path = std::filesystem::path(mRoot) / file;
    std::string where = includedFrom.empty() ? "" : includedFrom + ": ";
    if (!std::filesystem::is_regular_file(path))
        throw Error(where + "shader file '" + file + "' not found (looked for '" + path.string() + "')",
                    ExitCode::Failure);
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw Error(where + "cannot read shader file '" + path.string() + "'", ExitCode::Failure);
    return text.str();
}

std::string ShaderPreprocessor::mapLog(const std::string& log) const {
    static const std::regex mesa(R"(^\s*(\d+):(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
    static const std::regex glslang(R"(^\s*(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$)");
    auto fileName = [this](const std::string& index) {
        size_t i = std::stoul(index);
        return i < mFiles.size() ? mFiles[i] : "<source " + index + ">";
    };
    std::istringstream lines(log);
    std::string line, out;
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_match(line, m, mesa)) {
            line = fileName(m[1]) + ":" + m[2].str() + ":" + m[3].str() + ": " + m[4].str();
        } else if (std::regex_match(line, m, nvidia)) {
            line = fileName(m[1]) + ":" + m[2].str() + ": " + m[3].str();
        } else if (std::regex_match(line, m, glslang)) {
            line = fileName(m[2]) + ":" + m[3].str() + ": " + (m[1] == "ERROR" ? "error: " : "warning: ") +
                   m[4].str();
        }
        if (!line.empty()) out += (out.empty() ? "" : "\n") + line;
    }
    return out;
}

} // namespace sb
