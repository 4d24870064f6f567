#pragma once
// The layout's dependency rules (docs/ARCHITECTURE.md, "Layout"), checked over a source tree as text:
//   - includes: a file may include its own folder and the folders its layer lists, nothing else
//     (gl/ and scenes/ stand side by side on core/; no technique folder includes another; bench/'s
//     folders form one order: output < images, run < viewer, sweep < bottleneck < figures, report < bench/);
//   - core/ includes only the C++ standard library, GLM, nlohmann/json and libpng (core/PngFile);
//   - shaders: a technique's C++ names programs from shaders/<its name>/ and shaders/common/ only, and a
//     shader includes only its own folder and common/;
//   - text: nothing refers to a file outside the repository (DESIGN.md, ../shared) or carries an
//     "issue N" tag, in code, shaders, scripts, scene files or docs;
//   - every C++ folder has a layer in the table (a new folder is placed on purpose).
// The table below is the rules; docs/ARCHITECTURE.md explains them. tests/ may include anything.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace sb::layout {

namespace fs = std::filesystem;

struct Violation {
    std::string file; ///< relative to the checked root, '/' separated
    int line = 0;     ///< 1-based
    std::string
        rule; ///< "include", "core-system", "shader", "shader-include", "outside-reference", "no-layer"
    std::string detail;

    /// "gl/Bad.cpp:3: include: gl/ may not include scenes/ (scenes/Scene.h)"
    std::string text() const { return file + ":" + std::to_string(line) + ": " + rule + ": " + detail; }
    /// "gl/Bad.cpp:3: include" (what a fixture's expectations name)
    std::string key() const { return file + ":" + std::to_string(line) + ": " + rule; }
};

/// One row of the rules: a folder (a "layer"), the folders below it that it may include, and the shader
/// folders its C++ may name. "techniques/*" stands for every technique folder (techniques/<name>/
/// other than submit/ and common/), whose own shader folder shaders/<name>/ is always allowed.
struct Layer {
    std::string folder;
    std::vector<std::string> mayInclude;
    std::vector<std::string> shaderFolders;
};

inline const std::vector<Layer>& layers() {
    const std::vector<std::string> base = {"core", "gl", "scenes"};
    const std::vector<std::string> techniques = {"core", "gl", "scenes", "techniques", "techniques/submit"};
    // A technique folder may hold a Vulkan form of its technique (techniques/vulkan/ and vk/ below it).
    const std::vector<std::string> vulkanTechniques = {"vk", "techniques/vulkan"};
    const std::vector<std::string> belowBench = {
        "core",     "gl",         "gl/backends",       "vk",
        "scenes",   "techniques", "techniques/submit", "techniques/vulkan",
        "reference"};
    auto plus = [](std::vector<std::string> a, const std::vector<std::string>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    static const std::vector<Layer> kLayers = {
        {"core", {}, {}},
        {"gl", {"core"}, {}},
        {"gl/backends", {"core", "gl"}, {}},
        // The Vulkan platform stands on gl/ for the shader preprocessor (one GLSL source, two APIs).
        {"vk", {"core", "gl"}, {}},
        {"scenes", {"core"}, {}},
        {"techniques/submit", base, {}},
        {"techniques", plus(base, {"techniques/submit"}), {}},
        {"techniques/common", techniques, {"common"}},
        // The technique contract on Vulkan: the declaration and submission of techniques/, drawn with vk/.
        {"techniques/vulkan", plus(techniques, {"vk"}), {}},
        {"techniques/*", plus(plus(techniques, {"techniques/common"}), vulkanTechniques), {"common"}},
        {"reference", techniques, {"reference", "common"}},
        {"bench/output", {"core", "gl"}, {}},
        // Pictures of results (error maps, difference maps, contact sheets): pixels and the accuracy
        // classes in, pixels out, written through bench/output's ImageWriter.
        {"bench/images", plus(belowBench, {"bench/output"}), {}},
        {"bench/run", plus(belowBench, {"bench/output"}), {"calibrate", "common"}},
        {"bench/viewer", plus(belowBench, {"bench/output", "bench/run"}), {"viewer", "common"}},
        {"bench/sweep", plus(belowBench, {"bench/output", "bench/run"}), {}},
        {"bench/bottleneck", plus(belowBench, {"bench/output", "bench/run", "bench/sweep"}), {}},
        // `-t auto`: the calibration runs frames through the harness and judges them like accuracy.
        {"bench/select", plus(belowBench, {"bench/output", "bench/run"}), {}},
        // The matrix resolves its `auto` cells as a run does.
        {"bench/golden", plus(belowBench, {"bench/output", "bench/images", "bench/run", "bench/select"}), {}},
        // The performance gate (work counters, instructions under callgrind, wall-time statistics).
        {"bench/figures",
         plus(belowBench, {"bench/output", "bench/run", "bench/sweep", "bench/bottleneck"}),
         {}},
        {"bench/ci", plus(belowBench, {"bench/output", "bench/run", "bench/sweep"}), {}},
        {"bench/report", plus(belowBench, {"bench/output", "bench/run", "bench/sweep"}), {}},
        {"bench",
         plus(belowBench,
              {"bench/output", "bench/images", "bench/report", "bench/run", "bench/viewer", "bench/sweep",
               "bench/bottleneck", "bench/figures", "bench/golden", "bench/ci", "bench/select"}),
         {"common"}},
        // The hand-written shadow map that bench is measured against: the scene model only, no harness.
        {"bench/handshadow", {"core", "scenes"}, {}},
        // The libFuzzer targets call parsers from scenes/ up to bench/sweep/; nothing includes them.
        {"fuzz", plus(belowBench, {"bench/output", "bench/run", "bench/sweep"}), {}},
    };
    return kLayers;
}

/// Single files allowed more than their folder, each with its reason.
struct Exception {
    std::string file;
    std::vector<std::string> mayAlsoInclude;
    std::string why;
};

inline const std::vector<Exception>& exceptions() {
    static const std::vector<Exception> kExceptions = {
        {"registry/TechniqueRegistry.cpp",
         {"techniques/*", "reference"},
         "the one table of techniques names every technique, the reference included: the layout's one "
         "intended arrow up"},
        {"registry/TechniqueRegistry.h",
         {"techniques/vulkan"},
         "the table's Vulkan half hands out the Vulkan form of a technique (techniques/vulkan/), which "
         "stands on techniques/ like every technique"},
    };
    return kExceptions;
}

/// The layer a folder belongs to: "techniques/<name>" is "techniques/*" unless it is submit/ or common/.
inline std::string layerOf(const std::string& folder) {
    static const std::regex technique("techniques/([A-Za-z0-9_]+)");
    std::smatch m;
    if (std::regex_match(folder, m, technique) && m[1] != "submit" && m[1] != "common" && m[1] != "vulkan")
        return "techniques/*";
    return folder;
}

inline const Layer* findLayer(const std::string& layer) {
    for (const Layer& l : layers())
        if (l.folder == layer) return &l;
    return nullptr;
}

namespace detail {

inline std::string folderOf(const std::string& path) {
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? "" : path.substr(0, slash);
}

inline bool startsWith(const std::string& s, const std::string& prefix) {
    return s.compare(0, prefix.size(), prefix) == 0;
}

inline bool hasExtension(const std::string& path, std::initializer_list<const char*> extensions) {
    const std::string ext = fs::path(path).extension().string();
    return std::any_of(extensions.begin(), extensions.end(), [&](const char* e) { return ext == e; });
}

inline bool isCpp(const std::string& path) {
    return hasExtension(path, {".h", ".cpp"});
}

inline bool isShader(const std::string& path) {
    return hasExtension(path, {".vert", ".frag", ".geom", ".comp", ".glsl"});
}

/// Text the outside-reference rule reads: code, shaders, scripts, build files, scene files, docs.
inline bool isText(const std::string& path) {
    return isCpp(path) || isShader(path) || hasExtension(path, {".py", ".sh", ".md", ".json", ".sbatch"}) ||
           fs::path(path).filename() == "CMakeLists.txt" || path == ".ci/run";
}

inline std::vector<std::string> readLines(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

/// Every file under `root` (relative, '/' separated, sorted), without build trees, git and `skip`.
inline std::vector<std::string> listFiles(const fs::path& root, const std::vector<std::string>& skip) {
    std::vector<std::string> out;
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        const std::string rel = fs::relative(it->path(), root).generic_string();
        const std::string name = it->path().filename().string();
        const bool skipped =
            std::any_of(skip.begin(), skip.end(), [&](const std::string& s) { return rel == s; });
        if (it->is_directory() &&
            (skipped || (name.size() > 1 && name[0] == '.' && name != ".ci") || startsWith(name, "build") ||
             name == "out" || name == "__pycache__" || rel == "results/scratch")) {
            it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file() && !skipped) out.push_back(rel);
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// The folder set `allowed` covers `target` (a folder), "techniques/*" matching every technique folder.
inline bool covers(const std::vector<std::string>& allowed, const std::string& target) {
    const std::string layer = layerOf(target);
    return std::any_of(allowed.begin(), allowed.end(), [&](const std::string& a) { return a == layer; });
}

inline void checkIncludes(const std::string& file, const std::vector<std::string>& lines,
                          std::vector<Violation>& out) {
    static const std::regex quoted(R"(^\s*#\s*include\s+"([^"]+)\")");
    static const std::regex angled(R"(^\s*#\s*include\s+<([^>]+)>)");
    const std::string folder = folderOf(file);
    const std::string layer = layerOf(folder);
    const Layer* rules = findLayer(layer);
    if (!rules) {
        out.push_back({file, 1, "no-layer",
                       "folder " + folder + "/ has no layer in tests/LayoutRules.h (place it on purpose)"});
        return;
    }
    std::vector<std::string> allowed = rules->mayInclude;
    for (const Exception& e : exceptions())
        if (e.file == file) allowed.insert(allowed.end(), e.mayAlsoInclude.begin(), e.mayAlsoInclude.end());
    for (size_t i = 0; i < lines.size(); ++i) {
        std::smatch m;
        const int line = int(i) + 1;
        if (std::regex_search(lines[i], m, quoted)) {
            const std::string target = m[1];
            const std::string targetFolder = folderOf(target);
            if (targetFolder == folder || covers(allowed, targetFolder)) continue;
            out.push_back({file, line, "include",
                           folder + "/ may not include " + (targetFolder.empty() ? "." : targetFolder) +
                               "/ (" + target + ")"});
        } else if (layer == "core" && std::regex_search(lines[i], m, angled)) {
            const std::string header = m[1];
            const bool standard =
                header.find('/') == std::string::npos && header.find('.') == std::string::npos;
            if (standard || startsWith(header, "glm/") || startsWith(header, "nlohmann/") ||
                header == "png.h")
                continue;
            out.push_back(
                {file, line, "core-system",
                 "core/ uses only the standard library, GLM, nlohmann/json and libpng (<" + header + ">)"});
        }
    }
}

inline void checkShaderNames(const std::string& file, const std::vector<std::string>& lines,
                             std::vector<Violation>& out) {
    static const std::regex program(R"re("([a-z_]+)/[A-Za-z0-9_]+\.(vert|frag|geom|comp|glsl)")re");
    const std::string folder = folderOf(file);
    const Layer* rules = findLayer(layerOf(folder));
    if (!rules) return; // reported by checkIncludes
    std::vector<std::string> allowed = rules->shaderFolders;
    if (layerOf(folder) == "techniques/*")
        allowed.push_back(folder.substr(std::string("techniques/").size()));
    for (size_t i = 0; i < lines.size(); ++i) {
        // Code only: comments may name shaders as examples ("common/x.glsl").
        const std::string code = lines[i].substr(0, lines[i].find("//"));
        for (auto it = std::sregex_iterator(code.begin(), code.end(), program); it != std::sregex_iterator();
             ++it) {
            const std::string shaderFolder = (*it)[1];
            if (std::find(allowed.begin(), allowed.end(), shaderFolder) != allowed.end()) continue;
            out.push_back({file, int(i) + 1, "shader",
                           folder + "/ may not draw with shaders/" + shaderFolder + "/ (" + it->str() + ")"});
        }
    }
}

inline void checkShaderIncludes(const std::string& file, const std::vector<std::string>& lines,
                                std::vector<Violation>& out) {
    static const std::regex include(R"(^\s*#\s*include\s+"([^"/]+)/[^"]+")");
    // shaders/<folder>/file
    const std::string folder = folderOf(file).substr(std::string("shaders/").size());
    for (size_t i = 0; i < lines.size(); ++i) {
        std::smatch m;
        if (!std::regex_search(lines[i], m, include)) continue;
        if (m[1] == folder || m[1] == "common") continue;
        out.push_back(
            {file, int(i) + 1, "shader-include",
             "shaders/" + folder + "/ may include only its own folder and common/ (" + m[1].str() + "/)"});
    }
}

inline void checkOutsideReferences(const std::string& file, const std::vector<std::string>& lines,
                                   std::vector<Violation>& out) {
    struct Pattern {
        std::regex re;
        const char* what;
    };
    static const std::vector<Pattern> patterns = {
        {std::regex(R"(DESIGN\.md)"), "DESIGN.md is outside the repository: cite docs/ARCHITECTURE.md"},
        {std::regex(R"(\.\./shared)"), "../shared is outside the repository: cite what is inside it"},
        {std::regex(R"(\b[Ii]ssue [0-9]+\b)"), "an issue tag means nothing in a clone: say what it means"},
    };
    for (size_t i = 0; i < lines.size(); ++i)
        for (const Pattern& p : patterns)
            if (std::regex_search(lines[i], p.re))
                out.push_back({file, int(i) + 1, "outside-reference", p.what});
}

} // namespace detail

/// Checks the tree at `root`; `skip` lists relative paths (files or folders) left out, such as a fixture.
inline std::vector<Violation> check(const fs::path& root, const std::vector<std::string>& skip = {}) {
    std::vector<Violation> out;
    for (const std::string& file : detail::listFiles(root, skip)) {
        const bool test = detail::startsWith(file, "tests/");
        const bool cpp = detail::isCpp(file);
        if (!detail::isText(file)) continue;
        const std::vector<std::string> lines = detail::readLines(root / file);
        if (cpp && !test && file.find('/') != std::string::npos) {
            detail::checkIncludes(file, lines, out);
            detail::checkShaderNames(file, lines, out);
        }
        if (detail::isShader(file) && detail::startsWith(file, "shaders/"))
            detail::checkShaderIncludes(file, lines, out);
        detail::checkOutsideReferences(file, lines, out);
    }
    return out;
}

} // namespace sb::layout
