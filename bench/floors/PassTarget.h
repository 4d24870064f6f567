#pragma once
// What a pass drew into, read from GL at the pass's end (bench/floors/PassProbe.h): the bound draw
// framebuffer's size, the formats of the colour attachments it writes (its enabled draw buffers) and
// of its depth/stencil attachment, and the kind of pass that follows from them. A floor
// (bench/floors/FloorPass.h) draws into a target of the same size and formats.
#include <cstdint>
#include <string>
#include <vector>

#include <epoxy/gl.h>

namespace sb {

/// The kinds of pass a floor stands for, each with its own minimal output (FloorPass.h):
///   depth     no colour written, depth written (a shadow map's depth pass)
///   stencil   stencil written only (shadow volumes' mark pass)
///   lit       colour into the harness's frame targets (a lighting pass)
///   texture   colour into a texture of the technique's own (projective's texture, a moment map)
///   filtered  a texture pass that reads a texture per fragment (a blur)
enum class PassKind { Depth, Stencil, Lit, Texture, Filtered };

const char* passKindName(PassKind kind);

struct PassTarget {
    GLuint fbo = 0;
    int width = 0, height = 0;
    std::vector<GLenum> colourFormats; ///< internal formats of the written colour attachments, in order
    GLenum depthFormat = GL_NONE;      ///< internal format of the depth (or depth-stencil) attachment
    bool stencil = false;              ///< the depth attachment has stencil bits
    /// Why no floor can be drawn for it ("" when one can): the default framebuffer, an attachment
    /// whose format cannot be read.
    std::string unusable;

    /// The target bound for drawing now (GL_DRAW_FRAMEBUFFER_BINDING and its enabled draw buffers).
    static PassTarget current();
    /// The pass's kind: from the target (nothing written but depth: depth; the frame targets: lit;
    /// another colour target: texture; `frameTargetsFbo` is the harness's FBO) and, where the target cannot
    /// tell, from the pass's name (`mark` writes stencil into the frame targets; `blur` is a filtered texture
    /// pass). A hybrid's "part.pass" names are read by their last part.
    PassKind kindOf(const std::string& pass, GLuint frameTargetsFbo) const;
    /// "1024x1024 RGBA8+DEPTH24_STENCIL8", "2048x2048 DEPTH_COMPONENT24".
    std::string text() const;
    /// The same target (size and formats), whatever the FBO.
    bool sameFormats(const PassTarget& o) const;
};

/// GL's name of an internal format without its prefix ("RGBA16F"), or its hex value.
std::string formatName(GLenum format);

} // namespace sb
