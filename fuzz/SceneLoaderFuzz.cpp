// libFuzzer target: sb::SceneLoader::parse over arbitrary scene JSON (scenes/SceneLoader.h). Bad input
// must end in sb::Error; anything else (another exception, a sanitizer report, a hang past -timeout, more
// memory than -rss_limit_mb) is a bug. Seeds: fuzz/corpus/scene_loader/ (the built-in scenes and the
// tests' scenes); dictionary: fuzz/scene_loader.dict.
//
// In memory only: the scene's directory does not exist, so a relative model or texture path names a
// missing file (an error path of its own), and inputs whose model path could leave that directory
// (absolute, "..", a device such as /dev/zero) are skipped before the loader sees them: reading
// arbitrary files of the machine is not what is under test, and a pipe or device would hang the run.
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "fuzz/FuzzReach.h"
#include "scenes/SceneLoader.h"

namespace {

/// The scene's file name: in a directory that does not exist (see the header comment).
const char* const kSourceName = "/nonexistent-sb-fuzz/scene.json";

/// A plain file name (letters, digits, '_', '-', '.'; not "." or ".."): it resolves next to the
/// missing scene file, never elsewhere.
bool isPlainName(const std::string& name) {
    if (name.empty() || name == "." || name == "..") return false;
    for (char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) return false;
    return true;
}

/// Every "file" and "texture" value anywhere in the document is a plain name (or not a string, an
/// error the loader reports). Walked over the whole tree, so a key at any depth counts.
bool staysInMemory(const nlohmann::json& value, int depth = 0) {
    if (depth > 64) return true; // deeper values are no meshes the loader reads
    if (value.is_object()) {
        for (auto it = value.begin(); it != value.end(); ++it) {
            if ((it.key() == "file" || it.key() == "texture") && it.value().is_string() &&
                it.value().get<std::string>() != "auto" && !isPlainName(it.value().get<std::string>()))
                return false;
            if (!staysInMemory(it.value(), depth + 1)) return false;
        }
    } else if (value.is_array()) {
        for (const auto& element : value)
            if (!staysInMemory(element, depth + 1)) return false;
    }
    return true;
}

/// Whether the loader gets the input: its paths stay in memory (see the header comment). The loader
/// accepts // comments; so does this check.
bool worthLoading(const std::string& json) {
    try {
        return staysInMemory(nlohmann::json::parse(json, nullptr, true, /*ignore_comments=*/true));
    } catch (const nlohmann::json::exception&) {
        return true; // not JSON at all: the loader's own error, and it can name no file
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string json = sb::fuzz::text(data, size);
    if (!worthLoading(json)) return 0;

    sb::SceneOptions options;
    // Large enough for every built-in scene, small enough that a fuzzed layout count or tessellation is
    // refused by the loader's memory estimate instead of being generated.
    options.memoryLimitBytes = 256ull << 20;
    try {
        const sb::Scene scene = sb::SceneLoader::parse(json, kSourceName, options);
        sb::fuzz::reached(sb::fuzz::Outcome::Parsed, std::to_string(scene.meshes.size()) + " meshes, " +
                                                         std::to_string(scene.instances.size()) +
                                                         " instances");
    } catch (const sb::Error& e) {
        sb::fuzz::reached(sb::fuzz::Outcome::Rejected, e.what());
    }
    return 0;
}
