#pragma once
// `blob`: fake blob shadows, a soft ellipse on the ground under each caster, after Crawfis, Ad-hoc shadows
// (CSE 781 slides). The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name,
// effects, the capabilities of each API's form, passes, properties and quality knobs; and what both
// forms compute alike on the CPU (the ground, the blobs' fit, the counters; techniques/blob/BlobGL.h
// says how a blob is fitted).
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/ReceiverPlane.h"
#include "scenes/Scene.h"
#include "techniques/Property.h"
#include "techniques/Submission.h"
#include "techniques/Technique.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Blob {
    static constexpr const char* kFade = "fade";
    static constexpr const char* kOpacity = "opacity";
    static constexpr const char* kSoftness = "softness";

    static TechniqueInfo declaration();

    /// std430 mirror of the blob records in shaders/blob/blob.vert: 3 vec4 per blob.
    struct Record {
        glm::vec4 centre; ///< xyz on the ground; w: opacity
        glm::vec4 axisU;  ///< xyz: first semi-axis (direction * length); w: light index
        glm::vec4 axisV;  ///< xyz: second semi-axis; w: softness
    };
    /// The blob of world bounds `bounds` on `ground` for `light` (its index in w of axisU), or nothing
    /// when the light is behind or in the ground's plane or the bounds lie wholly below it.
    static std::optional<Record> fit(const Aabb& bounds, const ReceiverPlane& ground, const Light& light,
                                     int lightIndex, float opacity, float softness, float fade);
    /// The receiver plane facing most nearly up (normal.y >= 0.5), if any.
    static std::optional<ReceiverPlane> findGround(const Scene& scene);
    /// findGround, with a line on stderr naming the scene where it has none (nothing is shadowed): what
    /// both APIs' setScene take.
    static std::optional<ReceiverPlane> groundOf(const Scene& scene);
    /// Each mesh's object-space bounds (Scene::meshBoundsOf), as fitAll takes them.
    static std::vector<Aabb> meshBounds(const Scene& scene);
    /// Every blob of the frame into `out`: per caster (world bounds from its mesh's object-space
    /// `meshBounds`) and shadow-casting light, with the properties' opacity, softness and fade.
    static void fitAll(const Scene& scene, const ReceiverPlane& ground, const std::vector<Aabb>& meshBounds,
                       const PropertySet& properties, std::vector<Record>& out);
    /// The counters of a frame that drew `blobs` blobs after the submitter's work `s`.
    static Counters counters(const SubmitStats& s, size_t blobs);
};

} // namespace sb
