#pragma once
// glfw: a window (hidden unless visibleWindow) with a 4.5 compatibility context, for the viewer and for
// machines where only GLX works. Used only when asked for (--backend glfw); needs DISPLAY or
// WAYLAND_DISPLAY.
#include "gl/Context.h"

struct GLFWwindow;

namespace sb {

class GlfwContext : public Context {
public:
    /// Throws sb::Error("glfw: <reason>", ExitCode::Unsupported), e.g. when there is no display.
    explicit GlfwContext(const ContextOptions& options);
    ~GlfwContext() override;
    GlfwContext(const GlfwContext&) = delete;
    GlfwContext& operator=(const GlfwContext&) = delete;
    Backend backend() const override { return Backend::Glfw; }
    void makeCurrent() override;
    void present() override;
    bool shouldClose() const override;
    void* nativeWindow() const override { return mWindow; }

private:
    static void initializeLibrary();
    static void releaseLibrary();
    GLFWwindow* mWindow = nullptr;
};

} // namespace sb
