#include "shading/ShaderDump.h"

#include <filesystem>
#include <fstream>
#include <system_error>
#include <utility>

#include "core/Error.h"

namespace sb {
namespace {

constexpr const char* kUntagged = "untagged";
constexpr size_t kLongPermutation = 255; // a file name's limit in bytes

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

void ShaderDump::setDirectory(const std::string& directory) {
    mDirectory = directory;
    mWritten.clear();
    mLog.clear();
    if (directory.empty()) return;
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory))
        throw Error("--dump-shaders " + directory + ": cannot create the directory" +
                        (error ? " (" + error.message() + ")" : ""),
                    ExitCode::BadInput);
}

void ShaderDump::record(const ShaderSources& sources, const Defines& defines, const Build& build) {
    if (!active()) return;
    for (const auto& [stage, file] : sources.stages()) {
        std::string relative = path(mLabel, sources, defines, stage);
        mLog.push_back(relative);
        if (!mWritten.insert(relative).second) continue;
        writeText(std::filesystem::path(mDirectory) / relative, build(*file, stage));
    }
}

std::vector<std::string> ShaderDump::takeLog() {
    return std::exchange(mLog, {});
}

std::string ShaderDump::path(const std::string& label, const ShaderSources& sources, const Defines& defines,
                             ShaderStage stage) {
    std::string permutation = definesKey(defines);
    if (permutation.empty()) permutation = "default";
    // A longer key keeps its head and ends with its hash, within the limit.
    if (permutation.size() > kLongPermutation)
        permutation = permutation.substr(0, kLongPermutation - 17) + "~" + hash64(permutation);
    return (label.empty() ? kUntagged : label) + "/" + sources.programName() + "/" + permutation + "/" +
           stageFileName(stage);
}

} // namespace sb
