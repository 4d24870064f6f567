#include "gl/Context.h"

#include <epoxy/gl.h>

#include <array>

namespace sb {
namespace {

constexpr std::array kSoftwareRenderers = {"llvmpipe", "softpipe", "swrast"};

} // namespace

bool Context::isSoftwareRenderer() const {
    for (const char* name : kSoftwareRenderers)
        if (renderer.find(name) != std::string::npos) return true;
    return false;
}

bool Context::hasExtension(const std::string& name) const {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLubyte* extension = glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i));
        if (extension && name == reinterpret_cast<const char*>(extension)) return true;
    }
    return false;
}

} // namespace sb
