#include "bench/run/TimerTrust.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include <epoxy/gl.h>

#include "gl/FrameTargets.h"

namespace sb {

namespace {
constexpr int kSmall = 256, kLarge = 512; // 4x the pixels
constexpr int kRepeats = 3;
constexpr double kMinLargeWallMs = 15.0; // below this, fixed per-frame costs blur the ratio

struct Timing {
    double wallMs, gpuMs;
};

Timing timeFill(const FrameTargets& target, GLuint query, int iterations) {
    target.bind();
    glUniform1i(0, iterations);
    glFinish();
    auto t0 = std::chrono::steady_clock::now();
    glBeginQuery(GL_TIME_ELAPSED, query);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEndQuery(GL_TIME_ELAPSED);
    glFinish();
    auto t1 = std::chrono::steady_clock::now();
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns); // calibration only: waiting is fine here
    return {std::chrono::duration<double, std::milli>(t1 - t0).count(), double(ns) * 1e-6};
}

Timing medianTiming(const FrameTargets& target, GLuint query, int iterations) {
    std::vector<double> wall, gpu;
    for (int i = 0; i < kRepeats; ++i) {
        Timing t = timeFill(target, query, iterations);
        wall.push_back(t.wallMs);
        gpu.push_back(t.gpuMs);
    }
    std::sort(wall.begin(), wall.end());
    std::sort(gpu.begin(), gpu.end());
    return {wall[kRepeats / 2], gpu[kRepeats / 2]};
}

std::string fmt(const char* f, double a, double b, double c, double d, double e) {
    char buf[256];
    std::snprintf(buf, sizeof buf, f, a, b, c, d, e);
    return buf;
}
} // namespace

TimerVerdict TimerTrust::judge(double wallSmallMs, double wallLargeMs, double gpuSmallMs, double gpuLargeMs,
                               double pixelRatio) {
    TimerVerdict v;
    v.checked = true;
    v.wallSmallMs = wallSmallMs;
    v.wallLargeMs = wallLargeMs;
    v.gpuSmallMs = gpuSmallMs;
    v.gpuLargeMs = gpuLargeMs;
    double gpuRatio = gpuSmallMs > 0.0 ? gpuLargeMs / gpuSmallMs : 0.0;
    double wallRatio = wallSmallMs > 0.0 ? wallLargeMs / wallSmallMs : 0.0;
    double coverage = wallLargeMs > 0.0 ? gpuLargeMs / wallLargeMs : 0.0;
    bool scales = gpuRatio >= 0.5 * pixelRatio;
    bool covers = coverage >= 0.5;
    v.trusted = scales && covers;
    v.reason =
        fmt("%.0fx pixels: GPU timer %.2fx, wall %.2fx; timer covers %.0f%% of the wall time (%.2f ms)",
            pixelRatio, gpuRatio, wallRatio, 100.0 * coverage, wallLargeMs);
    if (!scales) v.reason += "; the timer does not grow with the fill work";
    if (!covers) v.reason += "; the timer misses most of the frame";
    return v;
}

TimerVerdict TimerTrust::calibrate(ProgramCache& programs) {
    GLint bits = 0;
    glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
    if (bits == 0) {
        TimerVerdict v;
        v.checked = true;
        v.reason = "GL_TIME_ELAPSED has 0 counter bits on this context";
        return v;
    }
    const Program& program = programs.get({"common/fullscreen.vert", "calibrate/fill.frag", ""}, {});
    FrameTargets small(kSmall, kSmall), large(kLarge, kLarge);
    GLuint query = 0, vao = 0;
    glGenQueries(1, &query);
    glCreateVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glDisable(GL_DEPTH_TEST);
    program.use();
    // Grow the per-pixel work until the large run is long enough to be fill-bound on this device.
    int iterations = 16;
    timeFill(large, query, iterations); // JIT the shader outside the measurement
    Timing a{}, b{};
    for (int attempt = 0; attempt < 10; ++attempt) {
        b = medianTiming(large, query, iterations);
        if (b.wallMs >= kMinLargeWallMs) break;
        iterations *= 2;
    }
    a = medianTiming(small, query, iterations);
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    glDeleteQueries(1, &query);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(0);
    return judge(a.wallMs, b.wallMs, a.gpuMs, b.gpuMs, double(kLarge * kLarge) / double(kSmall * kSmall));
}

} // namespace sb
