// TimerQueryRing (per-pass GL_TIMESTAMP ring, never waiting in collect) and DebugOutput (KHR_debug errors
// fail with the pass name) on a real context.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/Error.h"
#include "gl/Context.h"
#include "gl/DebugOutput.h"
#include "gl/FrameTargets.h"
#include "gl/TimerQueryRing.h"
#include "gl/backends/BackendRegistry.h"

namespace sb {
namespace {

class GLTestBase : public ::testing::Test {
protected:
    static void SetUpTestSuite() { sContext = createContext(ContextOptions{}); }
    static void TearDownTestSuite() { sContext.reset(); }
    static std::unique_ptr<Context> sContext;
};
std::unique_ptr<Context> GLTestBase::sContext;

constexpr const char* kShadowPass = "shadowmap/depth";
constexpr const char* kLightingPass = "shadowmap/lighting";

/// Some real work per pass so the timestamps have something between them.
void drawPass(const FrameTargets& targets, float shade) {
    targets.clear(shade, shade, shade);
    glColor3f(1.0f - shade, 0.0f, shade);
    glBegin(GL_TRIANGLES);
    glVertex2f(-1.0f, -1.0f);
    glVertex2f(1.0f, -1.0f);
    glVertex2f(0.0f, 1.0f);
    glEnd();
}

void runFrame(TimerQueryRing& ring, const FrameTargets& targets) {
    ring.beginFrame();
    ring.beginPass(kShadowPass);
    drawPass(targets, 0.25f);
    ring.beginPass(kLightingPass);
    drawPass(targets, 0.75f);
    ring.endFrame();
}

void expectWellFormed(const PassTimes& times) {
    ASSERT_EQ(times.passMs.size(), 2u);
    EXPECT_EQ(times.passMs[0].first, kShadowPass);
    EXPECT_EQ(times.passMs[1].first, kLightingPass);
    double sum = 0.0;
    for (const auto& [name, ms] : times.passMs) {
        EXPECT_GE(ms, 0.0) << name << " in frame " << times.frame;
        sum += ms;
    }
    EXPECT_NEAR(times.totalMs, sum, 1e-6);
}

using TimerQueryRingGLTest = GLTestBase;

TEST_F(TimerQueryRingGLTest, EveryFrameReportedInOrderWhenRingIsDeepEnough) {
    constexpr int kFrames = 6;
    FrameTargets targets(64, 64);
    TimerQueryRing ring(kFrames + 2); // no slot is reused, so nothing can be dropped
    std::vector<PassTimes> records;
    for (int f = 0; f < kFrames; ++f) {
        runFrame(ring, targets);
        std::vector<PassTimes> ready = ring.collect(); // right after endFrame: may be fewer than f + 1
        records.insert(records.end(), ready.begin(), ready.end());
        EXPECT_LE(records.size(), static_cast<size_t>(f + 1));
    }
    std::vector<PassTimes> rest = ring.drain();
    records.insert(records.end(), rest.begin(), rest.end());
    ASSERT_EQ(records.size(), static_cast<size_t>(kFrames));
    for (size_t i = 0; i < records.size(); ++i) {
        EXPECT_EQ(records[i].frame, i);
        expectWellFormed(records[i]);
    }
    EXPECT_EQ(ring.droppedFrames(), 0u);
    EXPECT_TRUE(ring.drain().empty());
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(TimerQueryRingGLTest, ShallowRingNeverLosesCountOfFrames) {
    // Depth 2 and collect only at the end: reused slots are either read (complete) or counted dropped.
    constexpr int kFrames = 20;
    FrameTargets targets(32, 32);
    TimerQueryRing ring(2);
    for (int f = 0; f < kFrames; ++f) runFrame(ring, targets);
    std::vector<PassTimes> records = ring.collect();
    std::vector<PassTimes> rest = ring.drain();
    records.insert(records.end(), rest.begin(), rest.end());
    EXPECT_EQ(records.size() + ring.droppedFrames(), static_cast<size_t>(kFrames));
    for (size_t i = 1; i < records.size(); ++i) EXPECT_LT(records[i - 1].frame, records[i].frame);
    for (const PassTimes& times : records) expectWellFormed(times);
}

TEST_F(TimerQueryRingGLTest, TooManyPassesIsAnError) {
    TimerQueryRing ring(2, 1);
    ring.beginFrame();
    ring.beginPass(kShadowPass);
    EXPECT_THROW(ring.beginPass(kLightingPass), Error);
    ring.endFrame();
    EXPECT_EQ(ring.drain().size(), 1u);
}

using DebugOutputGLTest = GLTestBase;

/// GL_INVALID_ENUM in every profile: GL_TEXTURE_BINDING_2D is a query enum, not a texture target.
void provokeInvalidEnum() {
    glTexImage2D(GL_TEXTURE_BINDING_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
}

std::string checkMessage() {
    try {
        DebugOutput::check();
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::Failure);
        return e.what();
    }
    return "";
}

TEST_F(DebugOutputGLTest, ErrorInsidePassThrowsWithPassName) {
    ASSERT_TRUE(DebugOutput::install()) << "llvmpipe has KHR_debug";
    EXPECT_EQ(checkMessage(), "");
    DebugOutput::setCurrentPass(kShadowPass);
    EXPECT_EQ(DebugOutput::currentPass(), kShadowPass);
    provokeInvalidEnum();
    // The pass reported is the one the error happened in, even when checked later.
    DebugOutput::setCurrentPass(kLightingPass);
    std::string message = checkMessage();
    EXPECT_EQ(message.rfind(std::string("GL error in pass '") + kShadowPass + "': GL_INVALID_ENUM", 0), 0u)
        << message;
    EXPECT_NE(message.find("glTexImage2D"), std::string::npos) << "driver message kept: " << message;
    EXPECT_EQ(checkMessage(), "") << "an error is reported once";
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    DebugOutput::setCurrentPass("");
}

TEST_F(DebugOutputGLTest, FallsBackToGlGetErrorWithoutCallback) {
    ASSERT_TRUE(DebugOutput::install());
    glDisable(GL_DEBUG_OUTPUT); // as if KHR_debug were absent: only glGetError sees the error
    DebugOutput::setCurrentPass(kLightingPass);
    provokeInvalidEnum();
    std::string message = checkMessage();
    EXPECT_EQ(message, std::string("GL error in pass '") + kLightingPass + "': GL_INVALID_ENUM") << message;
    glEnable(GL_DEBUG_OUTPUT);
    DebugOutput::setCurrentPass("");
}

TEST_F(DebugOutputGLTest, NonErrorMessagesAreWarnings) {
    ASSERT_TRUE(DebugOutput::install());
    DebugOutput::takeWarnings();
    glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PERFORMANCE, 1, GL_DEBUG_SEVERITY_MEDIUM,
                         -1, "slow path taken");
    EXPECT_EQ(checkMessage(), "");
    std::vector<std::string> warnings = DebugOutput::takeWarnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "slow path taken");
    EXPECT_TRUE(DebugOutput::takeWarnings().empty());
    // Many warnings are capped, with a count of the rest.
    for (int i = 0; i < 1000; ++i)
        glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PERFORMANCE, 2, GL_DEBUG_SEVERITY_LOW,
                             -1, "again");
    warnings = DebugOutput::takeWarnings();
    EXPECT_LT(warnings.size(), 1000u);
    EXPECT_NE(warnings.back().find("more warnings not kept"), std::string::npos) << warnings.back();
}

} // namespace
} // namespace sb
