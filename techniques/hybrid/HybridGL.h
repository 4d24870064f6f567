#pragma once
// `hybrid`: two techniques in one frame, each shading the instances of its role. Coleman ("Fast
// Self-Shadowing Using Occluder Textures", Section 6.3 and Chapter 7) ends on it: "For self-shadowing of
// aircraft, the occluder texture technique is probably preferred. For shadows cast by that aircraft onto
// the ground, shadow maps or projective shadows would be preferred. A single application could certainly
// use both techniques." `-t hybrid:self=occluder:cast=shadowmap` is that application:
//   self  shades the instances that cast a shadow (the aircraft): their own surfaces, where
//         self-shadowing shows;
//   cast  shades the instances that cast none (the ground, walls): where cast shadows fall.
// Every instance is shaded once, by its role's technique: the parts' view passes (TechniqueInfo::
// viewPasses) draw only their instances (Submitter::setViewScope) while their shadow passes (maps,
// volumes, textures, flattened casters) see every caster, as each would alone. The self part runs
// first, so the cast part's receivers are depth-tested against the casters already drawn.
//
// Passes are recorded under the role's name ("self_lighting", "cast_depth", "cast_lighting"), counters
// likewise ("cast_shadow_map_texels"), with `draw_calls` and `triangles` summed over both. A role whose
// scope is empty on the scene (nothing casts, or everything does) runs no pass at all; its passes are
// recorded as skipped with that reason. The parts run at their default properties.
//
// Effects: self-shadowing comes from the self part alone; every other effect shows on both kinds of
// receiver, so the hybrid delivers it only where both parts do.
//
// No technique includes another (docs/ARCHITECTURE.md, "The rules"): the registry hands this class a
// factory for its parts.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/Submitter.h"
#include "techniques/hybrid/Hybrid.h"
#include "techniques/hybrid/HybridPart.h"

namespace sb {

class HybridGL final : public GlTechnique {
public:
    /// Makes a part by registry name (throws sb::Error for an unknown one).
    using Factory = std::function<std::unique_ptr<GlTechnique>(const std::string& name)>;
    /// `choices`: the registry names a role may take, in --list order.
    HybridGL(Factory create, std::vector<std::string> choices);
    ~HybridGL() override;

    /// Creates the parts the `self` and `cast` properties name, and derives this technique's effects,
    /// capabilities and passes from them.
    void propertiesApplied() override;
    void setScene(const Scene& scene) override;
    /// Each prepared part follows the scene as it would alone.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override;
    /// Each instance's role's technique's (HybridMapTexels).
    const MapTexels* mapTexels() const override { return &mMapTexels; }

private:
    /// One role: its technique, the instances it shades and the names its passes are recorded under.
    using Part = HybridPart<GlTechnique, Submitter>;
    Part makePart(const std::string& role, const std::string& name) const;
    void runPart(Part& part, FrameContext& ctx);

    Factory mCreate;
    std::vector<Part> mParts; ///< self, then cast
    HybridMapTexels<Part> mMapTexels{mParts};
    const Scene* mScene = nullptr;
    Counters mCounters;
};

} // namespace sb
