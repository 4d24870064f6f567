// `cascaded` fit=sdsm (Lauritzen, Salvi and Lefohn 2011, Sample Distribution Shadow Maps, I3D) on Vulkan,
// with the validation layer on:
//  (a) the reduction (shaders/shadowmap/depth_range.comp through techniques/shadowmap/DepthRangeVulkan.h)
//      equals the min and max the CPU finds in the same pre-pass image read back
//      (techniques/vulkan/ViewDepthVulkan.h): exact, both compare the same stored floats;
//  (b) GL and Vulkan give the same splits for the same scene and camera: the two pre-passes rasterise the
//      same triangles at the same sample positions (the Vulkan pass's y flip maps an even-sized frame's
//      pixel centres onto GL's), and differ only in how their clip z is rounded (Vulkan's clipFromGl folds
//      z' = (z + w) / 2 into the matrix; GL halves after the divide): a few float ulps of window depth,
//      which the view depth d = b / (z_ndc + a) magnifies by about d / n relative (d / n <= 140 here): 1e-4
//      relative on every split is ~10 ulps of window depth at the farthest pixel. Measured on lavapipe
//      and llvmpipe (Mesa 22.3.6): the same window depths to 6 digits, splits 1.4e-5 apart (city) and
//      identical (aircraft).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "VulkanFrame.h"
#include "bench/lib/harness/Harness.h"
#include "techniques/shadowmap/CascadedGL.h"
#include "techniques/shadowmap/CascadedVulkan.h"

using namespace sb;

namespace {

constexpr int kSize = 200;

struct View {
    const char* scene;
    const char* camera;
};
const View kViews[] = {{"city", "mid"}, {"aircraft", "mid"}};

/// The pre-pass image of `depth` as stored (D32_SFLOAT: the floats themselves), copied to the host.
std::vector<float> readBack(VulkanContext& context, const ViewDepthVulkan& depth) {
    const VkDeviceSize size = VkDeviceSize(depth.width()) * depth.height() * sizeof(float);
    VulkanBuffer host(context, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    context.submitNow([&](VkCommandBuffer cmd) {
        transitionImage(cmd, depth.image(), VK_IMAGE_ASPECT_DEPTH_BIT,
                        VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
        region.imageExtent = {depth.width(), depth.height(), 1};
        vkCmdCopyImageToBuffer(cmd, depth.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.buffer(), 1,
                               &region);
        transitionImage(cmd, depth.image(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                        VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost,
                             0, nullptr, 0, nullptr);
    });
    std::vector<float> out(size_t(size / sizeof(float)));
    std::memcpy(out.data(), host.map(), size_t(size));
    return out;
}

CascadedVulkan& cascadedOf(test::VulkanFrame& frame) {
    return dynamic_cast<CascadedVulkan&>(frame.technique());
}

TEST(CascadedSdsmVulkan, ReductionEqualsTheCpuMinMaxOfTheSameDepthImage) {
    for (const View& v : kViews) {
        test::VulkanFrame frame(test::quickConfig(v.scene, v.camera, kSize),
                                "cascaded:fit=sdsm:resolution=256");
        const CascadedVulkan& t = cascadedOf(frame);
        const std::vector<float> depth = readBack(frame.harness().context(), t.viewDepth());
        float lo = 1.0f, hi = 0.0f;
        size_t covered = 0;
        for (float d : depth)
            if (d < 1.0f) {
                lo = std::min(lo, d);
                hi = std::max(hi, d);
                ++covered;
            }
        const glm::vec2 gpu = t.depthRange().latestWindowRange();
        std::cout << v.scene << " " << v.camera << ": " << covered << " covered pixels, window depth [" << lo
                  << ", " << hi << "]\n";
        ASSERT_GT(covered, 0u) << v.scene;
        // The same stored floats, min and max: no tolerance.
        EXPECT_EQ(gpu.x, lo) << v.scene << " " << v.camera;
        EXPECT_EQ(gpu.y, hi) << v.scene << " " << v.camera;
    }
}

TEST(CascadedSdsmVulkan, SplitsEqualGlsForTheSameView) {
    for (const View& v : kViews) {
        const RunConfig cfg = test::quickConfig(v.scene, v.camera, kSize);
        const std::string spec = "cascaded:fit=sdsm:resolution=256";
        Harness gl(cfg);
        CascadedGL glForm;
        glForm.properties().apply(TechniqueSpec::parse(spec).properties);
        glForm.propertiesApplied();
        test::renderOnce(gl, glForm);
        test::VulkanFrame frame(cfg, spec);
        const std::vector<float>& a = glForm.splits();
        const std::vector<float>& b = cascadedOf(frame).splits();
        ASSERT_EQ(a.size(), b.size()) << v.scene;
        const glm::vec2 wa = glForm.depthRange().windowRange(),
                        wb = cascadedOf(frame).depthRange().windowRange();
        std::cout << v.scene << " " << v.camera << ": window depth GL [" << wa.x << ", " << wa.y
                  << "], Vulkan [" << wb.x << ", " << wb.y << "]; splits GL [" << a.front() << ", "
                  << a.back() << "], Vulkan [" << b.front() << ", " << b.back() << "]\n";
        double worst = 0.0;
        for (size_t i = 0; i < a.size(); ++i) {
            EXPECT_NEAR(b[i], a[i], 1e-4 * a[i]) << v.scene << " split " << i;
            worst = std::max(worst, std::abs(double(b[i]) - double(a[i])) / double(a[i]));
        }
        std::cout << "  largest relative difference of a split: " << worst << "\n";
    }
}

} // namespace
