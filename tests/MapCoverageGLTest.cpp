// counter_map_covered_pct is counted on the CPU (scenes/MapCoverage.h) so that it is the same on every
// API and driver; here it is held to what a GL rasteriser makes of the same casters and the same light
// camera: sphere_plane's sphere drawn depth-only into a map with the fits of scenes/LightFit.h, the
// texels it wrote (depth below the cleared 1) counted from a readback.
#include <filesystem>
#include <memory>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "TestSupport.h"
#include "gl/ProgramCache.h"
#include "gl/backends/BackendRegistry.h"
#include "scenes/LightFit.h"
#include "scenes/MapCoverage.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {

constexpr int kResolution = 1024;

/// The texels of a kResolution^2 depth map that the casters of `scene` reach through `viewProj`, drawn
/// as a depth pass draws them (both faces, depth test, no colour).
uint64_t rasterisedTexels(const Scene& scene, const glm::mat4& viewProj) {
    namespace fs = std::filesystem;
    const fs::path root = test::freshTestDir("map_coverage");
    fs::create_directories(root / "test");
    test::writeFile((root / "test" / "depth.vert").string(), R"(
layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform mat4 uViewProj;
void main() { gl_Position = uViewProj * vec4(aPosition, 1.0); }
)");
    test::writeFile((root / "test" / "depth.frag").string(), "void main() {}\n");
    ProgramCache programs(root.string());
    const Program& program = programs.get({"test/depth.vert", "test/depth.frag", ""}, {});

    std::vector<glm::vec3> triangles; // world positions, three per caster triangle
    for (const Instance& inst : scene.instances) {
        if (!inst.castsShadow) continue;
        const Mesh& mesh = scene.meshes[inst.mesh];
        for (uint32_t i : mesh.indices)
            triangles.emplace_back(inst.model * glm::vec4(mesh.positions[i], 1.0f));
    }
    GLuint texture = 0, fbo = 0, vao = 0, vbo = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, GL_DEPTH_COMPONENT24, kResolution, kResolution);
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, texture, 0);
    glNamedFramebufferDrawBuffer(fbo, GL_NONE);
    glCreateBuffers(1, &vbo);
    glNamedBufferStorage(vbo, GLsizeiptr(triangles.size() * sizeof(glm::vec3)), triangles.data(), 0);
    glCreateVertexArrays(1, &vao);
    glVertexArrayVertexBuffer(vao, 0, vbo, 0, sizeof(glm::vec3));
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, 0, 0);

    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, kResolution, kResolution);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    program.use();
    glUniformMatrix4fv(0, 1, GL_FALSE, &viewProj[0][0]);
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(triangles.size()));
    std::vector<float> depth(size_t(kResolution) * kResolution);
    glGetTextureImage(texture, 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * sizeof(float)),
                      depth.data());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glDeleteVertexArrays(1, &vao);
    glDeleteBuffers(1, &vbo);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &texture);
    uint64_t written = 0;
    for (float d : depth) written += d < 1.0f ? 1 : 0;
    return written;
}

} // namespace

TEST(MapCoverageGL, TheCpuCountIsWhatTheRasteriserWrites) {
    auto context = createContext(ContextOptions{});
    const Scene scene = SceneLoader::load("sphere_plane");
    // Texel centres the two counts may disagree on lie within the rasteriser's snapping of the
    // vertices (llvmpipe: 1/256 texel) of the sphere's outline, or exactly on it. The outline is shorter
    // than the map's perimeter, 4 x 1024 texels, and a band of 2/256 texel around it holds about 32
    // centres: 64 allowed, against the hundreds of thousands covered (a fit off by half a texel in scale
    // would move the count by about half the outline, a thousand and more).
    constexpr double kTolerance = 64.0;
    for (const LightFitBounds bounds : {LightFitBounds::Casters, LightFitBounds::Sphere}) {
        SCOPED_TRACE(lightFitBoundsNames().name(bounds));
        const glm::mat4 viewProj = fitLightViewProjection(scene, scene.lights[0], {bounds, 0.01f});
        const MapCoverage cpu = MapCoverage::count(scene, viewProj, kResolution);
        const uint64_t gl = rasterisedTexels(scene, viewProj);
        EXPECT_GT(gl, 100000u);
        EXPECT_NEAR(double(cpu.covered), double(gl), kTolerance);
    }
}
