// Unit tests of techniques/proxy/ProxyIndexGrid (the IndexMap, OpenGL Insights ShadowProxies section 1.3):
// cell rectangles against hand-computed projections, numbering of the proxies in view, clipping,
// proxies reaching behind the eye, indices above 255, and counted overflow.
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "techniques/proxy/ProxyIndexGrid.h"

using namespace sb;

namespace {

ShadowProxy box(const glm::vec3& centre, const glm::vec3& half) {
    ShadowProxy p;
    p.shape = ShadowProxy::Shape::Box;
    p.frame = glm::scale(glm::translate(glm::mat4(1.0f), centre), half);
    return p;
}

} // namespace

TEST(ProxyIndexGridTest, CellsCoverTheProjectedInfluenceBounds) {
    // viewProj = identity: NDC = world xy (z in [-1, 1] inside). A 4 x 4 grid has cells 0.5 wide.
    // Box x in [-0.6, -0.1], y in [0.1, 0.4] grown by 0.05: x [-0.65, -0.05] -> cells 0 .. 1,
    // y [0.05, 0.45] -> cells 2 .. 2.
    ProxyIndexGrid g;
    g.build({box({-0.35f, 0.25f, 0.0f}, {0.25f, 0.15f, 0.1f})}, glm::mat4(1.0f), 0.05f, 4, 4, 4);
    ASSERT_EQ(g.visible().size(), 1u);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const bool expected = x <= 1 && y == 2;
            EXPECT_EQ(g.count(x, y), expected ? 1u : 0u) << x << "," << y;
            if (expected) {
                EXPECT_EQ(g.cell(x, y)[0], 1u); // visible index 0, stored + 1
            }
        }
    EXPECT_EQ(g.overflow(), 0u);
}

TEST(ProxyIndexGridTest, ClippedProxiesAreNotNumberedAndBehindTheEyeCoversAll) {
    // A perspective camera at the origin looking down -z: a proxy behind it (z = +5) is clipped, one
    // in front (z = -5) is numbered 0, one straddling the eye covers every cell.
    const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
    ProxyIndexGrid g;
    g.build(
        {box({0, 0, 5}, glm::vec3(0.5f)), box({0, 0, -5}, glm::vec3(0.5f)), box({0, 0, 0}, glm::vec3(0.5f))},
        vp, 0.0f, 8, 8, 4);
    ASSERT_EQ(g.visible(), (std::vector<uint32_t>{1, 2}));
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            // The straddling proxy (visible index 1) is in every cell; the one at z = -5 (half size 0.5
            // at distance 5 against a half view of 5 tan 30 = 2.9: the middle cells) only in some.
            bool hasStraddling = false;
            for (uint32_t k = 0; k < g.count(x, y); ++k)
                hasStraddling = hasStraddling || g.cell(x, y)[k] == 2u;
            EXPECT_TRUE(hasStraddling) << x << "," << y;
        }
    EXPECT_EQ(g.count(0, 0), 1u); // the corner cell: only the straddling one
    EXPECT_EQ(g.count(4, 4), 2u); // the middle: both
}

TEST(ProxyIndexGridTest, IndicesAbove255AndOverflowIsCounted) {
    // 300 small proxies in one cell of a 2 x 2 grid with capacity 256: the chapter's bytes would wrap at
    // 255; here index 299 is stored as 300 where it fits, and the 44 that do not fit are counted.
    std::vector<ShadowProxy> proxies;
    for (int i = 0; i < 300; ++i) proxies.push_back(box({-0.5f, -0.5f, 0.0f}, glm::vec3(0.01f)));
    ProxyIndexGrid g;
    g.build(proxies, glm::mat4(1.0f), 0.0f, 2, 2, 256);
    EXPECT_EQ(g.visible().size(), 300u);
    EXPECT_EQ(g.count(0, 0), 256u);
    EXPECT_EQ(g.cell(0, 0)[255], 256u); // visible index 255 -> 256: beyond a byte
    EXPECT_EQ(g.overflow(), 44u);
    EXPECT_EQ(g.count(1, 1), 0u);
}
