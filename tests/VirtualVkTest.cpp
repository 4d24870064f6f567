// `virtual`'s Vulkan form (techniques/virtual/VirtualVulkan.h, the atomic path) on lavapipe with the
// validation layer on, against independent answers:
//  (a) the cache's correctness on Vulkan: along the path on which casters move
//      (tests/VirtualScenes.h), every frame's visibility with the cache on equals the frame drawn with
//      the cache off, value for value, with fewer pages drawn;
//  (b) the same frames on GL: the CPU allocates from the marks on both APIs, so every page count of
//      every frame is GL's exactly (the marks are the same pages), and the visibility is GL's up to
//      the project's GL/Vulkan image rule (tests/GlVulkanImageVkTest.cpp: at most 0.5% of pixels
//      differing).
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "SecondDriver.h"
#include "TestSupport.h"
#include "VirtualScenes.h"
#include "VkTestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "bench/lib/harness/VulkanHarness.h"
#include "registry/TechniqueRegistry.h"
#include "techniques/virtual/VirtualGL.h"
#include "techniques/virtual/VirtualVulkan.h"

using namespace sb;

namespace {

constexpr const char* kProps = "virtual:virtual_resolution=4096:pool_pages=1024";

RunConfig vulkanConfig(RunConfig c) {
    c.api = RunConfig::Api::Vulkan;
    c.vulkan.validation = true;
    return c;
}

} // namespace

TEST(VirtualVkTest, CachedFramesEqualUncachedFramesAndGlsAlongAMovingPath) {
    RunConfig cfg = test::quickConfig(test::virtualMovingCastersScene(), "view", 128);
    cfg.pathFrames = 8;
    VulkanHarness cachedRun(vulkanConfig(cfg)), freshRun(vulkanConfig(cfg));
    Harness glRun(cfg);
    auto cached = std::unique_ptr<VirtualVulkan>(
        static_cast<VirtualVulkan*>(TechniqueRegistry::createVulkan(TechniqueSpec::parse(kProps)).release()));
    auto fresh = std::unique_ptr<VirtualVulkan>(static_cast<VirtualVulkan*>(
        TechniqueRegistry::createVulkan(TechniqueSpec::parse(std::string(kProps) + ":cache=false"))
            .release()));
    auto gl = std::make_unique<VirtualGL>();
    gl->properties().apply(TechniqueSpec::parse(kProps).properties);
    cachedRun.prepare(*cached);
    freshRun.prepare(*fresh);
    glRun.prepare(*gl);
    uint64_t cachedPages = 0, freshPages = 0;
    size_t worstGlDiffer = 0;
    for (int f = 0; f < 8; ++f) {
        SCOPED_TRACE("frame " + std::to_string(f));
        cachedRun.renderFrame(*cached);
        freshRun.renderFrame(*fresh);
        glRun.renderFrame(*gl);
        const std::vector<float> a = cachedRun.readVisibility();
        const std::vector<float> b = freshRun.readVisibility();
        const std::vector<float> g = glRun.targets().readVisibilityRGBA32F();
        ASSERT_EQ(a.size(), b.size());
        ASSERT_EQ(a.size(), g.size());
        size_t differ = 0, shadowed = 0, glDiffer = 0;
        for (size_t i = 0; i < a.size(); i += 4) {
            differ += a[i] != b[i] ? 1 : 0;
            glDiffer += std::abs(a[i] - g[i]) > 1.0f / 1024.0f ? 1 : 0;
            shadowed += b[i] < 1.0f ? 1 : 0;
        }
        EXPECT_EQ(differ, 0u) << "pixels whose visibility differs with the cache on";
        EXPECT_GT(shadowed, 0u) << "no shadow on screen: the comparison would be empty";
        EXPECT_LE(double(glDiffer), 0.005 * double(a.size() / 4)) << "pixels differing from GL's";
        worstGlDiffer = std::max(worstGlDiffer, glDiffer);
        const PageCounts& c = cached->pageCounts();
        const PageCounts& h = gl->pageCounts();
        EXPECT_EQ(c.needed, h.needed);
        EXPECT_EQ(c.rendered, h.rendered);
        EXPECT_EQ(c.reused, h.reused);
        EXPECT_EQ(c.invalidated, h.invalidated);
        EXPECT_EQ(c.dropped, 0u);
        cachedPages += c.rendered;
        freshPages += fresh->pageCounts().rendered;
    }
    std::cout << "Vulkan, pages drawn over 8 frames: cache on " << cachedPages << ", off " << freshPages
              << "; most pixels differing from GL in a frame: " << worstGlDiffer << "\n";
    EXPECT_LT(cachedPages, freshPages);
    EXPECT_EQ(test::validationErrorLog(cachedRun.context()), "");
    EXPECT_EQ(test::validationErrorLog(freshRun.context()), "");
    cached.reset();
    fresh.reset();
}

// path=sparse is refused naming what the device lacks: lavapipe of Mesa 22.3.6 has no sparse residency at
// all (sparseBinding, sparseResidencyImage2D, a sparse-binding queue and R32_UINT sparse formats all
// named). A device that has them all (lavapipe of 25.0.7) runs it: the next test. The features are read
// here from the device itself, the answer the refusal must agree with.
TEST(VirtualVkTest, TheSparsePathIsRefusedNamingWhatTheDeviceLacks) {
    const VulkanContext context(VulkanOptions{});
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(context.physicalDevice(), &features);
    const std::string refusal = TechniqueRegistry::createVulkan(TechniqueSpec::parse("virtual:path=sparse"))
                                    ->checkCapabilities(context);
    std::cout << (refusal.empty() ? "path=sparse runs on " + context.info().name : refusal) << "\n";
    if (!features.sparseResidencyImage2D) {
        EXPECT_NE(refusal.find("sparseResidencyImage2D"), std::string::npos) << refusal;
        EXPECT_NE(refusal.find(context.info().name), std::string::npos) << refusal;
    }
    EXPECT_EQ(TechniqueRegistry::createVulkan(TechniqueSpec::parse("virtual"))->checkCapabilities(context),
              "");
}

// path=sparse on lavapipe of Mesa 25.0.7 (in a child process on that driver, tests/SecondDriver.h): the
// map one sparse-resident image, each page bound to its slot's 64 KiB of the pool with vkQueueBindSparse,
// drawn at its own texels. Along the moving-casters path every frame's visibility equals the atomic
// path's (same texels, same bits: value for value) and its page counts are the atomic path's; the
// validation layer reports nothing.
TEST(VirtualVkTest, TheSparsePathDrawsTheAtomicPathsImagesOnTheSecondDriver) {
    REQUIRE_SECOND_DRIVER();
    if (!test::runsOnDriver(test::kSecondDriver))
        return test::runThisTestOnDriver(test::kSecondDriver, "virtual path=sparse");
    RunConfig cfg = test::quickConfig(test::virtualMovingCastersScene(), "view", 128);
    cfg.pathFrames = 8;
    VulkanHarness atomicRun(vulkanConfig(cfg)), sparseRun(vulkanConfig(cfg));
    auto atomic = TechniqueRegistry::createVulkan(TechniqueSpec::parse(kProps));
    auto sparse = TechniqueRegistry::createVulkan(TechniqueSpec::parse(std::string(kProps) + ":path=sparse"));
    ASSERT_EQ(sparse->checkCapabilities(sparseRun.context()), "");
    atomicRun.prepare(*atomic);
    sparseRun.prepare(*sparse);
    uint64_t pages = 0;
    for (int f = 0; f < 8; ++f) {
        SCOPED_TRACE("frame " + std::to_string(f));
        atomicRun.renderFrame(*atomic);
        sparseRun.renderFrame(*sparse);
        const std::vector<float> a = atomicRun.readVisibility();
        const std::vector<float> b = sparseRun.readVisibility();
        ASSERT_EQ(a.size(), b.size());
        size_t differ = 0, shadowed = 0;
        for (size_t i = 0; i < a.size(); i += 4) {
            differ += a[i] != b[i] ? 1 : 0;
            shadowed += a[i] < 1.0f ? 1 : 0;
        }
        EXPECT_EQ(differ, 0u) << "pixels whose visibility differs between the paths";
        EXPECT_GT(shadowed, 0u);
        const auto& pa = static_cast<VirtualVulkan&>(*atomic).pageCounts();
        const auto& pb = static_cast<VirtualVulkan&>(*sparse).pageCounts();
        EXPECT_EQ(pa.rendered, pb.rendered);
        EXPECT_EQ(pa.reused, pb.reused);
        pages += pb.rendered;
    }
    std::cout << "path=sparse: " << pages << " pages drawn over 8 frames, images equal to path=atomic's\n";
    EXPECT_EQ(test::validationErrorLog(sparseRun.context()), "");
    atomic.reset();
    sparse.reset();
}
