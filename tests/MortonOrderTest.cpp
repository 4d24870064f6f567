// Unit tests of scenes/MortonOrder: codes computed by hand from the definition (10 bits per axis,
// x in bit 3i, y in 3i+1, z in 3i+2), and the order of a hand-made grid against its Z-curve written out.
#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "scenes/MortonOrder.h"

using namespace sb;

namespace {

Aabb unitBox() {
    Aabb b;
    b.extend(glm::vec3(0.0f));
    b.extend(glm::vec3(1.0f));
    return b;
}

} // namespace

TEST(MortonOrder, CodesFollowTheInterleavingByHand) {
    const Aabb box = unitBox();
    EXPECT_EQ(mortonCode({0, 0, 0}, box), 0u);
    // Cell 1023 on one axis: its ten bits at every third position from 0, 1 or 2.
    EXPECT_EQ(mortonCode({1, 0, 0}, box), 0x09249249u);
    EXPECT_EQ(mortonCode({0, 1, 0}, box), 0x12492492u);
    EXPECT_EQ(mortonCode({0, 0, 1}, box), 0x24924924u);
    EXPECT_EQ(mortonCode({1, 1, 1}, box), 0x3FFFFFFFu);
    // 0.5 is cell 512 (bit 9 of x: bit 27 of the code); 0.25 is cell 256 (bit 8 of y: bit 25).
    EXPECT_EQ(mortonCode({0.5f, 0.25f, 0}, box), (1u << 27) | (1u << 25));
    // Outside the bounds clamps to the nearest cell.
    EXPECT_EQ(mortonCode({-5, 7, 0}, box), 0x12492492u);
}

TEST(MortonOrder, AnAxisWithoutExtentQuantisesToZero) {
    Aabb flat;
    flat.extend(glm::vec3(0, 2, 0));
    flat.extend(glm::vec3(1, 2, 1));
    EXPECT_EQ(mortonCode({1, 2, 0}, flat), 0x09249249u);
}

TEST(MortonOrder, IsAPermutationSortedByCodeAndStableForTies) {
    // Three copies of one point (indices 1, 3, 5) among others: equal codes keep their input order.
    const std::vector<glm::vec3> points = {{9, 9, 9}, {2, 2, 2}, {0, 0, 0}, {2, 2, 2},
                                           {9, 0, 0}, {2, 2, 2}, {0, 9, 9}};
    const std::vector<size_t> order = mortonOrder(points);
    std::vector<size_t> identity(points.size());
    std::iota(identity.begin(), identity.end(), size_t(0));
    ASSERT_TRUE(std::is_permutation(order.begin(), order.end(), identity.begin(), identity.end()));
    Aabb bounds;
    for (const glm::vec3& p : points) bounds.extend(p);
    for (size_t k = 1; k < order.size(); ++k)
        EXPECT_LE(mortonCode(points[order[k - 1]], bounds), mortonCode(points[order[k]], bounds));
    std::vector<size_t> ties;
    for (size_t i : order)
        if (points[i] == glm::vec3(2, 2, 2)) ties.push_back(i);
    EXPECT_EQ(ties, (std::vector<size_t>{1, 3, 5}));
    EXPECT_TRUE(mortonOrder({}).empty());
}

TEST(MortonOrder, AShuffledGridComesBackAlongTheZCurve) {
    // A 4x4 grid (x, y in 0..3, z 0) listed in a scrambled order. Over bounds [0,3] the cells are 0, 341,
    // 682, 1023, whose two high bits are 00, 01, 10, 11: the order is the 4x4 Z-curve, which visits each
    // 2x2 quadrant whole before the next (x before y inside each).
    const int scrambled[16] = {13, 2, 7, 0, 11, 4, 15, 9, 1, 14, 6, 3, 8, 12, 5, 10}; // grid index y*4+x
    std::vector<glm::vec3> points;
    for (int g : scrambled) points.emplace_back(float(g % 4), float(g / 4), 0.0f);
    std::vector<int> visited;
    for (size_t i : mortonOrder(points)) visited.push_back(scrambled[i]);
    const std::vector<int> zCurve = {0, 1, 4, 5, 2, 3, 6, 7, 8, 9, 12, 13, 10, 11, 14, 15};
    EXPECT_EQ(visited, zCurve);
    // Neighbours end up together: every run of four in the order is one 2x2 quadrant (no point farther
    // than sqrt(2) from another in it), where the scrambled input's runs span up to the whole grid.
    for (size_t k = 0; k < 16; k += 4)
        for (size_t a = k; a < k + 4; ++a)
            for (size_t b = k; b < k + 4; ++b) {
                const int ga = visited[a], gb = visited[b];
                EXPECT_LE(std::abs(ga % 4 - gb % 4), 1);
                EXPECT_LE(std::abs(ga / 4 - gb / 4), 1);
            }
}
