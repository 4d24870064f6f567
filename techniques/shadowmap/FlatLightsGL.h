#pragma once
// The GL side of FlatLightFits (shadowmap's and pcss's lights): their shadow matrices as uniforms and
// their maps' depth pass.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "scenes/InstanceCulling.h"
#include "techniques/FlatLightFits.h"
#include "techniques/gl/Submitter.h"
#include "techniques/shadowmap/DepthLayers.h"

namespace sb {

/// Sets the bound lighting program's shadow matrices (location 8, common/scene.vert), one per light.
void setFlatShadowMatrices(const FlatLightFits& lights);

/// The depth pass of every light of `lights` that casts shadows into layer i of `maps` (the depth program
/// bound, DepthPassState set by the caller): clears the layer, sets the light's matrix (location 8,
/// common/depth.vert) and draws the casters FlatLightFits::cullCasters keeps, or everything when
/// `drawAll` (the perf gate's injected regression, core/Injection.h). Returns the casters culled over all
/// lights.
size_t renderFlatDepth(const FlatLightFits& lights, Submitter& submitter, const InstanceCulling& culling,
                       const DepthLayers& maps, std::vector<uint8_t>& keep, bool drawAll = false,
                       const ViewCull* view = nullptr);

} // namespace sb
