// handloop: measures the harness's own overhead (README "Harness overhead"). In one process and on one
// context it alternates, frame by frame (and which goes first), between
//   (a) a minimal hand-written GL loop: bind FBO, clear, update the frame UBO, one program, per
//       instance two glUniform calls and one glDrawElements, glFinish; and
//   (b) a `none` frame through the Harness (uniform upload, pass timer and KHR_debug checks, timer
//       queries where the timer is trusted, submitter),
// drawing the same instances in the same order with the same compiled program into the same targets.
// It reports both medians and the median of the paired per-frame ratios (the overhead).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <numeric>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "bench/lib/harness/Harness.h"
#include "bench/lib/options/RunOptions.h"
#include "bench/lib/statistics/Statistics.h"
#include "core/Error.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/Math.h"

using namespace sb;

namespace {
using Clock = std::chrono::steady_clock;

constexpr const char* kFooter =
    R"(handloop alternates a hand-written GL loop and bench's `none` frame on one context,
frame by frame, and prints both medians and the median of the paired ratios: the harness's overhead.
--frames is the number of pairs; the scene, size, camera, instances and backend options are bench's.

Example:
  handloop --instances 200 --size 512x512 --frames 200)";

struct MeshGpu {
    GLuint vao = 0;
    GLsizei count = 0;
};

std::vector<MeshGpu> uploadMeshes(const Scene& scene) {
    std::vector<MeshGpu> out;
    for (const Mesh& m : scene.meshes) {
        std::vector<float> v;
        for (size_t i = 0; i < m.positions.size(); ++i)
            v.insert(v.end(), {m.positions[i].x, m.positions[i].y, m.positions[i].z, m.normals[i].x,
                               m.normals[i].y, m.normals[i].z});
        GLuint vao, vbo, ibo;
        glGenVertexArrays(1, &vao);
        glBindVertexArray(vao);
        glGenBuffers(1, &vbo);
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
        glGenBuffers(1, &ibo);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * 4), m.indices.data(),
                     GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 24, nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 24, reinterpret_cast<void*>(12));
        out.push_back({vao, GLsizei(m.indices.size())});
    }
    glBindVertexArray(0);
    return out;
}

// The hand-written frame: everything a minimal application must do for the same image.
double handFrame(Harness& h, GLuint program, GLuint ubo, const FrameUniformData& data,
                 const std::vector<MeshGpu>& meshes, const std::vector<uint32_t>& order) {
    auto t0 = Clock::now();
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, ubo);
    glNamedBufferSubData(ubo, 0, sizeof data, &data);
    glBindFramebuffer(GL_FRAMEBUFFER, h.targets().fbo());
    glViewport(0, 0, h.targets().width(), h.targets().height());
    // The same outputs as the harness: colour, visibility cleared to 1 (lit), depth and stencil.
    const GLfloat sky[] = {0.55f, 0.65f, 0.8f, 1.0f}, lit[] = {1.0f, 1.0f, 1.0f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, sky);
    glClearBufferfv(GL_COLOR, 1, lit);
    glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(program);
    for (uint32_t index : order) {
        const Instance& inst = h.scene().instances[index];
        glBindVertexArray(meshes[inst.mesh].vao);
        glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(inst.model));
        glUniform4f(4, inst.color.r, inst.color.g, inst.color.b, float(inst.objectId));
        glDrawElements(GL_TRIANGLES, meshes[inst.mesh].count, GL_UNSIGNED_INT, nullptr);
    }
    glFinish();
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}
} // namespace

int main(int argc, char** argv) {
    MeasuredHarness::pinAllocator(); // the harness's frames and the hand loop's share one allocator, as
                                     // bench's
    try {
        RunConfig config;
        config.techniques = {{"none", {}}};
        config.frames = 100;
        config.warmup = 2;
        bool listOnly = false;
        // Same options as bench (scene, instances, size, camera ...); --frames is the number of pairs.
        int code = RunOptions::parse(argc, argv, config, listOnly, kFooter);
        if (code >= 0) return code;
        RunOptions::requireGl(config, "handloop");
        config.submit = SubmitMode::Retained;
        Harness h(config);
        // Through the registry, as bench creates it (declared after the harness, released before it).
        const std::unique_ptr<GlTechnique> none = TechniqueRegistry::create("none");
        h.prepare(*none);
        Defines d;
        d["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(h.scene().lights.size()), 1, kMaxLights));
        GLuint program = h.programs().get({"common/scene.vert", "common/lit.frag", ""}, d).id();
        GLuint ubo;
        glCreateBuffers(1, &ubo);
        FrameUniformData data = computeFrameUniforms(
            h.scene(), cameraView(h.camera()),
            cameraProjection(h.camera(), float(config.width) / float(config.height)), h.camera().eye);
        glNamedBufferStorage(ubo, sizeof data, &data, GL_DYNAMIC_STORAGE_BIT);
        auto meshes = uploadMeshes(h.scene());
        // Draw in the retained submitter's order (grouped by mesh) so both do the same GPU work.
        std::vector<uint32_t> order(h.scene().instances.size());
        std::iota(order.begin(), order.end(), 0u);
        std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
            return h.scene().instances[a].mesh < h.scene().instances[b].mesh;
        });
        // As a default bench run does: calibrate, which switches timer queries off where untrusted.
        const TimerVerdict& verdict = h.calibrateTimer();
        for (int i = 0; i < config.warmup; ++i) handFrame(h, program, ubo, data, meshes, order);

        // Frame-by-frame interleaving, alternating which goes first, so the shared machine's noise
        // hits both alike; the overhead is the median of the paired per-frame ratios.
        for (int i = 0; i < config.warmup; ++i) h.renderFrame(*none);
        std::vector<double> hand, harness, ratios;
        const int pairs = config.frames;
        for (int i = 0; i < pairs; ++i) {
            double a, b;
            if (i % 2 == 0) {
                a = handFrame(h, program, ubo, data, meshes, order);
                b = h.renderFrame(*none).wallMs;
            } else {
                b = h.renderFrame(*none).wallMs;
                a = handFrame(h, program, ubo, data, meshes, order);
            }
            hand.push_back(a);
            harness.push_back(b);
            ratios.push_back(b / a);
        }
        Statistics a = Statistics::compute(hand), b = Statistics::compute(harness),
                   q = Statistics::compute(ratios);
        std::printf(
            "renderer %s\nscene %s, %zu triangles, %dx%d, %d frame pairs, interleaved frame by frame\n",
            h.context().renderer.c_str(), h.scene().name.c_str(), h.scene().totalTriangles(), config.width,
            config.height, pairs);
        std::printf("hand-written loop  median %.3f ms  (p5 %.3f, p95 %.3f, MAD %.3f, n %zu)\n", a.median,
                    a.p5, a.p95, a.mad, a.n);
        std::printf("harness, none      median %.3f ms  (p5 %.3f, p95 %.3f, MAD %.3f, n %zu)\n", b.median,
                    b.p5, b.p95, b.mad, b.n);
        std::printf("GPU timer %s (timer queries %s in measured frames)\n", verdict.label(),
                    h.timerQueriesEnabled() ? "on" : "off");
        std::printf("harness overhead   %+.2f %% median of paired frame ratios (p5 %+.2f %%, p95 %+.2f %%); "
                    "%+.2f %% from pooled medians (target < 2 %%)\n",
                    100.0 * (q.median - 1.0), 100.0 * (q.p5 - 1.0), 100.0 * (q.p95 - 1.0),
                    100.0 * (b.median / a.median - 1.0));
        return 0;
    } catch (const Error& e) {
        std::cerr << "handloop: error: " << e.what() << "\n";
        return int(e.code());
    }
}
