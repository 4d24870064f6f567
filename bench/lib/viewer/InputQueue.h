#pragma once
// The viewer's keyboard and wheel input as events (bench/lib/viewer/Viewer.h). GLFW calls back from
// glfwPollEvents with every press, repeat and release in order; the queue keeps them until the viewer
// takes them at its next frame. Polling glfwGetKey instead sees only the key's state at that moment,
// so a tap pressed and released between two slow llvmpipe frames would be lost.
#include <vector>

struct GLFWwindow;

namespace sb {

/// One GLFW key callback: GLFW_KEY_*, GLFW_PRESS / GLFW_REPEAT / GLFW_RELEASE, GLFW_MOD_* bits.
struct KeyEvent {
    int key = 0;
    int action = 0;
    int mods = 0;
};

class InputQueue {
public:
    /// Installs the key and scroll callbacks on `window` (and itself as the window's user pointer);
    /// the destructor removes them. One queue per window at a time.
    explicit InputQueue(GLFWwindow* window);
    ~InputQueue();
    InputQueue(const InputQueue&) = delete;
    InputQueue& operator=(const InputQueue&) = delete;

    /// Every key event since the last call, oldest first; the queue is empty afterwards.
    std::vector<KeyEvent> takeKeys();
    /// Wheel steps (positive: away from the user) since the last call; resets to 0.
    double takeScroll();

    /// What the callbacks do; public so that a test can feed events without a window.
    void pushKey(const KeyEvent& event) { mKeys.push_back(event); }
    void pushScroll(double dy) { mScroll += dy; }

private:
    GLFWwindow* mWindow;
    std::vector<KeyEvent> mKeys;
    double mScroll = 0.0;
};

} // namespace sb
