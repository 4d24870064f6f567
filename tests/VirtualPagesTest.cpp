// `virtual`'s API-neutral core (techniques/virtual/) against hand-computed answers:
//  - the sizes of UE5's virtual map (16k^2 in 128^2 pages, Epic's documentation "Virtual Shadow Maps")
//    and of the atlas that backs a pool, and the refusal of sizes that do not tile;
//  - the marking rule: which pages a lookup reads, worked out by hand for an orthographic light looking
//    straight down on a 16 x 16 world-unit square (1024 texels, 8 x 8 pages of 128: one world unit is 64
//    texels, half a page), the seam between pages and the map's edge included;
//  - allocation, the least-recently-used eviction and the pool running out, step by step;
//  - invalidation: a light that moves drops every page, a caster that moves drops its old and new pages,
//    found from its model matrix;
//  - the cache's correctness on a moving path, in a model of the GPU: each slot of the atlas holds the
//    "depth" a page was drawn with (a hash of the light and the casters over the page), and every page a
//    frame needs must read the depth a fresh draw would give it, as the cache-off run does by
//    construction. The same walk with the casters' invalidation left out must fail (the check bites).
#include <cstring>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "core/Error.h"
#include "scenes/MeshGenerators.h"
#include "techniques/virtual/CasterFootprints.h"
#include "techniques/virtual/PageMarking.h"
#include "techniques/virtual/VirtualPageCache.h"

using namespace sb;

namespace {

/// An orthographic light above the origin looking down -Y over x, z in [-8, 8]: map x follows world x,
/// map y follows -z (lookAt's up is -Z), so texel = ((x, -z) / 16 + 0.5) * resolution.
glm::mat4 downLight() {
    return glm::ortho(-8.0f, 8.0f, -8.0f, 8.0f, 0.1f, 20.0f) *
           glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1));
}

PageRect rect(int x0, int y0, int x1, int y1) {
    return {{x0, y0}, {x1, y1}};
}

void expectRect(const PageRect& got, const PageRect& want, const char* what) {
    EXPECT_EQ(got.lo, want.lo) << what;
    EXPECT_EQ(got.hi, want.hi) << what;
}

std::vector<uint8_t> needAll(const PageGeometry& g) {
    return std::vector<uint8_t>(g.pageCount(), 1);
}

std::vector<uint8_t> needPages(const PageGeometry& g, std::initializer_list<uint32_t> pages) {
    std::vector<uint8_t> n(g.pageCount(), 0);
    for (uint32_t p : pages) n[p] = 1;
    return n;
}

/// One frame on `cache`: begin, invalidate `moved`, allocate `needed`, draw.
PageCounts frame(VirtualPageCache& cache, const glm::mat4& light, bool on, const std::vector<uint8_t>& needed,
                 const std::vector<PageRect>& moved = {}) {
    cache.beginFrame(light, on);
    cache.invalidate(moved);
    cache.allocate(needed);
    cache.rendered();
    return cache.counts();
}

/// A scene of unit boxes (half extent 1) at `positions`, the last `receivers` of them receivers only.
Scene boxes(const std::vector<glm::vec3>& positions, size_t receivers = 0) {
    Scene s;
    s.meshes.push_back(MeshGenerators::box(glm::vec3(1.0f), 1));
    s.cacheMeshBounds();
    for (size_t i = 0; i < positions.size(); ++i) {
        Instance inst;
        inst.position = positions[i];
        inst.castsShadow = i + receivers < positions.size();
        s.instances.push_back(inst);
    }
    s.updateTransforms();
    return s;
}

} // namespace

TEST(VirtualPagesTest, GeometryOfUe5SizesAndItsAtlas) {
    const PageGeometry g(16384, 128, 1000);
    EXPECT_EQ(g.pagesPerSide(), 128);
    EXPECT_EQ(g.pageCount(), 16384u);
    // 31^2 = 961 < 1000 <= 32^2: 32 slots a side, 4096 texels.
    EXPECT_EQ(g.atlasPagesPerSide(), 32);
    EXPECT_EQ(g.atlasResolution(), 4096);
    EXPECT_EQ(g.atlasOrigin(0), glm::ivec2(0, 0));
    EXPECT_EQ(g.atlasOrigin(33), glm::ivec2(128, 128));
    EXPECT_EQ(g.atlasOrigin(999), glm::ivec2(7 * 128, 31 * 128));
    EXPECT_EQ(g.pageIndex({5, 2}), 2u * 128u + 5u);
    EXPECT_EQ(g.pageCoord(2 * 128 + 5), glm::ivec2(5, 2));
    EXPECT_EQ(PageGeometry(1024, 128, 64).atlasPagesPerSide(), 8); // a perfect square stays one
}

TEST(VirtualPagesTest, LevelsHalveTheMapAndNumberTheirPagesAfterLevelZeros) {
    // 16384^2 in pages of 128: 128 pages a side, halving down to one page: 8 levels of 128^2, 64^2,
    // ... 1^2 pages, 21845 in all (4^8 - 1) / 3; level 1 starts after level 0's 16384 pages.
    EXPECT_EQ(PageGeometry::maxLevels(16384, 128), 8);
    EXPECT_EQ(PageGeometry::maxLevels(128 * 96, 128), 6); // 96 = 3 * 2^5: 96, 48, 24, 12, 6, 3
    EXPECT_EQ(PageGeometry::maxLevels(16100, 128), 0);
    const PageGeometry g(16384, 128, 1024, 8);
    EXPECT_EQ(g.pageCount(), 21845u);
    EXPECT_EQ(g.levelOffset(1), 16384u);
    EXPECT_EQ(g.levelOffset(2), 16384u + 4096u);
    EXPECT_EQ(g.levelOffset(7), 21844u);
    EXPECT_EQ(g.pagesPerSide(3), 16);
    EXPECT_EQ(g.levelResolution(3), 2048);
    EXPECT_EQ(g.tableRows(), 171); // 21845 / 128 = 170.7
    EXPECT_EQ(g.pageIndex(2, {3, 5}), 16384u + 4096u + 5u * 32u + 3u);
    const PageAddress a = g.address(16384u + 4096u + 5u * 32u + 3u);
    EXPECT_EQ(a.level, 2);
    EXPECT_EQ(a.page, glm::ivec2(3, 5));
    EXPECT_EQ(g.address(21844u).level, 7);
    // Level 0's pages (5..9, 2..3) lie in level 2's (1..2, 0..0).
    expectRect(rect(5, 2, 9, 3).atLevel(2), rect(1, 0, 2, 0), "level 2");
    try {
        PageGeometry(1024, 128, 64, 5); // 8 pages a side halve to 1 in 4 levels
        ADD_FAILURE() << "levels 5 was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        EXPECT_NE(std::string(e.what()).find("levels 5"), std::string::npos) << e.what();
    }
}

TEST(VirtualPagesTest, MarkingAndInvalidationReachEveryLevel) {
    // downLight's 16 x 16 world units in 1024 texels, 4 levels (8, 4, 2, 1 pages a side).
    const PageGeometry g(1024, 128, 85, 4);
    ASSERT_EQ(g.pageCount(), 85u);
    const PageMarking marking(g, 1.5f);
    // (1, 0, -1): level 0's texel 576; at level 2 it is 144 (of 256): page 1 of 2, its footprint
    // 142.5 .. 145.5 inside it.
    expectRect(marking.pagesOf(downLight(), {1, 0, -1}, 2), rect(1, 1, 1, 1), "level 2");
    // The origin at level 1: texel 256 of 512, the corner of four pages.
    expectRect(marking.pagesOf(downLight(), {0, 0, 0}, 1), rect(1, 1, 2, 2), "level 1 corner");
    std::vector<uint8_t> needed(g.pageCount(), 0);
    marking.mark(downLight(), {1, 0, -1}, needed, 3);
    EXPECT_EQ(needed[84], 1); // level 3's one page
    // A caster over level 0's pages (3..4, 3..4) invalidates level 1's (1..2, 1..2), level 2's
    // (0..1, 0..1) and level 3's page: 4 + 4 + 4 + 1 pages.
    VirtualPageCache cache(g);
    frame(cache, downLight(), true, needAll(g));
    const PageCounts c = frame(cache, downLight(), true, needAll(g), {rect(3, 3, 4, 4)});
    EXPECT_EQ(c.invalidated, 13u);
    EXPECT_EQ(c.reused, 85u - 13u);
}

TEST(VirtualPagesTest, SizesThatDoNotTileAreRefusedByName) {
    struct Bad {
        int resolution, page, pool;
        const char* named;
    };
    for (const Bad& b : {Bad{16100, 128, 64, "virtual_resolution 16100"}, Bad{1024, 4, 64, "page_size 4"},
                         Bad{1024, 128, 0, "pool_pages 0"}, Bad{1024, 128, 65, "pool_pages 65"}}) {
        try {
            PageGeometry(b.resolution, b.page, b.pool);
            ADD_FAILURE() << b.named << " was accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ExitCode::BadInput);
            EXPECT_NE(std::string(e.what()).find(b.named), std::string::npos) << e.what();
        }
    }
}

TEST(VirtualPagesTest, MarkingReadsTheFootprintsPagesAcrossSeamsAndNothingOutside) {
    const PageGeometry g(1024, 128, 64);
    const PageMarking marking(g, 1.5f);
    const glm::mat4 light = downLight();
    // The origin projects to texel (512, 512), the corner of four pages: 510.5 .. 513.5 reads them all.
    expectRect(marking.pagesOf(light, {0, 0, 0}), rect(3, 3, 4, 4), "origin");
    // (-7.9, 7.9): texel 0.1 / 16 * 1024 = 6.4 on both axes; 4.9 .. 7.9 stays in page (0, 0).
    expectRect(marking.pagesOf(light, {-7.9f, 0, 7.9f}), rect(0, 0, 0, 0), "near corner");
    // (1, 0, -1): texel 576 on both axes, 574.5 .. 577.5 inside page 4.
    expectRect(marking.pagesOf(light, {1, 0, -1}), rect(4, 4, 4, 4), "inside a page");
    // x = 7.99: texel 1023.36, its footprint clipped at the edge: page 7 only.
    expectRect(marking.pagesOf(light, {7.99f, 0, 0}), rect(7, 3, 7, 4), "edge");
    // Beyond the edge by more than the footprint: nothing (the lookup says lit).
    EXPECT_TRUE(marking.pagesOf(light, {8.05f, 0, 0}).empty()); // texel 1027.2, 1025.7 .. : outside
    EXPECT_TRUE(marking.pagesOf(light, {0, 0, -9}).empty());
    // Just outside, by less than the footprint: its taps inside the map read page 0.
    expectRect(marking.pagesOf(light, {-8.001f, 0, 0}), rect(0, 3, 0, 4), "just outside");
    std::vector<uint8_t> needed(g.pageCount(), 0);
    marking.mark(light, {0, 0, 0}, needed);
    marking.mark(light, {1, 0, -1}, needed); // already marked
    size_t count = 0;
    for (uint8_t n : needed) count += n;
    EXPECT_EQ(count, 4u);
    for (uint32_t p : {3u * 8 + 3, 3u * 8 + 4, 4u * 8 + 3, 4u * 8 + 4}) EXPECT_EQ(needed[p], 1) << p;
}

TEST(VirtualPagesTest, AllocationReusesEvictsTheLeastRecentlyNeededAndDropsWhenFull) {
    const PageGeometry g(512, 128, 2); // 16 pages, 2 slots
    VirtualPageCache cache(g);
    const glm::mat4 light = downLight();
    PageCounts c = frame(cache, light, true, needPages(g, {0, 1}));
    EXPECT_EQ(c.needed, 2u);
    EXPECT_EQ(c.allocated, 2u);
    EXPECT_EQ(c.rendered, 2u);
    EXPECT_EQ(cache.table().slot(0), 0u); // lowest free slot first
    EXPECT_EQ(cache.table().slot(1), 1u);
    // Frame 2 needs page 2 only: no slot is free, both were last needed in frame 1; the tie goes to the
    // lower slot, so page 0 is evicted and page 1 stays cached.
    c = frame(cache, light, true, needPages(g, {2}));
    EXPECT_EQ(c.allocated, 1u);
    EXPECT_EQ(c.evicted, 1u);
    EXPECT_EQ(c.rendered, 1u);
    EXPECT_EQ(c.reused, 0u);
    EXPECT_FALSE(cache.table().mapped(0));
    EXPECT_EQ(cache.table().slot(2), 0u);
    EXPECT_TRUE(cache.table().valid(1));
    // Frame 3 needs 1 and 2: both cached, nothing drawn.
    c = frame(cache, light, true, needPages(g, {1, 2}));
    EXPECT_EQ(c.reused, 2u);
    EXPECT_EQ(c.rendered, 0u);
    EXPECT_EQ(c.resident, 2u);
    // Frame 4 needs 0, 1 and 2: the pool holds two and both are needed this frame: page 0 is dropped.
    c = frame(cache, light, true, needPages(g, {0, 1, 2}));
    EXPECT_EQ(c.needed, 3u);
    EXPECT_EQ(c.reused, 2u);
    EXPECT_EQ(c.dropped, 1u);
    EXPECT_EQ(c.evicted, 0u);
    EXPECT_EQ(c.rendered, 0u);
    // The GPU's words: page 1 mapped to slot 1 and valid, page 0 unmapped.
    std::vector<uint32_t> words;
    cache.packTable(words);
    EXPECT_EQ(words[1], PageTable::kMappedBit | 1u);
    EXPECT_EQ(words[0], 0u);
}

TEST(VirtualPagesTest, ALightThatMovesDropsEveryPageAndTheCacheOffKeepsNone) {
    const PageGeometry g(512, 128, 16);
    VirtualPageCache cache(g);
    const glm::mat4 light = downLight();
    frame(cache, light, true, needAll(g));
    PageCounts c = frame(cache, light, true, needAll(g));
    EXPECT_EQ(c.reused, 16u);
    EXPECT_EQ(c.rendered, 0u);
    // The light turns by a hundredth of a degree: no page's depth is known any more.
    const glm::mat4 turned = light * glm::rotate(glm::mat4(1.0f), glm::radians(0.01f), glm::vec3(0, 0, 1));
    c = frame(cache, turned, true, needAll(g));
    EXPECT_EQ(c.invalidated, 16u);
    EXPECT_EQ(c.rendered, 16u);
    EXPECT_EQ(c.reused, 0u);
    // The cache off: everything drawn every frame, nothing counted as invalidated.
    VirtualPageCache off(g);
    for (int f = 0; f < 3; ++f) {
        c = frame(off, light, false, needAll(g));
        EXPECT_EQ(c.rendered, 16u);
        EXPECT_EQ(c.reused, 0u);
        EXPECT_EQ(c.invalidated, 0u);
    }
}

TEST(VirtualPagesTest, ACasterThatMovesInvalidatesItsOldAndNewPagesOnly) {
    const PageGeometry g(1024, 128, 64);
    // Caster 0 at the origin, caster 1 at (-5, 0, -5), and a receiver (which never counts) at (5, 0, 5).
    Scene s = boxes({{0, 0, 0}, {-5, 0, -5}, {5, 0, 5}}, 1);
    CasterFootprints casters;
    casters.reset(s, downLight(), g, 1.0f);
    // x, z in [-1, 1]: texels 448 .. 576, grown by one: pages 3 .. 4 on both axes.
    expectRect(casters.pages(0), rect(3, 3, 4, 4), "caster 0");
    // x, z in [-6, -4]: x texels 128 .. 256 -> 127 .. 257: pages 0 .. 2; y = -z: texels 768 .. 896
    // -> 767 .. 897: pages 5 .. 7.
    expectRect(casters.pages(1), rect(0, 5, 2, 7), "caster 1");
    EXPECT_TRUE(casters.pages(2).empty());

    VirtualPageCache cache(g);
    frame(cache, downLight(), true, needAll(g));
    // Caster 0 moves to x = 3: texels 640 .. 768, grown by one to 639 .. 769: pages 4 .. 6 (639 is the
    // last texel of page 4). The receiver moves too.
    s.instances[0].position.x = 3.0f;
    s.instances[2].position.x = 6.0f;
    s.updateTransforms();
    std::vector<PageRect> moved;
    EXPECT_EQ(casters.moved(s, moved), 1u);
    ASSERT_EQ(moved.size(), 2u);
    expectRect(moved[0], rect(3, 3, 4, 4), "old");
    expectRect(moved[1], rect(4, 3, 6, 4), "new");
    // Old and new together: columns 3 .. 6 of rows 3 .. 4, 8 pages (column 4 is in both).
    const PageCounts c = frame(cache, downLight(), true, needAll(g), moved);
    EXPECT_EQ(c.invalidated, 8u);
    EXPECT_EQ(c.rendered, 8u);
    EXPECT_EQ(c.allocated, 8u);
    EXPECT_EQ(c.reused, 56u);
    // Nothing moved since: nothing more to invalidate.
    moved.clear();
    EXPECT_EQ(casters.moved(s, moved), 0u);
    EXPECT_TRUE(moved.empty());
}

namespace {

/// A model of the GPU for the walk below: the "depth" a page gets when drawn is a hash of the light's
/// version and of every caster over the page (its index and model matrix), which is what rasterizing
/// the casters into that page depends on; the atlas holds per slot what was drawn there.
class ModelGpu {
public:
    uint64_t depthOf(uint32_t page, const Scene& s, const CasterFootprints& casters, int lightVersion,
                     const PageGeometry& g) const {
        uint64_t h = 1469598103934665603ull ^ uint64_t(lightVersion);
        const glm::ivec2 at = g.pageCoord(page);
        for (size_t i = 0; i < s.instances.size(); ++i) {
            const PageRect r = casters.pages(i);
            if (r.empty() || at.x < r.lo.x || at.x > r.hi.x || at.y < r.lo.y || at.y > r.hi.y) continue;
            uint32_t bits[16];
            std::memcpy(bits, &s.instances[i].model[0][0], sizeof bits);
            h = (h ^ i) * 1099511628211ull;
            for (uint32_t b : bits) h = (h ^ b) * 1099511628211ull;
        }
        return h;
    }
    std::map<uint32_t, uint64_t> atlas; ///< slot -> depth drawn there
};

/// Walks 48 frames of a path: caster 0 slides in x every frame, caster 2 jumps every 6th frame, caster 1
/// stays, the light turns at frame 24, and the view's needed pages (a 3 x 3 window) wander over the
/// map; the pool (12 slots for 9 needed pages) must evict. Returns the frames whose lookups would read
/// a depth other than a fresh draw's; adds the pages drawn to `rendered`.
int walk(bool cacheOn, bool invalidateCasters, uint64_t& rendered) {
    const PageGeometry g(1024, 128, 12);
    Scene s = boxes({{-6, 0, 0}, {2, 0, 2}, {5, 0, -5}});
    const Scene rest = s;
    CasterFootprints casters;
    VirtualPageCache cache(g);
    ModelGpu gpu;
    int lightVersion = 0, wrong = 0;
    glm::mat4 light = downLight();
    casters.reset(s, light, g, 1.0f);
    for (int f = 0; f < 48; ++f) {
        s.instances[0].position.x = rest.instances[0].position.x + 0.37f * float(f % 30);
        if (f % 6 == 0) s.instances[2].position.z = rest.instances[2].position.z + float((f / 6) % 3);
        s.updateTransforms();
        if (f == 24) {
            light = light * glm::rotate(glm::mat4(1.0f), glm::radians(5.0f), glm::vec3(0, 0, 1));
            ++lightVersion;
            casters.reset(s, light, g, 1.0f);
        }
        std::vector<PageRect> moved;
        casters.moved(s, moved);
        std::vector<uint8_t> needed(g.pageCount(), 0);
        const glm::ivec2 at((f / 2) % 6, (f / 3) % 6);
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) needed[g.pageIndex(at + glm::ivec2(x, y))] = 1;
        cache.beginFrame(light, cacheOn);
        if (invalidateCasters) cache.invalidate(moved);
        for (uint32_t page : cache.allocate(needed))
            gpu.atlas[cache.table().slot(page)] = gpu.depthOf(page, s, casters, lightVersion, g);
        cache.rendered();
        rendered += cache.counts().rendered;
        EXPECT_EQ(cache.counts().dropped, 0u) << "frame " << f;
        EXPECT_EQ(cache.counts().reused + cache.counts().rendered, cache.counts().needed) << "frame " << f;
        bool frameWrong = false;
        for (uint32_t page = 0; page < g.pageCount(); ++page)
            if (needed[page] &&
                gpu.atlas[cache.table().slot(page)] != gpu.depthOf(page, s, casters, lightVersion, g))
                frameWrong = true;
        wrong += frameWrong ? 1 : 0;
    }
    return wrong;
}

} // namespace

TEST(VirtualPagesTest, CachedFramesReadWhatAFreshDrawWritesAlongAMovingPath) {
    uint64_t cachedWork = 0, freshWork = 0, brokenWork = 0;
    EXPECT_EQ(walk(true, true, cachedWork), 0);
    EXPECT_EQ(walk(false, true, freshWork), 0);
    EXPECT_EQ(freshWork, 48u * 9u); // the cache off draws every needed page of every frame
    EXPECT_LT(cachedWork, freshWork) << "the cache saved no page";
    // Negative control: without the casters' invalidation the cache serves stale depth.
    EXPECT_GT(walk(true, false, brokenWork), 0);
}
