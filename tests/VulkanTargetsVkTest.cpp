// VulkanTargets, GraphicsPipeline and TimestampRing on lavapipe: the clear and its read-backs, one
// triangle through a real pipeline (and the bottom-up row order of the read-backs), and per-pass
// timestamps collected without waiting.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "VkTestSupport.h"
#include "vk/GraphicsPipeline.h"
#include "vk/ShaderModuleCache.h"
#include "vk/TimestampRing.h"
#include "vk/VulkanTargets.h"

namespace sb {
namespace {

using test::VulkanTest;

class VulkanTargetsVkTest : public VulkanTest {};

constexpr int kWidth = 32, kHeight = 24;

TEST_F(VulkanTargetsVkTest, ClearReadsBack) {
    VulkanTargets targets(context(), kWidth, kHeight);
    EXPECT_EQ(targets.colourAttachments(), 2u);
    context().submitNow([&](VkCommandBuffer cmd) { targets.recordClear(cmd, 0.25f, 0.5f, 0.75f); });

    const std::vector<unsigned char> colour = targets.readColorRGBA8();
    ASSERT_EQ(colour.size(), size_t(kWidth * kHeight * 4));
    const int expected[4] = {64, 128, 191, 255};
    for (size_t i = 0; i < colour.size(); ++i)
        ASSERT_NEAR(int(colour[i]), expected[i % 4], 1) << "byte " << i;

    const std::vector<float> visibility = targets.readVisibilityRGBA32F();
    ASSERT_EQ(visibility.size(), size_t(kWidth * kHeight * 4));
    for (size_t i = 0; i < visibility.size(); ++i) ASSERT_EQ(visibility[i], 1.0f) << "channel " << i;

    const std::vector<float> depth = targets.readDepth();
    ASSERT_EQ(depth.size(), size_t(kWidth * kHeight));
    for (size_t i = 0; i < depth.size(); ++i) ASSERT_EQ(depth[i], 1.0f) << "pixel " << i;

    // The variant without visibility clears colour and depth only; the read-backs still work.
    targets.setVisibilityOutput(false);
    EXPECT_EQ(targets.colourAttachments(), 1u);
    EXPECT_NE(targets.renderPass(), targets.renderPass(true));
    context().submitNow([&](VkCommandBuffer cmd) { targets.recordClear(cmd, 1.0f, 0.0f, 0.0f); });
    const std::vector<unsigned char> red = targets.readColorRGBA8();
    EXPECT_EQ(int(red[0]), 255);
    EXPECT_EQ(int(red[1]), 0);
    EXPECT_EQ(targets.readVisibilityRGBA32F()[0], 1.0f); // untouched since the first clear
}

/// One triangle (tests/shaders/vk/triangle.*) over the lower-left half of NDC, x + y < 0, at depth 0.5.
class TriangleRender {
public:
    TriangleRender(VulkanContext& context, VulkanTargets& targets)
        : mContext(context), mCache(context, test::testShaderRoot()) {
        mLayout = createPipelineLayout(context, {}, sizeof(float) * 4);
        GraphicsPipelineDesc desc;
        desc.vertex = mCache.get("vk/triangle.vert", {}, ShaderStage::Vertex);
        desc.fragment = mCache.get("vk/triangle.frag", {}, ShaderStage::Fragment);
        desc.colourAttachments = targets.colourAttachments();
        desc.renderPass = targets.renderPass();
        desc.layout = mLayout;
        mPipeline = createGraphicsPipeline(context, desc);
    }
    ~TriangleRender() {
        vkDestroyPipeline(mContext.device(), mPipeline, nullptr);
        vkDestroyPipelineLayout(mContext.device(), mLayout, nullptr);
    }
    void record(VkCommandBuffer cmd, const VulkanTargets& targets) const {
        targets.beginPass(cmd);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline);
        const float red[4] = {1.0f, 0.0f, 0.0f, 1.0f};
        vkCmdPushConstants(cmd, mLayout, kPushConstantStages, 0, sizeof red, red);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRenderPass(cmd);
    }

private:
    VulkanContext& mContext;
    ShaderModuleCache mCache;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkPipeline mPipeline = VK_NULL_HANDLE;
};

// Orientation. The viewport is not flipped, so NDC y = -1 lands on Vulkan's image row 0, the top row in
// memory; the read-backs flip rows so that their row 0 is the bottom (GL's glReadPixels order). Hence
// returned row r shows NDC y = 1 - 2 (r + 0.5) / h: the triangle (NDC x + y < 0) covers the returned
// rows' *upper-left* (high row indices, small x). This is what makes GL and Vulkan images agree once
// the techniques' projections flip y for Vulkan.
TEST_F(VulkanTargetsVkTest, TriangleLandsWhereTheUnflippedViewportPutsIt) {
    VulkanTargets targets(context(), kWidth, kHeight);
    TriangleRender triangle(context(), targets);
    context().submitNow([&](VkCommandBuffer cmd) {
        targets.recordClear(cmd, 0.0f, 0.0f, 0.0f);
        triangle.record(cmd, targets);
    });
    const std::vector<unsigned char> colour = targets.readColorRGBA8();
    const std::vector<float> visibility = targets.readVisibilityRGBA32F();
    const std::vector<float> depth = targets.readDepth();

    auto at = [&](int x, int row) { return size_t(row) * kWidth + size_t(x); };
    auto covered = [&](int x, int row) { return colour[4 * at(x, row)] == 255; };
    int inside = 0, outside = 0;
    for (int row = 0; row < kHeight; ++row)
        for (int x = 0; x < kWidth; ++x) {
            const float ndcX = (x + 0.5f) / kWidth * 2.0f - 1.0f;
            const float ndcY = 1.0f - (row + 0.5f) / kHeight * 2.0f; // returned rows are bottom-up
            const float edge = ndcX + ndcY;
            if (std::abs(edge) < 2.0f * (2.0f / kHeight)) continue; // pixels the diagonal touches
            const size_t p = at(x, row);
            if (edge < 0.0f) {
                ++inside;
                ASSERT_TRUE(covered(x, row)) << "x " << x << " row " << row;
                ASSERT_EQ(int(colour[4 * p + 1]), 0);
                ASSERT_EQ(visibility[4 * p], 0.5f);
                ASSERT_NEAR(depth[p], 0.5f, 1e-6f);
            } else {
                ++outside;
                ASSERT_FALSE(covered(x, row)) << "x " << x << " row " << row;
                ASSERT_EQ(visibility[4 * p], 1.0f);
                ASSERT_EQ(depth[p], 1.0f);
            }
        }
    EXPECT_GT(inside, kWidth * kHeight / 4);
    EXPECT_GT(outside, kWidth * kHeight / 4);
    // The two points where the orientations disagree: upper-left of the returned image is covered, its
    // lower-left is not (without the row flip, or with a flipped viewport, it would be the other way).
    EXPECT_TRUE(covered(kWidth / 4, kHeight * 7 / 8));
    EXPECT_FALSE(covered(kWidth / 4, kHeight / 8));
}

TEST_F(VulkanTargetsVkTest, TimestampsPerPass) {
    if (context().timestampPeriodNs() == 0.0) GTEST_SKIP() << "the queue writes no timestamps";
    VulkanTargets targets(context(), kWidth, kHeight);
    TriangleRender triangle(context(), targets);
    TimestampRing ring(context(), 4, 2);
    std::vector<PassTimes> frames;
    for (uint64_t frame = 0; frame < 3; ++frame) {
        context().submitNow([&](VkCommandBuffer cmd) {
            ring.beginFrame(cmd, frame);
            ring.pass(cmd, "clear");
            targets.recordClear(cmd, 0.0f, 0.0f, 0.0f);
            ring.pass(cmd, "triangle");
            triangle.record(cmd, targets);
            ring.pass(cmd, "extra"); // beyond passesPerFrame: ignored, counted in "triangle"
            triangle.record(cmd, targets);
            ring.endFrame(cmd);
        });
        for (PassTimes& t : ring.collect()) frames.push_back(std::move(t));
    }
    for (PassTimes& t : ring.collect()) frames.push_back(std::move(t)); // none left: submitNow waited
    ASSERT_EQ(frames.size(), 3u);
    for (uint64_t i = 0; i < frames.size(); ++i) {
        const PassTimes& t = frames[i];
        EXPECT_EQ(t.frame, i);
        ASSERT_EQ(t.passMs.size(), 2u);
        EXPECT_EQ(t.passMs[0].first, "clear");
        EXPECT_EQ(t.passMs[1].first, "triangle");
        double sum = 0.0;
        for (const auto& [name, ms] : t.passMs) {
            EXPECT_TRUE(std::isfinite(ms)) << name;
            EXPECT_GE(ms, 0.0) << name;
            EXPECT_LT(ms, 10000.0) << name;
            sum += ms;
        }
        EXPECT_TRUE(std::isfinite(t.totalMs));
        EXPECT_GE(t.totalMs, 0.0);
        EXPECT_NEAR(t.totalMs, sum, 1e-6 + 1e-9 * sum);
    }
    EXPECT_TRUE(ring.collect().empty());
}

} // namespace
} // namespace sb
