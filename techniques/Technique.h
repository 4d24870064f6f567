#pragma once
// The technique interface (docs/ARCHITECTURE.md, "The technique contract"). A technique declares, before it
// does anything, its name, effects, the GL capabilities it needs, its passes and its properties
// (TechniqueInfo); then the harness calls setScene (untimed precompute), compile (programs for the current
// properties, scene effects and submission mode) and execute once per measured frame. Every technique writes,
// besides colour, the visibility target (FrameTargets attachment 1: channel i = light i, 1 lit, 0 shadowed).
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Context.h"
#include "gl/FrameTargets.h"
#include "gl/ProgramCache.h"
#include "scenes/Scene.h"
#include "techniques/FrameUniforms.h"
#include "techniques/PassTimer.h"
#include "techniques/PropertySet.h"
#include "techniques/submit/Submitter.h"

namespace sb {

/// A GL requirement: a minimum version or an extension. Checked against the context before a run; a
/// missing one is a clear skip (ExitCode::Unsupported), never a crash.
struct Capability {
    std::string name; ///< shown to the user: "GL 4.5", "GL_ARB_depth_clamp"
    int glMajor = 0;  ///< version requirement (0 = none)
    int glMinor = 0;
    std::string extension; ///< extension requirement ("" = none)
};

/// A quality knob and the values `bench accuracy --sweep` walks (accuracy against time).
struct QualityKnob {
    std::string property;
    std::vector<std::string> values;
};

struct TechniqueInfo {
    std::string name;        ///< registry name, lower case: "shadowmap"
    std::string description; ///< one line for --list
    EffectMask effects = 0;  ///< what it can produce
    std::vector<Capability> capabilities;
    std::vector<std::string> passes; ///< stable names: GPU timer scopes and CSV columns
    /// The passes that draw the scene as the camera sees it (shading the visible instances), a subset
    /// of `passes`; the others make shadows (maps, volumes, textures, blurs). A hybrid technique
    /// restricts only these to the instances its part owns. Empty: {"lighting"}.
    std::vector<std::string> viewPasses;
    std::vector<PropertyDesc> properties;
    std::vector<QualityKnob> quality; ///< knobs that trade accuracy for time, with sweep values
};

/// Named counters of the last frame ("triangles", "draw_calls", "shadow_map_texels" ...), in a stable
/// order: they become CSV columns "counter_<name>".
using Counters = std::vector<std::pair<std::string, double>>;

struct CompileContext {
    ProgramCache& programs;
    const Scene& scene;
    const Submitter& submitter; ///< its defines() go into every scene-drawing program
    const Context& context;

    /// What every scene-drawing program is compiled with: the submitter's defines and the scene's
    /// shadow exceptions, each only where the scene has one (common/lighting.glsl, shadowApplies):
    /// SB_NON_RECEIVERS when an instance receives no shadow (the instance's sign carries it,
    /// Submitter::shadowSignedId), SB_SHADOWLESS_LIGHTS=<mask> when a light casts none. A scene
    /// without exceptions gets the submitter's defines alone, so its programs stay what they were.
    Defines defines() const;
};

struct FrameContext {
    const Scene& scene;
    glm::mat4 view{1.0f}, proj{1.0f};
    glm::vec3 eye{0.0f};
    FrameTargets& targets; ///< bound and cleared by the harness before execute()
    Submitter& submitter;
    PassTimer& passes;
    uint64_t frameIndex = 0;
    /// The harness's frame block (binding 0). A technique that binds a block of its own there (volume's
    /// infinite projection) leaves it bound; a hybrid binds this one again before its next part.
    const FrameUniforms* frameBlock = nullptr;
};

class Technique {
public:
    explicit Technique(TechniqueInfo info);
    virtual ~Technique() = default;
    Technique(const Technique&) = delete;
    Technique& operator=(const Technique&) = delete;

    const TechniqueInfo& info() const { return mInfo; }
    const std::string& name() const { return mInfo.name; }
    PropertySet& properties() { return mProperties; }
    const PropertySet& properties() const { return mProperties; }

    /// "" when every capability is present, else "shadowmap needs GL_ARB_x (not exposed by <renderer>)".
    std::string checkCapabilities(const Context& context) const;

    /// Untimed precompute for a scene (adjacency, planes, fitted cameras, GPU resources).
    /// Throws sb::Error(ExitCode::Unsupported) for scenes it cannot handle (e.g. a light type).
    virtual void setScene(const Scene& scene) = 0;
    /// A scene in motion (scenes/Motion.h) moved: called in every one of its frames, inside the timed
    /// frame and before execute(), with what moved (SceneChange bits: lights, casters, camera). This is
    /// the per-frame work a static scene lets setScene do once (light fits, projectors, silhouettes,
    /// caster bounds), so it is paid where an application pays it. The default runs setScene again: the
    /// whole precompute, correct for any technique; a technique overrides it with the part that depends
    /// on what moved. Never compiles: the effects, lights and instances are the same in every frame.
    virtual void sceneChanged(const Scene& scene, uint32_t changes);
    /// Builds the programs for the current properties, scene effects and submission mode.
    virtual void compile(const CompileContext& ctx) = 0;
    /// Renders one frame into ctx.targets, calling ctx.passes.begin() at each declared pass.
    virtual void execute(FrameContext& ctx) = 0;
    /// Called after properties were applied from a spec (TechniqueRegistry::create): a technique whose
    /// declaration depends on its properties (the hybrid's passes and effects) updates it here.
    virtual void propertiesApplied() {}
    /// Counters of the last executed frame.
    virtual Counters counters() const { return {}; }
    /// Sorted, '|'-joined keys of the programs compile() selected: the permutation logged per row.
    const std::string& permutationKey() const { return mPermutationKey; }

protected:
    /// For propertiesApplied(): the declaration that follows from the properties.
    TechniqueInfo& mutableInfo() { return mInfo; }
    void setPermutationKey(std::string key) { mPermutationKey = std::move(key); }

private:
    TechniqueInfo mInfo;
    PropertySet mProperties;
    std::string mPermutationKey;
};

} // namespace sb
