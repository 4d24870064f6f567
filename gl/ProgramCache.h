#pragma once
// Program cache keyed by (shader files, sorted defines) (docs/ARCHITECTURE.md, "The technique contract":
// named, listable permutations). Shader files are GLSL without a #version line; the cache prepends
// "#version 450 compatibility", then one "#define NAME VALUE" per define (sorted), then the file with
// `#include "common/x.glsl"` lines expanded (relative to shaders/). Compile errors throw sb::Error
// naming the shader file and the line in that file (the #line bookkeeping maps back through includes).
// With a dump directory set (bench --dump-shaders DIR), every stage of every program get() hands out is
// also written, exactly as it goes to glShaderSource, to
//   DIR/<label>/<program>/<permutation>/<stage>.<ext>
// label: the technique being compiled (setDumpLabel); program: its files, '/' as '-', joined by '+'
// ("common-scene.vert+shadowmap-lighting.frag"); permutation: definesKey ("default" when empty);
// stage and ext: vertex.vert, fragment.frag, geometry.geom (the extensions glslangValidator takes the
// stage from). The path names the source exactly: the files, the defines and the stage determine it.
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <epoxy/gl.h>

namespace sb {

/// Sorted NAME -> VALUE list; the key of a permutation. VALUE "" means "#define NAME 1".
using Defines = std::map<std::string, std::string>;
/// "PCF_SIZE=3,SB_INSTANCED" style key: sorted, comma separated, VALUE 1 and "" omitted.
std::string definesKey(const Defines& d);

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

struct ShaderSources {
    std::string vertex;   ///< path relative to shaders/, e.g. "shadowmap/lighting.vert"
    std::string fragment; ///< may be "" for depth-only programs
    std::string geometry; ///< optional
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
    std::string preprocess(const std::string& file, const Defines& defines, GLenum stage) const;

    /// Dump every stage get() hands out under `directory` (created; "" stops dumping). Throws
    /// sb::Error(BadInput) naming the directory when it cannot be created.
    void setDumpDirectory(const std::string& directory);
    /// First path component of the dumped files (the technique name); "" = "untagged".
    void setDumpLabel(const std::string& label) { mDumpLabel = label; }
    /// While dumping: the dump-relative paths of the stages get() handed out (hits included) since the
    /// last call, in order. Tests use it to tell which sources one compile() selected.
    std::vector<std::string> takeDumpLog();
    /// "label/program/permutation/stage.ext" of one stage (the layout above).
    static std::string dumpPath(const std::string& label, const ShaderSources& sources,
                                const Defines& defines, GLenum stage);

private:
    void dump(const ShaderSources& sources, const Defines& defines);
    std::string mRoot;
    std::string mDumpDirectory;
    std::string mDumpLabel;
    std::set<std::string> mDumped; ///< dump-relative paths already written
    std::vector<std::string> mDumpLog;
    std::map<std::string, std::unique_ptr<Program>> mPrograms;
    size_t mCompiles = 0;
};

} // namespace sb
