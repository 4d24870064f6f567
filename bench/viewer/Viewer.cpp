#include "bench/viewer/Viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include <GLFW/glfw3.h>
#include <glm/gtc/constants.hpp>

namespace sb {

namespace {
// Orbit around the preset's target, starting from the preset's eye.
struct Orbit {
    glm::vec3 target{0.0f};
    float yaw = 0.0f, pitch = 0.0f, distance = 1.0f;

    static Orbit from(const CameraPreset& c) {
        Orbit o;
        o.target = c.target;
        glm::vec3 d = c.eye - c.target;
        o.distance = std::max(glm::length(d), 1e-3f);
        o.yaw = std::atan2(d.x, d.z);
        o.pitch = std::asin(std::clamp(d.y / o.distance, -1.0f, 1.0f));
        return o;
    }
    CameraPreset apply(CameraPreset c) const {
        float p = std::clamp(pitch, -1.55f, 1.55f);
        c.eye = target +
                distance * glm::vec3(std::cos(p) * std::sin(yaw), std::sin(p), std::cos(p) * std::cos(yaw));
        c.target = target;
        c.up = {0.0f, 1.0f, 0.0f};
        return c;
    }
};

double gScroll = 0.0;
void onScroll(GLFWwindow*, double, double dy) {
    gScroll += dy;
}

// Key edge detection: true once per press.
bool pressed(GLFWwindow* w, int key, std::set<int>& down) {
    bool isDown = glfwGetKey(w, key) == GLFW_PRESS;
    bool edge = isDown && !down.count(key);
    if (isDown)
        down.insert(key);
    else
        down.erase(key);
    return edge;
}
} // namespace

int Viewer::run(Harness& harness, std::vector<std::unique_ptr<Technique>>& techniques, int maxFrames) {
    auto* window = static_cast<GLFWwindow*>(harness.context().nativeWindow());
    glfwSetScrollCallback(window, onScroll);
    const CameraPreset preset = harness.camera();
    Orbit orbit = Orbit::from(preset);
    size_t current = 0;
    std::vector<bool> prepared(techniques.size(), false);
    bool showVisibility = false;
    std::set<int> down;
    double lastX = 0, lastY = 0, wallEma = 0, cpuEma = 0;
    glfwGetCursorPos(window, &lastX, &lastY);
    int frames = 0;
    while (!harness.context().shouldClose() && (maxFrames <= 0 || frames < maxFrames)) {
        if (!prepared[current]) {
            harness.prepare(*techniques[current]);
            prepared[current] = true;
        }
        if (pressed(window, GLFW_KEY_ESCAPE, down)) break;
        if (pressed(window, GLFW_KEY_TAB, down)) current = (current + 1) % techniques.size();
        for (int k = 0; k < 9 && k < int(techniques.size()); ++k)
            if (pressed(window, GLFW_KEY_1 + k, down)) current = size_t(k);
        if (pressed(window, GLFW_KEY_V, down)) showVisibility = !showVisibility;
        if (pressed(window, GLFW_KEY_R, down)) orbit = Orbit::from(preset);
        if (glfwGetKey(window, GLFW_KEY_EQUAL) == GLFW_PRESS) orbit.distance *= 0.98f;
        if (glfwGetKey(window, GLFW_KEY_MINUS) == GLFW_PRESS) orbit.distance *= 1.02f;
        double x, y;
        glfwGetCursorPos(window, &x, &y);
        if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) {
            orbit.yaw -= float(x - lastX) * 0.005f;
            orbit.pitch += float(y - lastY) * 0.005f;
        }
        lastX = x;
        lastY = y;
        orbit.distance *= float(std::pow(0.9, gScroll));
        gScroll = 0.0;
        harness.setCamera(orbit.apply(preset));
        if (!prepared[current]) continue; // switched: prepare on the next iteration

        FrameSample s = harness.renderFrame(*techniques[current]);
        wallEma = wallEma == 0 ? s.wallMs : 0.9 * wallEma + 0.1 * s.wallMs;
        cpuEma = cpuEma == 0 ? s.cpuSubmitMs : 0.9 * cpuEma + 0.1 * s.cpuSubmitMs;
        int fw, fh;
        glfwGetFramebufferSize(window, &fw, &fh);
        FrameTargets& t = harness.targets();
        glNamedFramebufferReadBuffer(t.fbo(), showVisibility ? GL_COLOR_ATTACHMENT1 : GL_COLOR_ATTACHMENT0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glBlitNamedFramebuffer(t.fbo(), 0, 0, 0, t.width(), t.height(), 0, 0, fw, fh, GL_COLOR_BUFFER_BIT,
                               GL_LINEAR);
        glNamedFramebufferReadBuffer(t.fbo(), GL_COLOR_ATTACHMENT0);
        char title[256];
        std::snprintf(title, sizeof title,
                      "shadowbench: %s%s  wall %.2f ms  cpu submit %.2f ms  [Tab/1-9 technique, V "
                      "visibility, drag orbit]",
                      techniques[current]->name().c_str(), showVisibility ? " (visibility)" : "", wallEma,
                      cpuEma);
        glfwSetWindowTitle(window, title);
        harness.context().present();
        ++frames;
    }
    return 0;
}

} // namespace sb
