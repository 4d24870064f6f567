// FrameTargets on a real context: attachment formats, clear values and float read-back that keeps NaN/Inf.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "TestPaths.h"
#include "gl/Context.h"
#include "gl/FrameTargets.h"
#include "gl/ProgramCache.h"
#include "gl/backends/BackendRegistry.h"

namespace sb {
namespace {

const std::string kShaderRoot = std::string(SB_SOURCE_DIR) + "/tests/shaders";

class FrameTargetsGLTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { sContext = createContext(ContextOptions{}); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<Context> sContext;
};
std::unique_ptr<Context> FrameTargetsGLTest::sContext;

void drawFullscreenQuad() {
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2f(-1.0f, -1.0f);
    glVertex2f(1.0f, -1.0f);
    glVertex2f(-1.0f, 1.0f);
    glVertex2f(1.0f, 1.0f);
    glEnd();
}

GLint textureSize(GLuint texture, GLenum what) {
    GLint value = 0;
    glGetTextureLevelParameteriv(texture, 0, what, &value);
    return value;
}

TEST_F(FrameTargetsGLTest, SizesAndFormats) {
    // Odd, non-square size: catches swapped width/height and row-alignment slips in read-backs.
    FrameTargets targets(37, 21);
    EXPECT_EQ(targets.width(), 37);
    EXPECT_EQ(targets.height(), 21);
    for (GLuint texture :
         {targets.colorTexture(), targets.visibilityTexture(), targets.depthStencilTexture()}) {
        EXPECT_EQ(textureSize(texture, GL_TEXTURE_WIDTH), 37);
        EXPECT_EQ(textureSize(texture, GL_TEXTURE_HEIGHT), 21);
    }
    EXPECT_EQ(textureSize(targets.colorTexture(), GL_TEXTURE_INTERNAL_FORMAT), GL_RGBA8);
    EXPECT_EQ(textureSize(targets.visibilityTexture(), GL_TEXTURE_INTERNAL_FORMAT), GL_RGBA16F);
    EXPECT_EQ(textureSize(targets.depthStencilTexture(), GL_TEXTURE_INTERNAL_FORMAT), GL_DEPTH24_STENCIL8);
    targets.bind();
    GLint viewport[4] = {};
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(viewport[2], 37);
    EXPECT_EQ(viewport[3], 21);
    EXPECT_EQ(targets.readColorRGBA8().size(), 37u * 21u * 4u);
    EXPECT_EQ(targets.readVisibilityRGBA32F().size(), 37u * 21u * 4u);
    EXPECT_EQ(targets.readDepth().size(), 37u * 21u);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(FrameTargetsGLTest, ClearValuesReadBack) {
    FrameTargets targets(37, 21);
    // Masks left off by "a technique" must not make the clear partial.
    glDepthMask(GL_FALSE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    targets.clear(0.2f, 0.4f, 0.6f);
    std::vector<unsigned char> color = targets.readColorRGBA8();
    std::vector<float> visibility = targets.readVisibilityRGBA32F();
    std::vector<float> depth = targets.readDepth();
    int wrongColor = 0, wrongVisibility = 0, wrongDepth = 0;
    for (size_t i = 0; i < depth.size(); ++i) {
        // 0.2 * 255 = 51, 0.4 * 255 = 102, 0.6 * 255 = 153: exact in unorm8.
        const unsigned char* c = &color[i * 4];
        wrongColor += !(c[0] == 51 && c[1] == 102 && c[2] == 153 && c[3] == 255);
        for (int k = 0; k < 4; ++k) wrongVisibility += visibility[i * 4 + k] != 1.0f;
        wrongDepth += depth[i] != 1.0f;
    }
    EXPECT_EQ(wrongColor, 0);
    EXPECT_EQ(wrongVisibility, 0) << "visibility must clear to exactly 1.0 (lit)";
    EXPECT_EQ(wrongDepth, 0);
    GLint stencil = -1;
    glReadPixels(3, 4, 1, 1, GL_STENCIL_INDEX, GL_INT, &stencil);
    EXPECT_EQ(stencil, 0);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(FrameTargetsGLTest, NanAndInfWrittenByShaderSurviveInVisibility) {
    ProgramCache cache(kShaderRoot);
    const Program& program = cache.get({"fill.vert", "nan.frag", ""}, {});
    FrameTargets targets(16, 8);
    targets.clear(0.0f, 0.0f, 0.0f);
    program.use();
    drawFullscreenQuad();
    glUseProgram(0);
    std::vector<float> visibility = targets.readVisibilityRGBA32F();
    int notNan = 0, notInf = 0, wrongRest = 0;
    for (size_t i = 0; i < visibility.size(); i += 4) {
        notNan += !std::isnan(visibility[i]);
        notInf += !(std::isinf(visibility[i + 1]) && visibility[i + 1] > 0.0f);
        wrongRest += visibility[i + 2] != 0.25f || visibility[i + 3] != 0.75f; // exact in half float
    }
    EXPECT_EQ(notNan, 0) << "first pixel channel 0 = " << visibility[0];
    EXPECT_EQ(notInf, 0) << "first pixel channel 1 = " << visibility[1];
    EXPECT_EQ(wrongRest, 0);
    std::vector<unsigned char> color = targets.readColorRGBA8();
    EXPECT_EQ(color[1], 255); // attachment 0 got oColor (green) in the same draw
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

} // namespace
} // namespace sb
