// FloorPass and PassTarget (bench/floors/) on a real context: a floor draws exactly the fragments asked
// for (GL_SAMPLES_PASSED, and the pipeline's fragment-shader invocations where the driver runs the
// shader), into a target of the same size and formats as the pass it stands for, and writes what its
// kind writes: read back here and counted pixel by pixel, an answer independent of the layout.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bench/floors/FloorLayout.h"
#include "bench/floors/FloorPass.h"
#include "bench/floors/PassTarget.h"
#include "core/Error.h"
#include "gl/Context.h"
#include "gl/FrameTargets.h"
#include "gl/PipelineStatistics.h"
#include "gl/backends/BackendRegistry.h"

namespace sb {
namespace {

class FloorPassGLTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { sContext = createContext(ContextOptions{}); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<Context> sContext;
};
std::unique_ptr<Context> FloorPassGLTest::sContext;

PassTarget like(int w, int h, std::vector<GLenum> colours, GLenum depth) {
    PassTarget t;
    t.fbo = 1; // not the frame targets
    t.width = w;
    t.height = h;
    t.colourFormats = std::move(colours);
    t.depthFormat = depth;
    t.stencil = depth == GL_DEPTH24_STENCIL8;
    return t;
}

struct Counted {
    uint64_t samples = 0;
    PipelineCounts pipeline;
};

/// The floor drawn once with an occlusion query and the pipeline statistics around it.
Counted drawCounted(FloorPass& floor, uint64_t fragments) {
    PipelineStatistics statistics;
    GLuint query = 0;
    glGenQueries(1, &query);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    statistics.begin();
    floor.draw(fragments);
    Counted c;
    c.pipeline = statistics.end();
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 samples = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &samples);
    glDeleteQueries(1, &query);
    c.samples = samples;
    return c;
}

template <typename T>
std::vector<T> readBack(const FloorPass& floor, int w, int h, GLenum buffer, GLenum format, GLenum type,
                        int components) {
    std::vector<T> out(size_t(w) * size_t(h) * size_t(components));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, floor.fbo());
    glReadBuffer(buffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, format, type, out.data());
    return out;
}

/// Fragment-shader invocations where the driver counts them: llvmpipe counts 4x4 blocks, and a floor's
/// layout has at most one partly covered block (its last two scissor boxes may both touch it: < 32
/// more). llvmpipe also counts more blocks on every row of blocks of a draw that reaches the target's
/// right edge: measured, one more per row at widths 32 to 256 (a whole 32x32 target, 1024 fragments,
/// counts 1152, the same with the scissor off and whatever the triangle's shape), two at width 48;
/// a technique's passes pay the same. The bound allows a 16-pixel block's width (4 blocks) per row of
/// such rectangles; rectangles clear of that edge are counted exactly.
void expectInvocations(const Counted& c, uint64_t fragments, int width, int height, bool shaderMayBeSkipped) {
    const uint64_t fs = c.pipeline.fragmentShaderInvocations;
    if (shaderMayBeSkipped && fs == 0) return; // a driver that runs no empty fragment shader (Mesa 25)
    uint64_t edge = 0;
    for (const FloorRect& r : FloorLayout::of(fragments, width, height))
        if (r.x1 == width) edge += 4 * 16 * uint64_t((r.y1 - r.y0 + 3) / 4) * r.repeat;
    EXPECT_GE(fs, fragments);
    EXPECT_LT(fs, fragments + edge + 32);
    if (edge == 0 && fragments % 16 == 0) {
        EXPECT_EQ(fs, fragments);
    }
}

TEST_F(FloorPassGLTest, DepthFloorWritesOnlyDepthForExactlyTheFragmentsAsked) {
    const PassTarget map = like(64, 64, {}, GL_DEPTH_COMPONENT24);
    FloorPass floor(map, PassKind::Depth);
    EXPECT_TRUE(floor.target().sameFormats(map)) << floor.target().text();
    EXPECT_TRUE(floor.target().colourFormats.empty());
    // Fewer than the map's texels: the written ones (depth 0.5 over a clear of 1) counted one by one.
    const Counted c = drawCounted(floor, 1234);
    EXPECT_EQ(c.samples, 1234u);
    expectInvocations(c, 1234, 64, 64, true);
    const auto depth = readBack<float>(floor, 64, 64, GL_NONE, GL_DEPTH_COMPONENT, GL_FLOAT, 1);
    int written = 0, cleared = 0;
    for (float d : depth) {
        written += std::abs(d - 0.5f) < 1e-6f; // 24-bit depth: 0.5 within 6e-8
        cleared += d == 1.0f;
    }
    EXPECT_EQ(written, 1234);
    EXPECT_EQ(cleared, 64 * 64 - 1234);
    // More fragments than texels (a depth pass's front and back faces): whole layers, then the rest.
    const uint64_t many = 3 * 64 * 64 + 777 + 16 * 3;
    const Counted m = drawCounted(floor, many);
    EXPECT_EQ(m.samples, many);
    expectInvocations(m, many, 64, 64, true);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(FloorPassGLTest, LitFloorWritesItsColourToEveryAttachment) {
    const PassTarget frame = like(48, 32, {GL_RGBA8, GL_RGBA16F}, GL_DEPTH24_STENCIL8);
    FloorPass floor(frame, PassKind::Lit);
    EXPECT_TRUE(floor.target().sameFormats(frame)) << floor.target().text();
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(floor.fbo(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(floor.fbo(), GL_COLOR, 1, zero);
    const Counted c = drawCounted(floor, 800);
    EXPECT_EQ(c.samples, 800u);
    expectInvocations(c, 800, 48, 32, false);
    // The floor's colour (0.5, 0.25, 0.125, 1): 128, 64, 32, 255 in unorm8 (round to nearest),
    // exact in half floats.
    const auto rgba8 =
        readBack<unsigned char>(floor, 48, 32, GL_COLOR_ATTACHMENT0, GL_RGBA, GL_UNSIGNED_BYTE, 4);
    const auto rgba16f = readBack<float>(floor, 48, 32, GL_COLOR_ATTACHMENT1, GL_RGBA, GL_FLOAT, 4);
    int colour = 0, visibility = 0;
    for (size_t i = 0; i < size_t(48 * 32); ++i) {
        const unsigned char* p = &rgba8[i * 4];
        colour += p[0] == 128 && p[1] == 64 && p[2] == 32 && p[3] == 255;
        const float* f = &rgba16f[i * 4];
        visibility += f[0] == 0.5f && f[1] == 0.25f && f[2] == 0.125f && f[3] == 1.0f;
    }
    EXPECT_EQ(colour, 800);
    EXPECT_EQ(visibility, 800);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(FloorPassGLTest, StencilFloorIncrementsStencilOncePerFragment) {
    const PassTarget frame = like(64, 64, {GL_RGBA8}, GL_DEPTH24_STENCIL8);
    FloorPass floor(frame, PassKind::Stencil);
    const PassTarget made = floor.target();
    EXPECT_TRUE(made.colourFormats.empty()) << made.text(); // stencil only: no colour attachment
    EXPECT_EQ(made.depthFormat, GLenum(GL_DEPTH24_STENCIL8));
    EXPECT_EQ(made.width, 64);
    const uint64_t fragments = 64 * 64 + 500;
    const Counted c = drawCounted(floor, fragments);
    EXPECT_EQ(c.samples, fragments);
    expectInvocations(c, fragments, 64, 64, true);
    // Each fragment incremented its pixel's stencil once over a clear of 0: the values sum to N.
    const auto stencil =
        readBack<unsigned char>(floor, 64, 64, GL_NONE, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, 1);
    uint64_t sum = 0;
    for (unsigned char s : stencil) sum += s;
    EXPECT_EQ(sum, fragments);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(FloorPassGLTest, TextureFloorClearsItsTextureThenWritesTheFragments) {
    const PassTarget projector = like(32, 32, {GL_R8}, GL_NONE);
    FloorPass floor(projector, PassKind::Texture);
    EXPECT_TRUE(floor.target().sameFormats(projector)) << floor.target().text();
    const Counted c = drawCounted(floor, 100);
    EXPECT_EQ(c.samples, 100u);
    expectInvocations(c, 100, 32, 32, false);
    const auto r8 = readBack<unsigned char>(floor, 32, 32, GL_COLOR_ATTACHMENT0, GL_RED, GL_UNSIGNED_BYTE, 1);
    int written = 0, cleared = 0;
    for (unsigned char v : r8) {
        written += v == 128;
        cleared += v == 0;
    }
    EXPECT_EQ(written, 100);
    EXPECT_EQ(cleared, 32 * 32 - 100);
    // A multiple of 16 clear of the right edge (24 columns 4 high): exactly its fragments, shaded once.
    const Counted exact = drawCounted(floor, 96);
    EXPECT_EQ(exact.samples, 96u);
    EXPECT_EQ(exact.pipeline.fragmentShaderInvocations, 96u);
}

TEST_F(FloorPassGLTest, FilteredFloorReadsOneTexelAtEachFragmentsPixel) {
    const PassTarget moments = like(32, 32, {GL_RG32F}, GL_NONE);
    FloorPass floor(moments, PassKind::Filtered);
    EXPECT_TRUE(floor.target().sameFormats(moments)) << floor.target().text();
    ASSERT_NE(floor.sourceTexture(), 0u);
    // The source holds its own pixel's coordinates: the output must hold the fragment's own.
    std::vector<float> source(32 * 32 * 2);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            source[size_t(y * 32 + x) * 2] = float(x);
            source[size_t(y * 32 + x) * 2 + 1] = float(y);
        }
    glTextureSubImage2D(floor.sourceTexture(), 0, 0, 0, 32, 32, GL_RG, GL_FLOAT, source.data());
    const float marker[4] = {-1, -1, 0, 0};
    glClearNamedFramebufferfv(floor.fbo(), GL_COLOR, 0, marker);
    const Counted c = drawCounted(floor, 160);
    EXPECT_EQ(c.samples, 160u);
    expectInvocations(c, 160, 32, 32, false);
    const auto out = readBack<float>(floor, 32, 32, GL_COLOR_ATTACHMENT0, GL_RG, GL_FLOAT, 2);
    int own = 0, untouched = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const float* p = &out[size_t(y * 32 + x) * 2];
            own += p[0] == float(x) && p[1] == float(y);
            untouched += p[0] == -1.0f;
        }
    EXPECT_EQ(own, 160);
    EXPECT_EQ(untouched, 32 * 32 - 160);
}

TEST_F(FloorPassGLTest, PassTargetReadsTheBoundTargetAndItsKind) {
    FrameTargets frame(40, 24);
    frame.bind();
    PassTarget t = PassTarget::current();
    EXPECT_EQ(t.fbo, frame.fbo());
    EXPECT_EQ(t.text(), "40x24 RGBA8+RGBA16F+DEPTH24_STENCIL8");
    EXPECT_TRUE(t.stencil);
    EXPECT_EQ(t.kindOf("lighting", frame.fbo()), PassKind::Lit);
    EXPECT_EQ(t.kindOf("mark", frame.fbo()), PassKind::Stencil);
    EXPECT_EQ(t.kindOf("self.mark", frame.fbo()), PassKind::Stencil);
    frame.setVisibilityOutput(false);
    frame.bind();
    EXPECT_EQ(PassTarget::current().text(), "40x24 RGBA8+DEPTH24_STENCIL8"); // draw buffers, not attachments
    frame.setVisibilityOutput(true);

    FloorPass depth(like(16, 16, {}, GL_DEPTH_COMPONENT32F), PassKind::Depth);
    glBindFramebuffer(GL_FRAMEBUFFER, depth.fbo());
    EXPECT_EQ(PassTarget::current().text(), "16x16 DEPTH_COMPONENT32F");
    EXPECT_EQ(PassTarget::current().kindOf("depth", frame.fbo()), PassKind::Depth);
    FloorPass texture(like(8, 8, {GL_R8}, GL_NONE), PassKind::Texture);
    glBindFramebuffer(GL_FRAMEBUFFER, texture.fbo());
    EXPECT_EQ(PassTarget::current().kindOf("texture", frame.fbo()), PassKind::Texture);
    EXPECT_EQ(PassTarget::current().kindOf("blur", frame.fbo()), PassKind::Filtered);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    EXPECT_FALSE(PassTarget::current().unusable.empty());
}

TEST_F(FloorPassGLTest, RefusesATargetItCannotMatchWithTheReason) {
    try {
        FloorPass f(like(16, 16, {GL_RGBA8}, GL_DEPTH_COMPONENT24), PassKind::Stencil);
        FAIL() << "a stencil floor without stencil";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::Unsupported);
        EXPECT_NE(std::string(e.what()).find("16x16 RGBA8+DEPTH_COMPONENT24"), std::string::npos) << e.what();
    }
    EXPECT_THROW(FloorPass(like(16, 16, {GL_R32UI}, GL_NONE), PassKind::Lit), Error);
    PassTarget none;
    none.unusable = "the default framebuffer";
    EXPECT_THROW(FloorPass(none, PassKind::Lit), Error);
}

} // namespace
} // namespace sb
