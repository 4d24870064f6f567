#pragma once
// What the GL and Vulkan forms of `proxy` share, API-neutral: the proxies of the scene and their GPU
// records (setScene), the permutation the properties and the scene choose (defines), steps 2 and 3 of
// the chapter's pipeline on the CPU each frame (build: clipping, numbering, the IndexMap, the records
// of the proxies in view in the grid's numbering), the values of the lit pass's uniforms, and the
// counters. Each form only uploads what build() produced and draws.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Scene.h"
#include "scenes/ShadowProxy.h"
#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/proxy/ProxyIndexGrid.h"

namespace sb {

class ProxyPlan {
public:
    /// std430 mirror of `struct Proxy` in shaders/proxy/lit.frag.
    struct GpuProxy {
        glm::mat4 toLocal, toWorld;
        glm::vec4 diffuse;    ///< w: shape
        glm::vec4 reflective; ///< w: owner object id
    };
    /// The lit pass's uniforms (GL sets them by location; Vulkan's std140 ProxyBlock mirrors this).
    struct Uniforms {
        glm::vec4 shading{0.0f}; ///< offset, shadow factor, falloff exponent, cutoff
        glm::ivec2 cells{1};
        glm::vec2 viewport{1.0f};
        float start = 0.0f, penumbra = 0.0f, bleed = 0.0f;
        int32_t capacity = 1, count = 0;
        float pad[3] = {0.0f, 0.0f, 0.0f};
    };

    /// The proxies (declared or fitted), their records and the permutation's switches.
    void setScene(const Scene& scene, const PropertySet& properties);
    /// LIGHT_COUNT and the PROXY_* switches added to `defines`.
    Defines defines(Defines defines, const PropertySet& properties) const;
    /// Steps 2 and 3 for this frame's camera: the grid (one cell holding every proxy in view when
    /// grid=off) and inView(); warns once when a cell overflowed.
    void build(const glm::mat4& viewProj, const PropertySet& properties);
    /// The uniforms of the lit pass for a `width` x `height` target.
    Uniforms uniforms(const PropertySet& properties, int width, int height) const;
    /// The counters of the frame, given the lit pass's draw statistics.
    Counters counters(const SubmitStats& lit) const;

    bool useGrid() const { return mUseGrid; }
    bool rays() const { return mRays; }   ///< PROXY_RAYS: the lit pass reads the penumbra
    bool bleed() const { return mBleed; } ///< PROXY_BLEED: the lit pass reads the bleed amount
    size_t proxyCount() const { return mProxies.size(); }
    /// The most records a frame uploads, and the IndexMap's entries (both at least 1): buffer sizes.
    size_t maxInView() const { return std::max<size_t>(1, mProxies.size()); }
    size_t indexEntries(const PropertySet& properties) const;
    const std::vector<GpuProxy>& inView() const { return mInView; }
    const ProxyIndexGrid& grid() const { return mGrid; }

private:
    std::vector<ShadowProxy> mProxies; ///< world space, every caster's
    std::vector<GpuProxy> mRecords;    ///< per entry of mProxies
    std::vector<GpuProxy> mInView;     ///< this frame's upload, in the grid's numbering
    ProxyIndexGrid mGrid;
    bool mUseGrid = true, mModulate = false, mRays = false, mBleed = false, mWarnedOverflow = false;
    int mLights = 1, mCells = 64, mCapacity = 16;
};

} // namespace sb
