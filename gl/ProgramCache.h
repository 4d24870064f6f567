#pragma once
// Program cache keyed by (shader files, sorted defines) (docs/ARCHITECTURE.md, "The technique contract":
// named, listable permutations). Shader files are GLSL without a #version line; shading/ShaderPreprocessor
// prepends "#version 450 compatibility", then one "#define NAME VALUE" per define (sorted), then the file
// with `#include "common/x.glsl"` lines expanded (relative to shaders/). Compile errors throw sb::Error
// naming the shader file and the line in that file (the #line bookkeeping maps back through includes).
// With a dump directory set (bench --dump-shaders DIR), every stage of every program get() hands out is
// also written, exactly as it goes to glShaderSource, in shading/ShaderDump.h's layout.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "shading/Defines.h"
#include "shading/ShaderDump.h"
#include "shading/ShaderSources.h"
#include "shading/ShaderStage.h"

namespace sb {

/// The GL name of a stage (GL_VERTEX_SHADER ...).
GLenum glStage(ShaderStage stage);

class Program {
public:
    Program(GLuint id, std::string key) : mId(id), mKey(std::move(key)) {}
    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;
    GLuint id() const { return mId; }
    /// The permutation key (definesKey of the defines it was built with), logged in CSV rows.
    const std::string& key() const { return mKey; }
    /// Cached glGetUniformLocation (-1 when the uniform is absent or optimised out).
    GLint uniform(const char* name) const;
    void use() const { glUseProgram(mId); }

private:
    GLuint mId;
    std::string mKey;
    mutable std::map<std::string, GLint> mUniforms;
};

class ProgramCache {
public:
    /// `shaderRoot`: the shaders/ directory itself (paths in ShaderSources are relative to it);
    /// "" = the first "shaders" directory in Paths::searchRoots(), throwing sb::Error when there is none.
    explicit ProgramCache(std::string shaderRoot = "");
    /// Returns the cached program or compiles and links it. The reference stays valid until clear().
    const Program& get(const ShaderSources& sources, const Defines& defines);
    size_t size() const { return mPrograms.size(); }
    /// Number of compile+link operations so far (tests check caching).
    size_t compileCount() const { return mCompiles; }
    void clear();
    /// Full source after #version/#define/#include processing (for tests and --dump-shaders). `stage`
    /// adds "#define SB_VERTEX_SHADER 1" (SB_FRAGMENT_SHADER, SB_GEOMETRY_SHADER) after the defines.
    std::string preprocess(const std::string& file, const Defines& defines, ShaderStage stage) const;

    /// Dump every stage get() hands out under `directory` (created; "" stops dumping). Throws
    /// sb::Error(BadInput) naming the directory when it cannot be created.
    void setDumpDirectory(const std::string& directory) { mDump.setDirectory(directory); }
    /// First path component of the dumped files (the technique name); "" = "untagged".
    void setDumpLabel(const std::string& label) { mDump.setLabel(label); }
    /// While dumping: the dump-relative paths of the stages get() handed out (hits included) since the
    /// last call, in order. Tests use it to tell which sources one compile() selected.
    std::vector<std::string> takeDumpLog() { return mDump.takeLog(); }

private:
    std::string mRoot;
    ShaderDump mDump;
    std::map<std::string, std::unique_ptr<Program>> mPrograms;
    size_t mCompiles = 0;
};

} // namespace sb
