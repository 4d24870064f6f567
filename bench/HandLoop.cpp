// handloop: measures the harness's own overhead (README "Performance"). In one process and on one
// context it alternates blocks of frames of
//   (a) a minimal hand-written GL loop: bind FBO, clear, update the frame UBO, one program, per
//       instance two glUniform calls and one glDrawElements, glFinish; and
//   (b) `bench -t none` through the Harness (uniform upload, timer-query ring, pass timer, KHR_debug
//       checks, submitter, statistics),
// drawing the same instances with the same compiled program into the same targets, and reports the
// median wall time of each and their ratio. Blocks are interleaved so machine noise hits both alike.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "bench/BenchApp.h"
#include "bench/Harness.h"
#include "bench/Statistics.h"
#include "scenes/Error.h"
#include "scenes/Math.h"
#include "techniques/NoneTechnique.h"

using namespace sb;

namespace {
using Clock = std::chrono::steady_clock;

struct MeshGpu {
    GLuint vao = 0;
    GLsizei count = 0;
};

std::vector<MeshGpu> uploadMeshes(const Scene& scene) {
    std::vector<MeshGpu> out;
    for (const Mesh& m : scene.meshes) {
        std::vector<float> v;
        for (size_t i = 0; i < m.positions.size(); ++i)
            v.insert(v.end(), {m.positions[i].x, m.positions[i].y, m.positions[i].z, m.normals[i].x, m.normals[i].y,
                               m.normals[i].z});
        GLuint vao, vbo, ibo;
        glGenVertexArrays(1, &vao);
        glBindVertexArray(vao);
        glGenBuffers(1, &vbo);
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
        glGenBuffers(1, &ibo);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * 4), m.indices.data(), GL_STATIC_DRAW);
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
                 const std::vector<MeshGpu>& meshes) {
    auto t0 = Clock::now();
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, ubo);
    glNamedBufferSubData(ubo, 0, sizeof data, &data);
    glBindFramebuffer(GL_FRAMEBUFFER, h.targets().fbo());
    glViewport(0, 0, h.targets().width(), h.targets().height());
    glClearColor(0.55f, 0.65f, 0.8f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(program);
    for (const Instance& inst : h.scene().instances) {
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
    try {
        RunConfig config;
        config.techniques = {{"none", {}}};
        config.frames = 20;
        config.warmup = 2;
        bool listOnly = false;
        int rounds = 5;
        // Same options as bench (scene, instances, size, camera ...); --frames is frames per block.
        if (const char* r = std::getenv("HANDLOOP_ROUNDS")) rounds = std::max(1, std::atoi(r));
        int code = BenchApp::parse(argc, argv, config, listOnly);
        if (code >= 0) return code;
        config.submit = SubmitMode::Retained;
        Harness h(config);
        NoneTechnique none;
        h.prepare(none);
        Defines d;
        d["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(h.scene().lights.size()), 1, kMaxLights));
        GLuint program = h.programs().get({"common/scene.vert", "none/lit.frag", ""}, d).id();
        GLuint ubo;
        glCreateBuffers(1, &ubo);
        FrameUniformData data = FrameUniforms::compute(h.scene(), cameraView(h.camera()),
                                                       cameraProjection(h.camera(), float(config.width) / float(config.height)),
                                                       h.camera().eye);
        glNamedBufferStorage(ubo, sizeof data, &data, GL_DYNAMIC_STORAGE_BIT);
        auto meshes = uploadMeshes(h.scene());
        for (int i = 0; i < config.warmup; ++i) handFrame(h, program, ubo, data, meshes);

        std::vector<double> hand, harness;
        for (int r = 0; r < rounds; ++r) {
            for (int i = 0; i < config.frames; ++i) hand.push_back(handFrame(h, program, ubo, data, meshes));
            RunResult res = h.measure(none);
            for (const FrameSample& s : res.samples) harness.push_back(s.wallMs);
        }
        Statistics a = Statistics::compute(hand), b = Statistics::compute(harness);
        std::printf("renderer %s\nscene %s, %zu triangles, %dx%d, %d rounds x %d frames, interleaved\n",
                    h.context().renderer.c_str(), h.scene().name.c_str(), h.scene().totalTriangles(), config.width,
                    config.height, rounds, config.frames);
        std::printf("hand-written loop  median %.3f ms  (p5 %.3f, p95 %.3f, MAD %.3f, n %zu)\n", a.median, a.p5, a.p95,
                    a.mad, a.n);
        std::printf("harness, none      median %.3f ms  (p5 %.3f, p95 %.3f, MAD %.3f, n %zu)\n", b.median, b.p5, b.p95,
                    b.mad, b.n);
        std::printf("harness overhead   %+.2f %% (target < 2 %%)\n", 100.0 * (b.median / a.median - 1.0));
        return 0;
    } catch (const Error& e) {
        std::cerr << "handloop: error: " << e.what() << "\n";
        return int(e.code());
    }
}
