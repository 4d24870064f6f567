// Unit tests of techniques/EffectCoverage: the three masks of a row and the shortfall line, against masks
// and sentences written out by hand for the built-in scenes' requests and the registry's declared effects.
#include <gtest/gtest.h>

#include "registry/TechniqueRegistry.h"
#include "techniques/EffectCoverage.h"

using namespace sb;

TEST(EffectCoverage, PlanarOnAircraftMissesSelfShadowingOnly) {
    // aircraft asks for hard shadows and self-shadowing; planar projects onto a plane: hard shadows and
    // several lights, no self-shadowing (techniques/planar/PlanarGL.h).
    const EffectMask aircraft = Effect::HardShadows | Effect::SelfShadowing;
    const EffectMask planar = Effect::HardShadows | Effect::MultipleLights;
    const EffectCoverage c = EffectCoverage::of(aircraft, planar);
    EXPECT_EQ(c.requested, aircraft);
    EXPECT_EQ(c.delivered, uint32_t(Effect::HardShadows));
    EXPECT_EQ(c.missing, uint32_t(Effect::SelfShadowing));
    EXPECT_TRUE(c.fallsShort());
    EXPECT_EQ(c.shortfall("planar", "aircraft"),
              "planar cannot produce self_shadowing, which scene aircraft asks for");
    EXPECT_EQ(effectMaskToString(c.delivered), "hard_shadows");
}

TEST(EffectCoverage, EffectsOfferedButNotAskedForAreNeitherDeliveredNorMissing) {
    // painting_machine asks for soft shadows, colour bleeding and several lights; a shadow map offers
    // hard shadows, self-shadowing, non-planar receivers and several lights.
    const EffectMask painting = Effect::SoftShadows | Effect::ColourBleeding | Effect::MultipleLights;
    const EffectMask map =
        Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers | Effect::MultipleLights;
    const EffectCoverage c = EffectCoverage::of(painting, map);
    EXPECT_EQ(c.delivered, uint32_t(Effect::MultipleLights));
    EXPECT_EQ(c.missing, Effect::SoftShadows | Effect::ColourBleeding);
    EXPECT_EQ(effectMaskToString(c.missing), "soft_shadows+colour_bleeding");
    EXPECT_EQ(c.delivered | c.missing, c.requested);
    EXPECT_EQ(c.delivered & c.missing, 0u);
}

TEST(EffectCoverage, NothingMissingIsNoShortfall) {
    const EffectCoverage c =
        EffectCoverage::of(Effect::HardShadows | Effect::SelfShadowing,
                           Effect::HardShadows | Effect::SelfShadowing | Effect::MultipleLights);
    EXPECT_EQ(c.missing, 0u);
    EXPECT_FALSE(c.fallsShort());
    EXPECT_EQ(c.shortfall("volume", "aircraft"), "");
    EXPECT_EQ(effectMaskToString(c.missing), "none");
}

TEST(EffectCoverage, BaselinesMissEverythingButNeverFallShort) {
    // `none` and `synthetic` declare no effect: the row records what they miss, a run never warns.
    for (const char* name : {"none", "synthetic"}) {
        const auto t = TechniqueRegistry::create(TechniqueSpec::parse(name));
        const EffectCoverage c =
            EffectCoverage::of(Effect::HardShadows | Effect::SelfShadowing, t->info().effects);
        EXPECT_TRUE(c.baseline()) << name;
        EXPECT_EQ(c.missing, Effect::HardShadows | Effect::SelfShadowing) << name;
        EXPECT_FALSE(c.fallsShort()) << name;
    }
    // A scene that asks for nothing (synthetic_draws) leaves nothing missing for anyone.
    const EffectCoverage empty = EffectCoverage::of(0, uint32_t(Effect::HardShadows));
    EXPECT_EQ(empty.missing, 0u);
    EXPECT_FALSE(empty.fallsShort());
}

TEST(EffectCoverage, EveryShadowTechniqueOfTheRegistryDeclaresSomething) {
    // The baseline rule exempts a technique only by declaring nothing: every technique that draws shadows
    // must declare at least one effect, or it would silently escape the warning and --strict-effects.
    for (const auto& entry : TechniqueRegistry::entries()) {
        const auto t = TechniqueRegistry::describe(TechniqueSpec{entry.name, {}});
        const std::string& name = t->info().name;
        if (name == "none" || name == "synthetic") continue;
        EXPECT_NE(t->info().effects, 0u) << name;
    }
}
