#pragma once
// Builds the source of one shader stage for both APIs' caches (gl/ProgramCache, vk/ShaderModuleCache):
// "#version 450 compatibility", the sorted
// defines, a stage define, then the file with `#include "common/x.glsl"` lines expanded (paths relative
// to the shader root, each file included once per stage, like #pragma once). Every file gets a GLSL
// source-string number through `#line LINE FILE_INDEX`, so a compile log line such as
// "1:12(5): error: ..." maps back to "common/x.glsl:12:5: error: ...". vk/ShaderModuleCache sets the
// version line to "#version 450" (core profile, for glslang targeting Vulkan).
#include <set>
#include <string>
#include <vector>

#include "shading/Defines.h"
#include "shading/ShaderStage.h"

namespace sb {

class ShaderPreprocessor {
public:
    explicit ShaderPreprocessor(std::string root) : mRoot(std::move(root)) {}

    /// The first line of every built source, newline included; "#version 450 compatibility\n" unless set.
    void setVersionLine(std::string line) { mVersionLine = std::move(line); }

    /// Throws sb::Error naming the missing file (and which file:line included it) or a bad define name.
    std::string build(const std::string& file, const Defines& defines, ShaderStage stage);
    /// Source-string number -> path relative to the root; 0 is the main file.
    const std::vector<std::string>& files() const { return mFiles; }
    /// Rewrites driver log lines "N:LINE(COL): msg" (Mesa) and "N(LINE) : msg" (NVIDIA) as
    /// "path:LINE:COL: msg" / "path:LINE: msg", and glslang's "ERROR: N:LINE: msg" / "WARNING: N:LINE: msg"
    /// as "path:LINE: error: msg" / "path:LINE: warning: msg"; other lines are kept as they are.
    std::string mapLog(const std::string& log) const;

private:
    void expand(const std::string& file, const std::string& includedFrom, std::string& out);
    std::string readFile(const std::string& file, const std::string& includedFrom) const;

    std::string mRoot;
    std::string mVersionLine = "#version 450 compatibility\n";
    std::vector<std::string> mFiles;
    std::set<std::string> mIncluded;
};

} // namespace sb
