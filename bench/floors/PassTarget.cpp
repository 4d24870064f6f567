#include "bench/floors/PassTarget.h"

#include <cstdio>

namespace sb {

namespace {

struct Attachment {
    GLenum format = GL_NONE;
    int width = 0, height = 0;
};

/// The internal format and size of what `attachment` of `fbo` holds (GL_NONE: nothing attached).
Attachment readAttachment(GLuint fbo, GLenum attachment) {
    Attachment a;
    GLint type = GL_NONE, name = 0, level = 0;
    glGetNamedFramebufferAttachmentParameteriv(fbo, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type == GL_NONE) return a;
    glGetNamedFramebufferAttachmentParameteriv(fbo, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    GLint format = 0;
    if (type == GL_RENDERBUFFER) {
        glGetNamedRenderbufferParameteriv(GLuint(name), GL_RENDERBUFFER_INTERNAL_FORMAT, &format);
        glGetNamedRenderbufferParameteriv(GLuint(name), GL_RENDERBUFFER_WIDTH, &a.width);
        glGetNamedRenderbufferParameteriv(GLuint(name), GL_RENDERBUFFER_HEIGHT, &a.height);
    } else {
        glGetNamedFramebufferAttachmentParameteriv(fbo, attachment, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL,
                                                   &level);
        glGetTextureLevelParameteriv(GLuint(name), level, GL_TEXTURE_INTERNAL_FORMAT, &format);
        glGetTextureLevelParameteriv(GLuint(name), level, GL_TEXTURE_WIDTH, &a.width);
        glGetTextureLevelParameteriv(GLuint(name), level, GL_TEXTURE_HEIGHT, &a.height);
    }
    a.format = GLenum(format);
    return a;
}

bool hasStencil(GLenum format) {
    return format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8 || format == GL_STENCIL_INDEX8;
}

std::string lastPart(const std::string& pass) {
    const size_t dot = pass.rfind('.');
    return dot == std::string::npos ? pass : pass.substr(dot + 1);
}

} // namespace

const char* passKindName(PassKind kind) {
    switch (kind) {
    case PassKind::Depth:
        return "depth";
    case PassKind::Stencil:
        return "stencil";
    case PassKind::Lit:
        return "lit";
    case PassKind::Texture:
        return "texture";
    case PassKind::Filtered:
        return "filtered";
    }
    return "?";
}

std::string formatName(GLenum format) {
    struct Name {
        GLenum format;
        const char* name;
    };
    static constexpr Name kNames[] = {
        {GL_RGBA8, "RGBA8"},
        {GL_RGBA16F, "RGBA16F"},
        {GL_RGBA32F, "RGBA32F"},
        {GL_R8, "R8"},
        {GL_RG8, "RG8"},
        {GL_R16F, "R16F"},
        {GL_R32F, "R32F"},
        {GL_RG16F, "RG16F"},
        {GL_RG32F, "RG32F"},
        {GL_R32UI, "R32UI"},
        {GL_DEPTH_COMPONENT16, "DEPTH_COMPONENT16"},
        {GL_DEPTH_COMPONENT24, "DEPTH_COMPONENT24"},
        {GL_DEPTH_COMPONENT32, "DEPTH_COMPONENT32"},
        {GL_DEPTH_COMPONENT32F, "DEPTH_COMPONENT32F"},
        {GL_DEPTH24_STENCIL8, "DEPTH24_STENCIL8"},
        {GL_DEPTH32F_STENCIL8, "DEPTH32F_STENCIL8"},
        {GL_STENCIL_INDEX8, "STENCIL_INDEX8"},
    };
    for (const Name& n : kNames)
        if (n.format == format) return n.name;
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04x", unsigned(format));
    return hex;
}

PassTarget PassTarget::current() {
    PassTarget t;
    GLint fbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
    t.fbo = GLuint(fbo);
    if (t.fbo == 0) {
        t.unusable = "the default framebuffer (no floor target of its formats)";
        return t;
    }
    GLint maxDrawBuffers = 0;
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxDrawBuffers);
    for (GLint i = 0; i < maxDrawBuffers; ++i) {
        GLint buffer = GL_NONE;
        glGetIntegerv(GL_DRAW_BUFFER0 + i, &buffer);
        if (buffer < GLint(GL_COLOR_ATTACHMENT0) || buffer > GLint(GL_COLOR_ATTACHMENT15)) continue;
        const Attachment a = readAttachment(t.fbo, GLenum(buffer));
        if (a.format == GL_NONE) continue;
        t.colourFormats.push_back(a.format);
        t.width = a.width;
        t.height = a.height;
    }
    Attachment depth = readAttachment(t.fbo, GL_DEPTH_ATTACHMENT);
    if (depth.format == GL_NONE) depth = readAttachment(t.fbo, GL_STENCIL_ATTACHMENT);
    if (depth.format != GL_NONE) {
        t.depthFormat = depth.format;
        t.stencil = hasStencil(depth.format);
        t.width = depth.width;
        t.height = depth.height;
    }
    if (t.width <= 0 || t.height <= 0) t.unusable = "a target whose attachments' size GL does not report";
    return t;
}

PassKind PassTarget::kindOf(const std::string& pass, GLuint frameTargetsFbo) const {
    const std::string name = lastPart(pass);
    if (colourFormats.empty()) return PassKind::Depth;
    if (name == "mark" && stencil) return PassKind::Stencil;
    if (name == "blur") return PassKind::Filtered;
    return fbo == frameTargetsFbo ? PassKind::Lit : PassKind::Texture;
}

std::string PassTarget::text() const {
    std::string out = std::to_string(width) + "x" + std::to_string(height) + " ";
    std::string formats;
    for (GLenum f : colourFormats) formats += (formats.empty() ? "" : "+") + formatName(f);
    if (depthFormat != GL_NONE) formats += (formats.empty() ? "" : "+") + formatName(depthFormat);
    return out + (formats.empty() ? "none" : formats);
}

bool PassTarget::sameFormats(const PassTarget& o) const {
    return width == o.width && height == o.height && colourFormats == o.colourFormats &&
           depthFormat == o.depthFormat;
}

} // namespace sb
