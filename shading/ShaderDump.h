#pragma once
// `--dump-shaders DIR`: every stage a program cache (GL) or module cache (Vulkan) hands out is written,
// exactly as it goes to the compiler, to
//   DIR/<label>/<program>/<permutation>/<stage>.<ext>
// label: the technique being compiled (setLabel); program: ShaderSources::programName(); permutation:
// definesKey ("default" when empty; past 255 characters, a file name's limit, its first 238, '~' and the
// whole key's hash64); stage and ext: shading/ShaderStage.h's file names. The path names the source
// exactly (files, defines and stage determine it), so the two APIs' dumps of one configuration differ only
// in what the API's version line and `#ifdef VULKAN` blocks make of the same files.
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "shading/Defines.h"
#include "shading/ShaderSources.h"

namespace sb {

class ShaderDump {
public:
    /// The source of one stage as the cache compiles it.
    using Build = std::function<std::string(const std::string& file, ShaderStage stage)>;

    /// Dump under `directory` (created; "" stops dumping). Throws sb::Error(BadInput) naming the directory
    /// when it cannot be created.
    void setDirectory(const std::string& directory);
    bool active() const { return !mDirectory.empty(); }
    /// First path component of the dumped files (the technique name); "" = "untagged".
    void setLabel(const std::string& label) { mLabel = label; }
    /// Writes each stage of `sources` not yet written under this label, logging every path (hits too).
    void record(const ShaderSources& sources, const Defines& defines, const Build& build);
    /// The dump-relative paths recorded since the last call, in order: which sources one compile chose.
    std::vector<std::string> takeLog();
    /// "label/program/permutation/stage.ext" of one stage.
    static std::string path(const std::string& label, const ShaderSources& sources, const Defines& defines,
                            ShaderStage stage);

private:
    std::string mDirectory, mLabel;
    std::set<std::string> mWritten;
    std::vector<std::string> mLog;
};

} // namespace sb
