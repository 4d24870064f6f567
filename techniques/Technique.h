#pragma once
// The technique contract (docs/ARCHITECTURE.md, "The technique contract"), what every API's form of a
// technique keeps: the declaration (TechniqueInfo, from the technique's API-neutral file), its properties,
// the scene-side calls (setScene, untimed precompute; sceneChanged, a scene in motion moved), the counters
// of the last frame and the permutation it compiled. What a form does with its API (compile, execute)
// is in its API's contract: techniques/gl/GlTechnique.h, techniques/vulkan/VulkanTechnique.h. The run
// loop holds techniques by this class and hands them to the harness of their API.
#include <cstdint>
#include <string>
#include <utility>

#include "scenes/Scene.h"
#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

class MapTexels;

class Technique {
public:
    explicit Technique(TechniqueInfo info);
    virtual ~Technique() = default;
    Technique(const Technique&) = delete;
    Technique& operator=(const Technique&) = delete;

    /// The API this form renders with.
    virtual Api api() const = 0;
    const TechniqueInfo& info() const { return mInfo; }
    const std::string& name() const { return mInfo.name; }
    PropertySet& properties() { return mProperties; }
    const PropertySet& properties() const { return mProperties; }

    /// Untimed precompute for a scene (adjacency, planes, fitted cameras, API resources).
    /// Throws sb::Error(ExitCode::Unsupported) for scenes it cannot handle (e.g. a light type).
    virtual void setScene(const Scene& scene) = 0;
    /// A scene in motion (scenes/Motion.h) moved: called in every one of its frames, inside the timed
    /// frame and before execute(), with what moved (SceneChange bits: lights, casters, camera). This is
    /// the per-frame work a static scene lets setScene do once (light fits, projectors, silhouettes,
    /// caster bounds), so it is paid where an application pays it. The default runs setScene again: the
    /// whole precompute, correct for any technique; a technique overrides it with the part that depends
    /// on what moved. Never compiles: the effects, lights and instances are the same in every frame.
    virtual void sceneChanged(const Scene& scene, uint32_t changes);
    /// Called after properties were applied from a spec (the registry's create): a technique whose
    /// declaration depends on its properties (the hybrid's passes and effects) updates it here.
    virtual void propertiesApplied() {}
    /// Counters of the last executed frame.
    virtual Counters counters() const { return {}; }
    /// Where the last executed frame's lighting pass looked world points up in its shadow maps
    /// (techniques/MapTexels.h; the accuracy judge's texels per pixel); null for a technique that reads no
    /// shadow map.
    virtual const MapTexels* mapTexels() const { return nullptr; }
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

/// The defines a scene adds to every scene-drawing program, on either API (common/lighting.glsl):
/// - its shadow exceptions, each only where the scene has one: SB_NON_RECEIVERS when an instance
///   receives no shadow (the instance's sign carries it), SB_SHADOWLESS_LIGHTS=<mask> when a light casts
///   none (shadowApplies);
/// - its lights' kinds, a bit per light index: SB_POSITIONAL_LIGHTS (point or spot), SB_SPOT_LIGHTS and
///   SB_RANGED_LIGHTS (a positional light with a range), under SB_STATIC_LIGHTS. A light's kind and range
///   are fixed once the scene is loaded (motion moves lights, it does not change them), and llvmpipe runs
///   both sides of a branch on a uniform under a mask: known at compile time, a directional light's
///   fragments skip the distance, range and cone terms they would discard;
/// - under SB_STATIC_LIGHTS too, what is fixed once the scene is loaded, as constants: its ambient light,
///   SB_AMBIENT=<vec3> (ambientDefine), and each light's colour and range, SB_LIGHT_COLORS=<vec4[4]>, and
///   cone, SB_LIGHT_CONES=<vec2[4]> (techniques/FrameBlock.h, lightConstants). A constant costs the
///   fragment stage nothing where a uniform read does not (common/lighting.glsl); the lights' positions
///   and directions, which motion changes, stay uniforms;
/// - its lighting rate (addLightingRateDefines).
void addSceneDefines(const Scene& scene, Defines& defines);
/// A scene lit per vertex (Scene::lighting, scenes/LightingRate.h): SB_VERTEX_LIGHTING and
/// SB_LIGHT_TERMS=<its light count, 1 to kMaxLights>, so that common/lighting.glsl's lightTerm reads the
/// terms the vertex stage wrote (writeVertexLighting). Nothing for a scene lit per fragment. Part of
/// addLightKindDefines; the reference's shading pass, which takes no light kinds, adds it alone.
void addLightingRateDefines(const Scene& scene, Defines& defines);
/// SB_AMBIENT's value for an ambient colour: "vec3(0.15)" for a grey, "vec3(0.1,0.2,0.3)" otherwise, each
/// float written so that it parses back to the identical float (the uniform's value, bit for bit).
std::string ambientDefine(const glm::vec3& ambient);
/// The light kinds, the scene's constants and the lighting rate (the last three items above), for programs
/// that take no shadow exceptions (the lit passes of `none`, `blob`, `planar`, `projective` and `volume`,
/// which apply their own).
void addLightKindDefines(const Scene& scene, Defines& defines);
/// `defines` with the light kinds of `scene` added (addLightKindDefines).
Defines withLightKinds(Defines defines, const Scene& scene);

} // namespace sb
