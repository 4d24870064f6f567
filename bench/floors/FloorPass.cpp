#include "bench/floors/FloorPass.h"

#include <string>

#include "bench/floors/FloorLayout.h"
#include "core/Error.h"
#include "gl/TextureFramebuffer.h"
#include "techniques/gl/FrameState.h"

namespace sb {

namespace {

// The floor's programs are a few lines each and belong to no technique. The vertex stage draws one
// triangle over the whole target, its edges well outside it; the scissor box cuts each rectangle of the
// layout out of it. One triangle, not two per rectangle: llvmpipe shades and counts fragments in 4x4
// blocks per triangle, and the shared diagonal of a two-triangle rectangle shades every block it
// crosses twice (measured: 1024 fragment-shader invocations for 800 pixels on a 48x32 target); an edge
// on the target's left or bottom border added one more block per draw (16 for a 4x4 rectangle).
constexpr const char* kVertex = R"(#version 450 core
void main() {
    gl_Position = vec4(gl_VertexID == 1 ? 7.0 : -3.0, gl_VertexID == 2 ? 7.0 : -3.0, 0.0, 1.0);
}
)";

/// The floor's constant colour (any value: nothing reads it but the tests).
constexpr const char* kColour = "vec4(0.5, 0.25, 0.125, 1.0)";

std::string fragmentSource(PassKind kind, size_t outputs) {
    std::string s = "#version 450 core\n";
    if (kind == PassKind::Filtered) s += "layout(binding = 0) uniform sampler2D uSource;\n";
    for (size_t i = 0; i < outputs; ++i)
        s += "layout(location = " + std::to_string(i) + ") out vec4 o" + std::to_string(i) + ";\n";
    s += "void main() {\n";
    if (kind == PassKind::Filtered && outputs > 0)
        s += "    vec4 c = texelFetch(uSource, ivec2(gl_FragCoord.xy), 0);\n";
    for (size_t i = 0; i < outputs; ++i)
        s += "    o" + std::to_string(i) + " = " + (kind == PassKind::Filtered ? "c" : kColour) + ";\n";
    return s + "}\n";
}

GLuint compile(GLenum stage, const std::string& source) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        glDeleteShader(shader);
        throw Error(std::string("floor pass: the floor's shader does not compile: ") + log,
                    ExitCode::Failure);
    }
    return shader;
}

bool integerFormat(GLenum f) {
    return f == GL_R32UI || f == GL_R32I || f == GL_RG32UI || f == GL_RGBA32UI || f == GL_RGBA32I ||
           f == GL_R8UI || f == GL_R16UI || f == GL_RGBA8UI;
}

} // namespace

FloorPass::FloorPass(const PassTarget& like, PassKind kind)
    : mKind(kind), mWidth(like.width), mHeight(like.height) {
    if (!like.unusable.empty()) throw Error("floor pass: " + like.unusable, ExitCode::Unsupported);
    for (GLenum f : like.colourFormats)
        if (integerFormat(f))
            throw Error("floor pass: target " + like.text() + " has an integer colour format",
                        ExitCode::Unsupported);
    glCreateVertexArrays(1, &mVao);
    try {
        createTarget(like);
        createProgram(
            mFbo && (kind == PassKind::Lit || kind == PassKind::Texture || kind == PassKind::Filtered)
                ? like.colourFormats.size()
                : 0);
    } catch (...) {
        release(); // a constructor that throws runs no destructor
        throw;
    }
}

FloorPass::~FloorPass() {
    release();
}

void FloorPass::release() {
    if (mProgram) glDeleteProgram(mProgram);
    if (mFbo) glDeleteFramebuffers(1, &mFbo);
    if (!mColours.empty()) glDeleteTextures(GLsizei(mColours.size()), mColours.data());
    if (mDepth) glDeleteTextures(1, &mDepth);
    if (mSource) glDeleteTextures(1, &mSource);
    if (mVao) glDeleteVertexArrays(1, &mVao);
    mProgram = mFbo = mDepth = mSource = mVao = 0;
    mColours.clear();
}

void FloorPass::createTarget(const PassTarget& like) {
    glCreateFramebuffers(1, &mFbo);
    // A depth or stencil floor writes no colour: its target holds the pass's depth/stencil attachment
    // only, as a depth pass's map does.
    const bool colour = mKind == PassKind::Lit || mKind == PassKind::Texture || mKind == PassKind::Filtered;
    std::vector<GLenum> buffers;
    if (colour)
        for (size_t i = 0; i < like.colourFormats.size(); ++i) {
            mColours.push_back(createTexture(like.colourFormats[i], mWidth, mHeight));
            const GLenum attachment = GLenum(GL_COLOR_ATTACHMENT0 + i);
            glNamedFramebufferTexture(mFbo, attachment, mColours.back(), 0);
            buffers.push_back(attachment);
        }
    if (buffers.empty())
        glNamedFramebufferDrawBuffer(mFbo, GL_NONE);
    else
        glNamedFramebufferDrawBuffers(mFbo, GLsizei(buffers.size()), buffers.data());
    glNamedFramebufferReadBuffer(mFbo, buffers.empty() ? GL_NONE : buffers[0]);
    if (like.depthFormat != GL_NONE) {
        mDepth = createTexture(like.depthFormat, mWidth, mHeight);
        mStencil = like.stencil;
        glNamedFramebufferTexture(mFbo, like.stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                  mDepth, 0);
    }
    if (mKind == PassKind::Filtered && !like.colourFormats.empty())
        mSource = createTexture(like.colourFormats[0], mWidth, mHeight);
    const GLenum status = glCheckNamedFramebufferStatus(mFbo, GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error("floor pass: a target like " + like.text() + " is incomplete (status " +
                        formatName(status) + ")",
                    ExitCode::Unsupported);
    if ((mKind == PassKind::Depth && like.depthFormat == GL_NONE) ||
        (mKind == PassKind::Stencil && !like.stencil))
        throw Error(std::string("floor pass: a ") + passKindName(mKind) + " pass into " + like.text() +
                        ", which has no such attachment",
                    ExitCode::Unsupported);
}

void FloorPass::createProgram(size_t colourOutputs) {
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertex);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragmentSource(mKind, colourOutputs));
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    mProgram = glCreateProgram();
    glAttachShader(mProgram, vs);
    glAttachShader(mProgram, fs);
    glLinkProgram(mProgram);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(mProgram, GL_LINK_STATUS, &ok);
    if (!ok) throw Error("floor pass: the floor's program does not link", ExitCode::Failure);
}

void FloorPass::setState() const {
    resetFrameState();
    glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
    glViewport(0, 0, mWidth, mHeight);
    glDisable(GL_SCISSOR_TEST); // the clears below cover the whole target
    // Every fragment passes every test and writes what the kind writes.
    glDepthFunc(GL_ALWAYS);
    switch (mKind) {
    case PassKind::Depth:
        glClear(GL_DEPTH_BUFFER_BIT);
        break;
    case PassKind::Stencil:
        glDepthMask(GL_FALSE);
        glEnable(GL_STENCIL_TEST);
        glStencilMask(0xff);
        glStencilFunc(GL_ALWAYS, 0, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
        glClear(GL_STENCIL_BUFFER_BIT);
        break;
    case PassKind::Texture:
        glClear(GL_COLOR_BUFFER_BIT | (mDepth ? GL_DEPTH_BUFFER_BIT : 0));
        break;
    case PassKind::Lit:
    case PassKind::Filtered:
        break;
    }
    if (!mDepth) glDisable(GL_DEPTH_TEST);
    if (mSource) glBindTextureUnit(0, mSource);
    glUseProgram(mProgram);
    glBindVertexArray(mVao);
}

void FloorPass::draw(uint64_t fragments) {
    setState();
    glEnable(GL_SCISSOR_TEST);
    for (const FloorRect& r : FloorLayout::of(fragments, mWidth, mHeight)) {
        glScissor(r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);
        for (uint64_t i = 0; i < r.repeat; ++i) glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(0);
    glUseProgram(0);
    if (mSource) glBindTextureUnit(0, 0);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    resetFrameState();
}

PassTarget FloorPass::target() const {
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, mFbo);
    PassTarget t = PassTarget::current();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previous));
    return t;
}

} // namespace sb
