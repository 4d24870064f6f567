#include "core/Paths.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/Error.h"

namespace sb {

namespace fs = std::filesystem;

std::vector<std::string> Paths::searchRoots() {
    std::vector<std::string> roots;
    // The build copies shaders/ and scenes/data/ next to the binaries; tests live one level below
    // (build/tests/), hence the parent too. The source tree is the fallback for uncopied files.
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec && exe.has_parent_path()) {
        roots.push_back(exe.parent_path().string());
        if (exe.parent_path().has_parent_path()) roots.push_back(exe.parent_path().parent_path().string());
#ifdef SHADOWBENCH_INSTALL_DATADIR
        // Installed: <prefix>/bin/bench reads <prefix>/share/shadowbench (relative, so a prefix moved
        // or unpacked elsewhere, as a .deb's or a test's temporary prefix, still finds its files).
        if (exe.parent_path().has_parent_path())
            roots.push_back((exe.parent_path().parent_path() / SHADOWBENCH_INSTALL_DATADIR).string());
#endif
    }
#ifdef SHADOWBENCH_SOURCE_DIR
    roots.push_back(SHADOWBENCH_SOURCE_DIR);
#endif
    return roots;
}

std::string Paths::findResource(const std::string& relative) {
    std::error_code ec;
    for (const auto& root : searchRoots()) {
        const fs::path candidate = fs::path(root) / relative;
        if (fs::is_regular_file(candidate, ec)) return candidate.string();
    }
    return "";
}

std::string Paths::findResourceDirectory(const std::string& relative) {
    std::string searched;
    for (const std::string& root : searchRoots()) {
        const fs::path candidate = fs::path(root) / relative;
        std::error_code error;
        if (fs::is_directory(candidate, error)) return candidate.string();
        searched += (searched.empty() ? "" : ", ") + root;
    }
    throw Error("directory '" + relative + "/' not found (searched: " + searched + ")", ExitCode::Failure);
}

std::string Paths::readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot read '" + path + "': " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw Error("cannot read '" + path + "': " + std::strerror(errno));
    return text.str();
}

} // namespace sb
