#pragma once
// `planar`: projected planar shadows, after Crawfis, Ad-hoc shadows (CSE 781 slides).
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs; and what both forms compute
// alike on the CPU (the flattenings, the proxy occluders' records, the counters).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/ReceiverPlane.h"
#include "scenes/Scene.h"
#include "techniques/Submission.h"
#include "techniques/SubmissionPlan.h"
#include "techniques/Technique.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Planar {
    static constexpr const char* kCull = "cull";
    static constexpr const char* kDarkness = "darkness";
    static constexpr const char* kGuards = "guards";
    static constexpr const char* kOccluder = "occluder";
    static constexpr const char* kStencil = "stencil";

    static TechniqueInfo declaration();

    /// One flattening: a receiver plane and a light in front of it.
    struct Projection {
        size_t plane = 0;
        int light = 0;
        glm::vec4 lightPos{0.0f}; ///< homogeneous (ReceiverPlane::homogeneousLight)
        glm::mat4 matrix{1.0f};   ///< ReceiverPlane::projection
    };
    /// The (plane, light) pairs that get shadows: with `guards`, only lights strictly in front of the
    /// plane (P.L > 1e-6 |L|); without, every pair (a light behind or in the plane then makes the
    /// slides' anti-shadows).
    static std::vector<Projection> projections(const std::vector<ReceiverPlane>& planes, const Scene& scene,
                                               bool guards);

    /// The unit shapes of ShadowProxy (sphere radius 1, box [-1, 1]^3, cylinder radius 1 around z, z in
    /// [-1, 1]), coarse: an occluder proxy is meant to be cheap. Mesh i is shape i.
    static Scene unitShapes();
    /// occluder=proxy: the casters' proxies grouped by shape, one instanced draw per shape.
    struct ProxyBatch {
        size_t shape = 0;              ///< mesh of unitShapes()
        uint32_t first = 0, count = 0; ///< instance range in `records`
    };
    struct ProxyPlan {
        std::vector<InstanceRecord> records;
        std::vector<ProxyBatch> batches; ///< the shapes with at least one proxy
        uint64_t triangles = 0;          ///< per flattening
    };
    static ProxyPlan planProxies(const Scene& scene, const Scene& shapes);

    /// The counters of a frame: `proxyBatches` draws of `proxyTriangles` triangles per flattening with
    /// occluder=proxy (0 with mesh occluders) on top of the submitter's.
    struct FrameCounts {
        size_t planes = 0, flattenings = 0, culled = 0, proxyBatches = 0;
        uint64_t proxyTriangles = 0;
        bool proxies = false;
    };
    static Counters counters(const SubmitStats& s, const FrameCounts& f, const Scene& scene);
};

} // namespace sb
