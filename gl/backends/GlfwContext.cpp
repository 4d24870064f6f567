#include "gl/backends/GlfwContext.h"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/Error.h"
#include "gl/backends/EpoxyOsMesaBridge.h"

namespace sb {
namespace {

int gWindowCount = 0;       // glfwTerminate destroys every window, so it waits for the last one
std::string gLastGlfwError; // glfw reports the reason through its callback, not the failing call

void recordGlfwError(int code, const char* description) {
    char codeText[16];
    std::snprintf(codeText, sizeof codeText, "0x%05x", static_cast<unsigned>(code));
    gLastGlfwError = std::string(description ? description : "") + " (GLFW error " + codeText + ")";
}

[[noreturn]] void fail(const std::string& reason) {
    throw Error("glfw: " + reason, ExitCode::Unsupported);
}

} // namespace

GlfwContext::GlfwContext(const ContextOptions& options) {
    initializeLibrary();
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_COMPAT_PROFILE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, options.visibleWindow ? GLFW_TRUE : GLFW_FALSE);
    mWindow = glfwCreateWindow(options.width, options.height, "shadowbench", nullptr, nullptr);
    if (!mWindow) {
        std::string reason = gLastGlfwError;
        releaseLibrary();
        fail("cannot create a window with an OpenGL 4.5 compatibility context: " + reason);
    }
    makeCurrent();
}

GlfwContext::~GlfwContext() {
    if (glfwGetCurrentContext() == mWindow) glfwMakeContextCurrent(nullptr);
    glfwDestroyWindow(mWindow);
    releaseLibrary();
}

void GlfwContext::makeCurrent() {
    // As in EglContext::makeCurrent: OSMesa may have replaced Mesa's dispatch behind GLX's back.
    if (glfwGetCurrentContext() == mWindow) glfwMakeContextCurrent(nullptr);
    glfwMakeContextCurrent(mWindow);
    EpoxyOsMesaBridge::restore(); // GLX/EGL contexts use epoxy's own resolution
}

void GlfwContext::present() {
    glfwSwapBuffers(mWindow);
    glfwPollEvents();
}

bool GlfwContext::shouldClose() const {
    return glfwWindowShouldClose(mWindow);
}

void GlfwContext::initializeLibrary() {
    if (gWindowCount > 0) {
        ++gWindowCount;
        return;
    }
    // Checked first: glfwInit's own message for a missing display is less direct than this one.
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY"))
        fail("no display (DISPLAY and WAYLAND_DISPLAY are unset); use a headless backend or run under "
             "xvfb-run");
    glfwSetErrorCallback(recordGlfwError);
    if (!glfwInit()) fail("glfwInit failed: " + gLastGlfwError);
    gWindowCount = 1;
}

void GlfwContext::releaseLibrary() {
    if (--gWindowCount == 0) glfwTerminate();
}

} // namespace sb
