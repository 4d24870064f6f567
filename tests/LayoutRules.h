#pragma once
// The layout's dependency rules (docs/ARCHITECTURE.md, "Layout"), checked over a source tree as text:
//   - includes: a file may include its own folder and the folders its layer lists, nothing else; the
//     table below has no arrow up (the registry is a layer of its own, above every technique);
//   - vulkan-gl: no Vulkan file (vk/, techniques/vulkan/, a technique's *Vulkan.{h,cpp}) reaches a GL
//     header, directly or through what it includes (gl/, techniques/gl/, <epoxy/...>, <EGL/...>,
//     <GL/...>): one declaration per technique serves both APIs without pulling GL into Vulkan code;
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
#include <map>
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
    /// "include", "vulkan-gl", "core-system", "shader", "shader-include", "outside-reference", "no-layer"
    std::string rule;
    std::string detail;

    /// "gl/Bad.cpp:3: include: gl/ may not include scenes/ (scenes/Scene.h)"
    std::string text() const { return file + ":" + std::to_string(line) + ": " + rule + ": " + detail; }
    /// "gl/Bad.cpp:3: include" (what a fixture's expectations name)
    std::string key() const { return file + ":" + std::to_string(line) + ": " + rule; }
};

/// One row of the rules: a folder (a "layer"), the folders below it that it may include, and the shader
/// folders its C++ may name. "techniques/*" stands for every technique folder (techniques/<name>/
/// other than the contract folders gl/ and vulkan/), whose own shader folder shaders/<name>/ is always
/// allowed; "bench/lib/*" for every library folder of bench/.
struct Layer {
    std::string folder;
    std::vector<std::string> mayInclude;
    std::vector<std::string> shaderFolders;
};

inline const std::vector<Layer>& layers() {
    auto plus = [](std::vector<std::string> a, const std::vector<std::string>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    // The technique contract, neutral, and each API's contract above it.
    const std::vector<std::string> contract = {"core", "shading", "scenes", "techniques"};
    const std::vector<std::string> glContract = plus(contract, {"gl", "techniques/gl"});
    const std::vector<std::string> vulkanContract = plus(contract, {"vk", "techniques/vulkan"});
    // What bench's folders stand on below bench/: every layer of the product.
    const std::vector<std::string> belowBench =
        plus(plus(glContract, {"gl/backends", "vk", "techniques/vulkan"}), {"reference", "registry"});
    auto lib = [&](std::initializer_list<const char*> libs) {
        std::vector<std::string> out = belowBench;
        for (const char* l : libs) out.push_back(std::string("bench/lib/") + l);
        return out;
    };
    static const std::vector<Layer> kLayers = {
        {"core", {}, {}},
        // The shader text both APIs compile: preprocessor, defines, stages, the dump, the light limit.
        {"shading", {"core"}, {}},
        {"gl", {"core", "shading"}, {}},
        {"gl/backends", {"core", "shading", "gl"}, {}},
        // The Vulkan platform stands beside gl/ on shading/: nothing of GL's.
        {"vk", {"core", "shading"}, {}},
        {"scenes", {"core"}, {}},
        {"techniques", {"core", "shading", "scenes"}, {}},
        {"techniques/gl", glContract, {"common"}},
        {"techniques/vulkan", vulkanContract, {"common"}},
        // A technique's folder: its declaration (neutral), its GL form and its Vulkan form; the
        // vulkan-gl rule keeps the Vulkan form's includes free of GL.
        {"techniques/*", plus(glContract, {"vk", "techniques/vulkan"}), {"common"}},
        // The judge: like a technique's folder, a GL and a Vulkan form, and each API's G-buffer.
        {"reference", plus(glContract, {"vk", "techniques/vulkan"}), {"reference", "common"}},
        // The one table of techniques, above every technique folder and the reference.
        {"registry", plus(plus(glContract, {"vk", "techniques/vulkan", "techniques/*"}), {"reference"}), {}},
        // bench's libraries, in one order: output < options, statistics < harness < rows < measure < ...
        {"bench/lib/output", {"core", "shading", "gl"}, {}},
        {"bench/lib/statistics", {"core"}, {}},
        {"bench/lib/callgrind", {"core"}, {}},
        {"bench/lib/options", lib({"output"}), {}},
        // The one bitmap font, of the pictures and of the viewer's overlay.
        {"bench/lib/font", lib({"output"}), {}},
        {"bench/lib/images", lib({"output", "font"}), {}},
        {"bench/lib/harness", lib({"output", "options", "statistics"}), {"calibrate", "common"}},
        {"bench/lib/rows", lib({"output", "options", "statistics", "harness"}), {}},
        {"bench/lib/measure", lib({"output", "options", "statistics", "harness", "rows"}), {}},
        // `-t auto`: the calibration runs frames through the harness and judges them like accuracy.
        {"bench/lib/select", lib({"output", "options", "statistics", "harness", "rows", "measure"}), {}},
        {"bench/lib/viewer",
         lib({"output", "font", "options", "statistics", "harness"}),
         {"viewer", "common"}},
        {"bench/lib/sweep", lib({"output", "options", "statistics", "harness", "rows", "measure"}), {}},
        {"bench/lib/bottleneck", lib({"output", "options", "statistics", "sweep"}), {}},
        // The performance gate: the suite, its runner and layers (work, instructions, wall time).
        {"bench/lib/gate", lib({"output", "options", "statistics", "sweep", "callgrind"}), {}},
        // Bisection: builds commits in a worktree and measures them as the gate's layers do.
        {"bench/lib/bisect", lib({"output", "options", "statistics", "sweep", "callgrind", "gate"}), {}},
        // One folder per subcommand, each on the libraries only (never on another subcommand).
        {"bench/run",
         lib({"output", "options", "statistics", "harness", "rows", "measure", "select", "viewer", "images"}),
         {"common"}},
        {"bench/explain",
         lib({"output", "options", "statistics", "harness", "rows", "measure", "select"}),
         {}},
        // Each pass against its floor: the harness's census and frames, callgrind's dumps read back.
        {"bench/floors", lib({"output", "options", "statistics", "callgrind", "harness", "select"}), {}},
        {"bench/merge", lib({"output", "options"}), {}},
        {"bench/export", lib({"output", "options"}), {}},
        {"bench/sweep", lib({"output", "options", "sweep"}), {}},
        {"bench/bottleneck", lib({"output", "options", "sweep", "bottleneck"}), {}},
        {"bench/figures", lib({"output", "options", "sweep", "bottleneck"}), {}},
        // The matrix resolves its `auto` cells as a run does and draws its differences as images.
        {"bench/golden",
         lib({"output", "options", "statistics", "harness", "rows", "measure", "select", "images"}),
         {}},
        {"bench/ci", lib({"output", "options", "statistics", "sweep", "callgrind", "gate"}), {}},
        {"bench/compare", lib({"output", "options", "statistics", "gate"}), {}},
        {"bench/bisect",
         lib({"output", "options", "statistics", "sweep", "callgrind", "gate", "bisect"}),
         {}},
        {"bench/report", lib({"output", "options", "sweep"}), {}},
        // The dispatcher: every subcommand and the libraries.
        {"bench",
         plus(lib({"output", "options", "statistics", "harness", "rows", "measure", "sweep"}),
              {"bench/run", "bench/explain", "bench/floors", "bench/merge", "bench/export", "bench/sweep",
               "bench/bottleneck", "bench/figures", "bench/golden", "bench/ci", "bench/compare",
               "bench/report", "bench/bisect"}),
         {"common"}},
        // The comparison programs. handloop runs bench's harness beside a hand-written loop;
        // handshadow is the other end of a comparison and shares no harness code: the scene model only.
        {"bench/handwritten/handloop", lib({"output", "options", "statistics", "harness"}), {"common"}},
        {"bench/handwritten/handshadow", {"core", "scenes"}, {}},
        // The libFuzzer targets call parsers from scenes/ up to bench/lib/sweep; nothing includes them.
        {"fuzz", lib({"output", "options", "statistics", "harness", "rows", "measure", "sweep"}), {}},
    };
    return kLayers;
}

/// The layer a folder belongs to: "techniques/<name>" is "techniques/*" unless it is a contract folder.
inline std::string layerOf(const std::string& folder) {
    static const std::regex technique("techniques/([A-Za-z0-9_]+)");
    std::smatch m;
    if (std::regex_match(folder, m, technique) && m[1] != "gl" && m[1] != "vulkan") return "techniques/*";
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
    const std::vector<std::string>& allowed = rules->mayInclude;
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

/// A file of a Vulkan form: vk/, techniques/vulkan/, a technique folder's *Vulkan.{h,cpp}, or a
/// reference/ file naming Vulkan (ReferenceVulkan, VulkanGBufferRenderer).
inline bool isVulkanFile(const std::string& file) {
    const std::string folder = folderOf(file);
    const std::string name = fs::path(file).stem().string();
    return folder == "vk" || folder == "techniques/vulkan" ||
           (layerOf(folder) == "techniques/*" && name.size() > 6 &&
            name.compare(name.size() - 6, 6, "Vulkan") == 0) ||
           (folder == "reference" && name.find("Vulkan") != std::string::npos);
}

/// What a GL header is: a file of the GL layers, or a system header of GL's (epoxy, EGL, GL, GLFW).
inline bool isGlFolder(const std::string& folder) {
    return folder == "gl" || folder == "gl/backends" || folder == "techniques/gl";
}

/// The includes of the checked C++ files, each with its line: the repository headers that exist under the
/// root (quoted) and whether the file includes a GL system header itself.
struct IncludeGraph {
    std::map<std::string, std::vector<std::pair<int, std::string>>> quoted;
    std::map<std::string, int> glSystem; ///< file -> line of its first GL system include
};

inline void addIncludes(const fs::path& root, const std::string& file, const std::vector<std::string>& lines,
                        IncludeGraph& graph) {
    static const std::regex quoted(R"(^\s*#\s*include\s+"([^"]+)\")");
    static const std::regex glSystem(R"(^\s*#\s*include\s+<(epoxy|EGL|GL|GLFW)/)");
    auto& list = graph.quoted[file];
    for (size_t i = 0; i < lines.size(); ++i) {
        std::smatch m;
        if (std::regex_search(lines[i], m, quoted) && fs::is_regular_file(root / m[1].str()))
            list.emplace_back(int(i) + 1, m[1].str());
        else if (std::regex_search(lines[i], glSystem) && !graph.glSystem.count(file))
            graph.glSystem[file] = int(i) + 1;
    }
}

/// The chain from `file` to the first GL header it reaches ("a.h -> gl/Context.h"), "" when none.
inline std::string glChain(const IncludeGraph& graph, const std::string& file, std::set<std::string>& seen) {
    if (!seen.insert(file).second) return "";
    if (isGlFolder(folderOf(file))) return file;
    if (graph.glSystem.count(file)) return file + " -> a GL system header";
    auto it = graph.quoted.find(file);
    if (it == graph.quoted.end()) return "";
    for (const auto& [line, target] : it->second)
        if (std::string chain = glChain(graph, target, seen); !chain.empty()) return file + " -> " + chain;
    return "";
}

inline void checkVulkanReachesNoGl(const IncludeGraph& graph, const std::string& file,
                                   std::vector<Violation>& out) {
    if (auto own = graph.glSystem.find(file); own != graph.glSystem.end()) {
        out.push_back({file, own->second, "vulkan-gl", "Vulkan code includes a GL system header"});
        return;
    }
    auto it = graph.quoted.find(file);
    if (it == graph.quoted.end()) return;
    for (const auto& [line, target] : it->second) {
        std::set<std::string> seen{file};
        const std::string chain = glChain(graph, target, seen);
        if (chain.empty()) continue;
        out.push_back({file, line, "vulkan-gl", "Vulkan code reaches GL: " + chain});
        return; // one report per file: the first include that leads there
    }
}

} // namespace detail

/// Checks the tree at `root`; `skip` lists relative paths (files or folders) left out, such as a fixture.
inline std::vector<Violation> check(const fs::path& root, const std::vector<std::string>& skip = {}) {
    std::vector<Violation> out;
    detail::IncludeGraph graph;
    std::vector<std::string> vulkanFiles;
    for (const std::string& file : detail::listFiles(root, skip)) {
        const bool test = detail::startsWith(file, "tests/");
        const bool cpp = detail::isCpp(file);
        if (!detail::isText(file)) continue;
        const std::vector<std::string> lines = detail::readLines(root / file);
        if (cpp && !test && file.find('/') != std::string::npos) {
            detail::checkIncludes(file, lines, out);
            detail::checkShaderNames(file, lines, out);
            detail::addIncludes(root, file, lines, graph);
            if (detail::isVulkanFile(file)) vulkanFiles.push_back(file);
        }
        if (detail::isShader(file) && detail::startsWith(file, "shaders/"))
            detail::checkShaderIncludes(file, lines, out);
        detail::checkOutsideReferences(file, lines, out);
    }
    for (const std::string& file : vulkanFiles) detail::checkVulkanReachesNoGl(graph, file, out);
    std::stable_sort(out.begin(), out.end(), [](const Violation& a, const Violation& b) {
        return a.file != b.file ? a.file < b.file : a.line < b.line;
    });
    return out;
}

} // namespace sb::layout
