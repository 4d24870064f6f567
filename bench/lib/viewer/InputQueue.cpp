#include "bench/lib/viewer/InputQueue.h"

#include <utility>

#include <GLFW/glfw3.h>

namespace sb {

namespace {
InputQueue* queueOf(GLFWwindow* window) {
    return static_cast<InputQueue*>(glfwGetWindowUserPointer(window));
}
void onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
    if (InputQueue* q = queueOf(window)) q->pushKey({key, action, mods});
}
void onScroll(GLFWwindow* window, double /*dx*/, double dy) {
    if (InputQueue* q = queueOf(window)) q->pushScroll(dy);
}
} // namespace

InputQueue::InputQueue(GLFWwindow* window) : mWindow(window) {
    glfwSetWindowUserPointer(mWindow, this);
    glfwSetKeyCallback(mWindow, onKey);
    glfwSetScrollCallback(mWindow, onScroll);
}

InputQueue::~InputQueue() {
    glfwSetKeyCallback(mWindow, nullptr);
    glfwSetScrollCallback(mWindow, nullptr);
    glfwSetWindowUserPointer(mWindow, nullptr);
}

std::vector<KeyEvent> InputQueue::takeKeys() {
    return std::exchange(mKeys, {});
}

double InputQueue::takeScroll() {
    return std::exchange(mScroll, 0.0);
}

} // namespace sb
