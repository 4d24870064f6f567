// The casters that cannot shadow anything the camera sees are left out of the passes that draw
// casters for the receivers in view (scenes/InstanceCulling: cullFlattened for planar's
// flattenings, cullShadows for projective's textures, keepReachingView for the shadow map's depth
// pass, each caster grown by the filter's footprint). The independent answer is the same technique
// with `cull=false`, which draws every caster: the frame must be the same, value for value (tolerance
// 0: the culled casters put nothing on a visible pixel, and everything else is the same draw), while
// the work drops. The aircraft scene from `near` (looking down on one aircraft from 3.5 units) has
// most of the 200 aircraft's shadows out of view; from `far` nearly all of them are in view.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

constexpr int kSize = 128;

struct Case {
    const char* culled;
    const char* unculled;
};

const Case kCases[] = {
    {"planar", "planar:cull=false"},
    {"planar:guards=false", "planar:guards=false:cull=false"},
    {"projective", "projective:cull=false"},
    {"shadowmap", "shadowmap:cull=false"},
    {"vsm", "vsm:cull=false"},
    {"esm:blur=9", "esm:blur=9:cull=false"},
    {"shadowmap:pcf=5:hardware_compare=false", "shadowmap:pcf=5:hardware_compare=false:cull=false"},
    {"shadowmap:kernel=poisson:radius=4:normal_offset=2",
     "shadowmap:kernel=poisson:radius=4:normal_offset=2:cull=false"},
};

size_t differing(const std::vector<float>& a, const std::vector<float>& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return n;
}

size_t differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return n;
}

} // namespace

TEST(CasterCulling, TheFrameIsTheSameAndTheWorkDrops) {
    for (SubmitMode mode : kAllSubmitModes) {
        Harness h(test::quickConfig("aircraft", "near", kSize, mode));
        for (const Case& c : kCases) {
            SCOPED_TRACE(std::string(c.culled) + " " + submitModeName(mode));
            auto culled = TechniqueRegistry::create(TechniqueSpec::parse(c.culled));
            auto all = TechniqueRegistry::create(TechniqueSpec::parse(c.unculled));
            const test::RenderedFrame a = test::renderOnce(h, *culled);
            const test::RenderedFrame b = test::renderOnce(h, *all);
            EXPECT_EQ(differing(a.visibility, b.visibility), 0u);
            EXPECT_EQ(differing(a.colour, b.colour), 0u);
            EXPECT_EQ(test::counter(b.counters, "casters_culled"), 0.0);
            // 200 aircraft, of which a handful shadow the view from above one of them (projective's
            // swept bounds are the looser test: 137 culled, planar's flattened ones about 190).
            EXPECT_GT(test::counter(a.counters, "casters_culled"), 100.0);
            EXPECT_LT(test::counter(a.counters, "triangles"), test::counter(b.counters, "triangles"));
            // Instanced mode draws each run of kept instances with one call (no upload), so culling
            // trades one call per mesh for a call per run: fewer triangles, not fewer draws.
            if (mode != SubmitMode::Instanced) {
                EXPECT_LT(test::counter(a.counters, "draw_calls"), test::counter(b.counters, "draw_calls"));
            }
        }
    }
}

TEST(CasterCulling, NotVacuousTheViewFromNearShowsShadowsAndFromFarKeepsMost) {
    // From near, the kept casters' shadows are on screen (the culled frame is not simply unshadowed).
    Harness near(test::quickConfig("aircraft", "near", kSize));
    for (const char* spec : {"planar", "projective"}) {
        SCOPED_TRACE(spec);
        auto t = TechniqueRegistry::create(TechniqueSpec::parse(spec));
        const test::RenderedFrame f = test::renderOnce(near, *t);
        size_t shadowed = 0;
        for (size_t i = 0; i < f.world.size(); ++i)
            shadowed += f.world[i].w != 0.0f && f.visibility[4 * i] < 0.5f;
        EXPECT_GT(shadowed, 100u);
    }
    // From far, where the view covers the layout, nearly every caster stays.
    Harness far(test::quickConfig("aircraft", "far", kSize));
    auto planar = TechniqueRegistry::create("planar");
    const test::RenderedFrame f = test::renderOnce(far, *planar);
    EXPECT_LT(test::counter(f.counters, "casters_culled"), 20.0);
}

TEST(CasterCulling, ASpotLightsMapGrowsItsMarginWithDistance) {
    // A spot's texels grow with the distance from it: the margin is taken at the farthest receiver.
    RunConfig config = test::quickConfig("aircraft", "near", kSize);
    config.sceneOptions.lightType = LightType::Spot;
    Harness h(config);
    for (const Case& c :
         {Case{"shadowmap", "shadowmap:cull=false"},
          Case{"shadowmap:kernel=poisson:radius=4", "shadowmap:kernel=poisson:radius=4:cull=false"},
          Case{"projective", "projective:cull=false"}}) {
        SCOPED_TRACE(c.culled);
        auto culled = TechniqueRegistry::create(TechniqueSpec::parse(c.culled));
        auto all = TechniqueRegistry::create(TechniqueSpec::parse(c.unculled));
        const test::RenderedFrame a = test::renderOnce(h, *culled);
        const test::RenderedFrame b = test::renderOnce(h, *all);
        EXPECT_EQ(differing(a.visibility, b.visibility), 0u);
        EXPECT_EQ(differing(a.colour, b.colour), 0u);
        EXPECT_GT(test::counter(a.counters, "casters_culled"), test::counter(b.counters, "casters_culled"));
    }
}
