// Context backends on the CI platform (Mesa llvmpipe): each headless backend gives a 4.5 compatibility
// context in which immediate mode and display lists render what a hand computation predicts.
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "core/Error.h"
#include "gl/Context.h"
#include "gl/backends/BackendRegistry.h"
#include "gl/backends/EglDeviceContext.h"
#include "gl/backends/EpoxyOsMesaBridge.h"

namespace sb {
namespace {

constexpr int kSize = 64;
constexpr unsigned char kClear[4] = {0, 0, 255, 255}; // blue
constexpr unsigned char kRed[4] = {255, 0, 0, 255};
constexpr unsigned char kGreen[4] = {0, 255, 0, 255};

/// A kSize x kSize RGBA8 FBO, independent of FrameTargets so this test checks the context only.
class TestFbo {
public:
    TestFbo() {
        glGenTextures(1, &mTexture);
        glBindTexture(GL_TEXTURE_2D, mTexture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glGenFramebuffers(1, &mFbo);
        glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, mTexture, 0);
        mStatus = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glViewport(0, 0, kSize, kSize);
    }
    ~TestFbo() {
        glDeleteFramebuffers(1, &mFbo);
        glDeleteTextures(1, &mTexture);
    }
    GLenum status() const { return mStatus; }
    void clear() const {
        glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
        glClearColor(kClear[0] / 255.0f, kClear[1] / 255.0f, kClear[2] / 255.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    std::vector<unsigned char> read() const {
        std::vector<unsigned char> pixels(kSize * kSize * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, mFbo);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        return pixels;
    }

private:
    GLuint mTexture = 0, mFbo = 0;
    GLenum mStatus = 0;
};

bool pixelIs(const std::vector<unsigned char>& pixels, int x, int y, const unsigned char (&rgba)[4]) {
    const unsigned char* p = &pixels[(static_cast<size_t>(y) * kSize + x) * 4];
    return p[0] == rgba[0] && p[1] == rgba[1] && p[2] == rgba[2] && p[3] == rgba[3];
}

/// Lower-left half triangle (-1,-1) (1,-1) (-1,1) with identity matrices: pixel (x, y) has its centre
/// inside iff x + y < 63; centres with x + y == 63 lie exactly on the hypotenuse (fill rule decides).
void drawLowerLeftTriangle(const unsigned char (&rgba)[4]) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glUseProgram(0);
    glColor4ub(rgba[0], rgba[1], rgba[2], rgba[3]);
    glBegin(GL_TRIANGLES);
    glVertex2f(-1.0f, -1.0f);
    glVertex2f(1.0f, -1.0f);
    glVertex2f(-1.0f, 1.0f);
    glEnd();
}

void expectLowerLeftCoverage(const std::vector<unsigned char>& pixels, const unsigned char (&rgba)[4]) {
    int covered = 0, wrongInside = 0, wrongOutside = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            bool drawn = pixelIs(pixels, x, y, rgba);
            covered += drawn;
            if (x + y < 63 && !drawn) ++wrongInside;
            if (x + y > 63 && !pixelIs(pixels, x, y, kClear)) ++wrongOutside;
        }
    }
    EXPECT_EQ(wrongInside, 0) << "pixels with centre strictly inside the triangle not drawn";
    EXPECT_EQ(wrongOutside, 0)
        << "pixels with centre strictly outside the triangle not left at the clear colour";
    // 64 * 63 / 2 = 2016 strictly inside, plus at most the 64 tie pixels on the diagonal.
    EXPECT_GE(covered, 2016);
    EXPECT_LE(covered, 2016 + 64);
}

struct BackendCase {
    const char* name;
    Backend backend;
};
const BackendCase kHeadlessBackends[] = {
    {"EglSurfaceless", Backend::EglSurfaceless},
    {"OsMesa", Backend::OsMesa},
};

class HeadlessBackendGLTest : public ::testing::TestWithParam<BackendCase> {
protected:
    std::unique_ptr<Context> create() {
        ContextOptions options;
        options.backend = GetParam().backend;
        return createContext(options);
    }
};

TEST_P(HeadlessBackendGLTest, Creates45CompatibilityContext) {
    std::unique_ptr<Context> context = create();
    EXPECT_EQ(context->backend(), GetParam().backend);
    EXPECT_EQ(context->glMajor, 4);
    EXPECT_GE(context->glMinor, 5);
    EXPECT_TRUE(context->compatibilityProfile) << context->version;
    EXPECT_NE(context->version.find("Compatibility"), std::string::npos) << context->version;
    EXPECT_FALSE(context->renderer.empty());
    EXPECT_FALSE(context->glslVersion.empty());
    EXPECT_TRUE(context->hasExtension("GL_KHR_debug"));
    EXPECT_FALSE(context->hasExtension("GL_SB_not_an_extension"));
    // CI runs on llvmpipe; on another renderer this only has to agree with the renderer string.
    bool llvmpipe = context->renderer.find("llvmpipe") != std::string::npos;
    if (llvmpipe) {
        EXPECT_TRUE(context->isSoftwareRenderer());
    }
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_P(HeadlessBackendGLTest, ImmediateModeTriangleCoversHandComputedPixels) {
    std::unique_ptr<Context> context = create();
    TestFbo fbo;
    ASSERT_EQ(fbo.status(), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
    fbo.clear();
    drawLowerLeftTriangle(kRed);
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    expectLowerLeftCoverage(fbo.read(), kRed);
}

TEST_P(HeadlessBackendGLTest, DisplayListReplaysCompiledTriangle) {
    std::unique_ptr<Context> context = create();
    TestFbo fbo;
    GLuint list = glGenLists(1);
    ASSERT_NE(list, 0u);
    fbo.clear();
    glNewList(list, GL_COMPILE);
    drawLowerLeftTriangle(kGreen);
    glEndList();
    // GL_COMPILE only records: nothing may have been drawn yet.
    std::vector<unsigned char> before = fbo.read();
    EXPECT_TRUE(pixelIs(before, 2, 2, kClear));
    glCallList(list);
    expectLowerLeftCoverage(fbo.read(), kGreen);
    glDeleteLists(list, 1);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

INSTANTIATE_TEST_SUITE_P(Backends, HeadlessBackendGLTest, ::testing::ValuesIn(kHeadlessBackends),
                         [](const auto& param) { return std::string(param.param.name); });

TEST(ContextGLTest, OsMesaAndEglContextsCoexist) {
    // The OSMesa backend redirects epoxy's pointers while it is current; switching must put them back.
    ContextOptions options;
    options.backend = Backend::OsMesa;
    std::unique_ptr<Context> osmesa = createContext(options);
    EXPECT_TRUE(EpoxyOsMesaBridge::installed());
    EXPECT_GT(EpoxyOsMesaBridge::redirectedCount(), 1000u);
    options.backend = Backend::EglSurfaceless;
    std::unique_ptr<Context> egl = createContext(options);
    EXPECT_FALSE(EpoxyOsMesaBridge::installed());
    for (Context* context : {osmesa.get(), egl.get(), osmesa.get()}) {
        context->makeCurrent();
        TestFbo fbo;
        fbo.clear();
        drawLowerLeftTriangle(kRed);
        expectLowerLeftCoverage(fbo.read(), kRed);
    }
    osmesa.reset();
    egl->makeCurrent();
    TestFbo fbo;
    fbo.clear();
    EXPECT_TRUE(pixelIs(fbo.read(), 10, 10, kClear));
}

TEST(ContextGLTest, AutoPicksAHeadlessBackend) {
    std::unique_ptr<Context> context = createContext(ContextOptions{});
    EXPECT_TRUE(context->backend() == Backend::EglSurfaceless || context->backend() == Backend::OsMesa)
        << backendName(context->backend());
    EXPECT_TRUE(context->compatibilityProfile);
}

TEST(ContextGLTest, EglDeviceRendersWhenADeviceIsListed) {
    std::vector<EGLDeviceEXT> devices = EglDeviceContext::enumerateDevices();
    if (devices.empty())
        GTEST_SKIP() << "EGL reports no devices (EGL_EXT_device_enumeration missing or empty)";
    ContextOptions options;
    options.backend = Backend::EglDevice;
    options.gpu = 0;
    std::unique_ptr<Context> context = createContext(options);
    EXPECT_EQ(context->backend(), Backend::EglDevice);
    EXPECT_TRUE(context->compatibilityProfile);
    EXPECT_EQ(context->deviceName.rfind("device 0: ", 0), 0u) << context->deviceName;
    TestFbo fbo;
    fbo.clear();
    drawLowerLeftTriangle(kRed);
    expectLowerLeftCoverage(fbo.read(), kRed);
}

TEST(ContextGLTest, EglDeviceIndexOutOfRangeIsRefused) {
    ContextOptions options;
    options.backend = Backend::EglDevice;
    options.gpu = 99;
    try {
        createContext(options);
        FAIL() << "--gpu 99 accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("egl-device"), std::string::npos) << e.what();
        // With devices listed, the index is the user's input (exit 2) and the reason is the range; without
        // the extensions the machine lacks them (exit 3) and the message names the extension.
        if (!EglDeviceContext::enumerateDevices().empty()) {
            EXPECT_EQ(e.code(), ExitCode::BadInput);
            EXPECT_NE(std::string(e.what()).find("--gpu 99 is out of range"), std::string::npos) << e.what();
        } else {
            EXPECT_EQ(e.code(), ExitCode::Unsupported);
        }
    }
}

/// Restores DISPLAY on scope exit.
class DisplayOverride {
public:
    explicit DisplayOverride(const char* value) {
        if (const char* old = std::getenv("DISPLAY")) mOld = old;
        if (value) {
            setenv("DISPLAY", value, 1);
        } else {
            unsetenv("DISPLAY");
        }
    }
    ~DisplayOverride() {
        if (mOld) {
            setenv("DISPLAY", mOld->c_str(), 1);
        } else {
            unsetenv("DISPLAY");
        }
    }

private:
    std::optional<std::string> mOld;
};

TEST(ContextGLTest, GlfwWithoutDisplayIsRefusedWithReason) {
    if (std::getenv("WAYLAND_DISPLAY"))
        GTEST_SKIP() << "WAYLAND_DISPLAY set: glfw may succeed without DISPLAY";
    DisplayOverride noDisplay(nullptr);
    ContextOptions options;
    options.backend = Backend::Glfw;
    try {
        createContext(options);
        FAIL() << "glfw created a context without a display";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::Unsupported);
        EXPECT_NE(std::string(e.what()).find("glfw: no display"), std::string::npos) << e.what();
    }
}

TEST(ContextGLTest, GlfwHiddenWindowUnderX) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY (run under xvfb-run to test the glfw backend)";
    ContextOptions options;
    options.backend = Backend::Glfw;
    options.width = 128;
    options.height = 96;
    std::unique_ptr<Context> context = createContext(options);
    EXPECT_EQ(context->backend(), Backend::Glfw);
    EXPECT_NE(context->nativeWindow(), nullptr);
    EXPECT_TRUE(context->compatibilityProfile) << context->version;
    TestFbo fbo;
    fbo.clear();
    drawLowerLeftTriangle(kRed);
    expectLowerLeftCoverage(fbo.read(), kRed);
    context->present();
    EXPECT_FALSE(context->shouldClose());
}

TEST(ContextGLTest, BackendNamesRoundTrip) {
    for (Backend b :
         {Backend::Auto, Backend::EglSurfaceless, Backend::EglDevice, Backend::OsMesa, Backend::Glfw})
        EXPECT_EQ(parseBackend(backendName(b)), b) << backendName(b);
}

TEST(ContextGLTest, UnknownBackendErrorListsValidNames) {
    try {
        parseBackend("vulkan");
        FAIL() << "'vulkan' accepted";
    } catch (const Error& e) {
        std::string message = e.what();
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        EXPECT_NE(message.find("'vulkan'"), std::string::npos) << message;
        for (const char* name : {"auto", "egl-surfaceless", "egl-device", "osmesa", "glfw"})
            EXPECT_NE(message.find(name), std::string::npos) << name << " missing from: " << message;
    }
}

} // namespace
} // namespace sb
