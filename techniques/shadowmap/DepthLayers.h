#pragma once
// A depth texture array that shadow maps are rendered into and compared against: GL_TEXTURE_2D_ARRAY
// (spot and directional maps, paraboloid halves) or GL_TEXTURE_CUBE_MAP_ARRAY (cube maps: layer-face
// 6 * cube + face), 24-bit depth, one framebuffer per layer(-face) and, on request, one layered
// framebuffer over the whole array (a geometry shader picks the layer with gl_Layer). Sampled with
// hardware depth compare (GL_COMPARE_REF_TO_TEXTURE, GL_LEQUAL) and bilinear filtering of the
// comparison results, as `shadowmap` does by default (`pcss` binds sampler objects over it, `shadowmap`
// may switch the texture to nearest fetch without compare). Shared by every depth-map member of the
// family (`shadowmap`, `pcss`, `cascaded`, `cubemap`, `paraboloid`); the owner's name heads its error
// messages, so each member reports as it always has.
#include <string>
#include <utility>
#include <vector>

#include <epoxy/gl.h>

namespace sb {

class DepthLayers {
public:
    /// `owner` heads the error messages ("<owner>: depth framebuffer incomplete ...").
    explicit DepthLayers(std::string owner = "omni shadow map") : mOwner(std::move(owner)) {}
    ~DepthLayers() { release(); }
    DepthLayers(const DepthLayers&) = delete;
    DepthLayers& operator=(const DepthLayers&) = delete;

    /// (Re)allocates `layers` layers of size x size of `target` (for a cube map array, layers is six
    /// times the cubes). Keeps the current storage when nothing changed; layers == 0 releases it.
    /// Throws sb::Error(Failure) when a framebuffer is incomplete.
    void allocate(GLenum target, int size, int layers, bool layered);
    void release();

    /// Binds the framebuffer of one layer (a cube map array's layer-face) and clears its depth.
    void beginLayer(int layer) const;
    /// Binds the layered framebuffer (allocate(..., layered = true)) and clears every layer's depth.
    void beginLayered() const;

    GLuint texture() const { return mTexture; }
    int size() const { return mSize; }
    int layers() const { return mLayers; }
    bool empty() const { return mTexture == 0; }

private:
    std::string mOwner;
    GLenum mTarget = 0;
    GLuint mTexture = 0;
    std::vector<GLuint> mFbos; ///< per layer
    GLuint mLayeredFbo = 0;
    int mSize = 0, mLayers = 0;
    bool mLayered = false;
};

} // namespace sb
