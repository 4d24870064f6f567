#pragma once
// The floor of one pass: the least a pass of its kind must do to produce an output of the same formats
// and size with the same number of fragments, drawn with GL beside the technique's pass
// (bench/floors/FloorsCommand.h). Per kind (bench/floors/PassTarget.h):
//   depth     clears the depth target, then N fragments of an empty fragment shader, depth test ALWAYS
//             and depth writes on, no colour attachment
//   stencil   clears stencil, then N fragments that increment it (test ALWAYS), no colour, no depth writes
//   lit       N fragments writing one constant colour to every colour attachment and depth (ALWAYS)
//   texture   clears the texture, then the same as lit
//   filtered  N fragments each reading one texel (texelFetch at its own pixel) of a texture of the
//             first attachment's format and size, written to every colour attachment
// The fragments are screen-aligned rectangles (bench/floors/FloorLayout.h), each the scissor box of one
// triangle over the target: every fragment passes every test, so GL_SAMPLES_PASSED counts exactly N, and
// llvmpipe, which shades 4x4 blocks, shades each block once (N invocations where N is a multiple of 16
// on a target whose sides are multiples of 4, as its census counts always are).
#include <cstdint>
#include <memory>
#include <vector>

#include <epoxy/gl.h>

#include "bench/floors/PassTarget.h"

namespace sb {

class FloorPass {
public:
    /// A target of `like`'s size and formats (its own textures) and the kind's program. Needs a current
    /// context; throws sb::Error (Unsupported) when the target cannot be made (the formats GL refuses,
    /// an integer colour format), naming the target.
    FloorPass(const PassTarget& like, PassKind kind);
    ~FloorPass();
    FloorPass(const FloorPass&) = delete;
    FloorPass& operator=(const FloorPass&) = delete;

    /// Draws the floor of `fragments` fragments into its target and leaves GL in the state
    /// techniques/gl/FrameState.h describes (with the floor's FBO bound). Nothing waits for it: the
    /// caller times it with glFinish around it.
    void draw(uint64_t fragments);

    PassKind kind() const { return mKind; }
    GLuint fbo() const { return mFbo; }
    /// The floor's own target, read back from GL (the same formats as the pass's: checked by tests).
    PassTarget target() const;
    /// The floor's attachments: colour textures in order, then the depth/stencil texture (0 if none).
    const std::vector<GLuint>& colourTextures() const { return mColours; }
    GLuint depthTexture() const { return mDepth; }
    /// The texture a filtered floor reads, one texel at each fragment's pixel (0 for the other kinds).
    GLuint sourceTexture() const { return mSource; }

private:
    void createTarget(const PassTarget& like);
    void createProgram(size_t colourOutputs);
    void setState() const;
    void release();

    PassKind mKind;
    int mWidth, mHeight;
    bool mStencil = false;
    GLuint mFbo = 0, mDepth = 0, mSource = 0, mProgram = 0, mVao = 0;
    std::vector<GLuint> mColours;
};

} // namespace sb
