#include "bench/lib/viewer/Viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <GLFW/glfw3.h>
#include <glm/gtc/constants.hpp>

#include "bench/lib/output/RowExport.h"
#include "bench/lib/viewer/InputQueue.h"
#include "bench/lib/viewer/Overlay.h"
#include "bench/lib/viewer/RollingMedian.h"
#include "bench/lib/viewer/VisibilityView.h"

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

// Zoom per key event (a press, or each auto-repeat while held) and per wheel step.
constexpr float kKeyZoom = 0.95f;
constexpr double kWheelZoom = 0.9;

std::string fixed2(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", v);
    return text;
}
} // namespace

int Viewer::run(Harness& harness, std::vector<std::unique_ptr<GlTechnique>>& techniques, int maxFrames) {
    if (techniques.empty()) return 0;
    auto* window = static_cast<GLFWwindow*>(harness.context().nativeWindow());
    const RunConfig& config = harness.config();
    std::ostream& log = config.format == RowFormat::Console ? std::cout : std::cerr;
    // The verdict a measurement of this configuration would report (ConsoleReport prints the same one).
    if (config.checkTimer) harness.calibrateTimer();

    InputQueue input(window);
    Overlay overlay(harness.programs());
    VisibilityView visibilityView(harness.programs());
    const CameraPreset preset = harness.camera();
    Orbit orbit = Orbit::from(preset);
    const int lightCount = int(harness.scene().lights.size());
    const int visibleLights = std::clamp(lightCount, 1, kMaxLights); // channels worth showing
    size_t current = 0;
    std::vector<bool> prepared(techniques.size(), false);
    bool showVisibility = false, quit = false;
    int light = 0;
    RollingMedian wall(kMedianFrames), cpu(kMedianFrames);
    size_t announcedTechnique = techniques.size(); // none yet
    std::string announcedView;
    double lastX = 0, lastY = 0;
    glfwGetCursorPos(window, &lastX, &lastY);
    int frames = 0;
    while (!quit && !harness.context().shouldClose() && (maxFrames <= 0 || frames < maxFrames)) {
        const size_t before = current;
        for (const KeyEvent& e : input.takeKeys()) {
            if (e.action == GLFW_RELEASE) continue;
            const bool press = e.action == GLFW_PRESS;
            const size_t n = techniques.size();
            if (e.key == GLFW_KEY_ESCAPE && press) quit = true;
            if (e.key == GLFW_KEY_TAB && press)
                current = (e.mods & GLFW_MOD_SHIFT) ? (current + n - 1) % n : (current + 1) % n;
            for (int k = 0; k < 9; ++k)
                if (press && (e.key == GLFW_KEY_1 + k || e.key == GLFW_KEY_KP_1 + k) && size_t(k) < n)
                    current = size_t(k);
            if (e.key == GLFW_KEY_V && press) showVisibility = !showVisibility;
            if (e.key == GLFW_KEY_L && press) light = (light + 1) % visibleLights;
            if (e.key == GLFW_KEY_R && press) orbit = Orbit::from(preset);
            if (e.key == GLFW_KEY_EQUAL || e.key == GLFW_KEY_KP_ADD) orbit.distance *= kKeyZoom;
            if (e.key == GLFW_KEY_MINUS || e.key == GLFW_KEY_KP_SUBTRACT) orbit.distance /= kKeyZoom;
        }
        if (quit) break;
        if (current != before) {
            wall.clear(); // the medians describe one technique
            cpu.clear();
        }
        double x, y;
        glfwGetCursorPos(window, &x, &y);
        if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) { // a drag is a state: polled
            orbit.yaw -= float(x - lastX) * 0.005f;
            orbit.pitch += float(y - lastY) * 0.005f;
        }
        lastX = x;
        lastY = y;
        orbit.distance *= float(std::pow(kWheelZoom, input.takeScroll()));
        harness.setCamera(orbit.apply(preset));
        GlTechnique& technique = *techniques[current];
        if (!prepared[current]) { // untimed, as in a measurement
            harness.prepare(technique);
            prepared[current] = true;
        }

        const FrameSample s = harness.renderFrame(technique);
        wall.add(s.wallMs);
        cpu.add(s.cpuSubmitMs);

        // The harness must not distort what it measures: everything below runs after the frame's wall
        // time was taken, draws only into the default framebuffer (the visibility view and the overlay
        // after the blit), never into the frame targets, which keep what the technique drew
        // (--screenshot after the viewer reads them), and leaves the GL state as it found it.
        int fw, fh;
        glfwGetFramebufferSize(window, &fw, &fh);
        FrameTargets& t = harness.targets();
        if (showVisibility) {
            visibilityView.draw(t, light, fw, fh);
        } else {
            glNamedFramebufferReadBuffer(t.fbo(), GL_COLOR_ATTACHMENT0);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glBlitNamedFramebuffer(t.fbo(), 0, 0, 0, t.width(), t.height(), 0, 0, fw, fh, GL_COLOR_BUFFER_BIT,
                                   GL_LINEAR);
        }
        const std::string properties = technique.properties().toString();
        const std::string view =
            showVisibility ? "visibility of light " + std::to_string(light + 1) : "colour";
        const std::string times = "wall " + fixed2(wall.median()) + " ms  cpu submit " +
                                  fixed2(cpu.median()) + " ms  (median of " + std::to_string(wall.count()) +
                                  ")";
        overlay.draw(fw, fh,
                     {technique.name(),
                      "properties: " + (properties.empty() ? std::string("none") : properties), times,
                      std::string("GPU timer: ") + harness.timerVerdict().label(),
                      "lights: " + std::to_string(lightCount), "view: " + view},
                     showVisibility);
        const std::string title = "shadowbench: " + technique.name() +
                                  (showVisibility ? " (visibility)" : "") + "  " + times +
                                  "  [Tab/1-9 technique, V visibility, drag orbit]";
        glfwSetWindowTitle(window, title.c_str());
        harness.context().present();
        // The swap and the overlay's draws finish here, not inside the next frame's wall time.
        glFinish();
        ++frames;
        if (!config.quiet) {
            if (current != announcedTechnique) {
                announcedTechnique = current;
                log << "viewer: technique " << technique.name() << std::endl;
            }
            if (view != announcedView) log << "viewer: view " << (announcedView = view) << std::endl;
        }
    }
    return 0;
}

} // namespace sb
