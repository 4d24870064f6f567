#pragma once
// The GL side of OmniLightSet (cubemap's and paraboloid's lights): their lighting uniforms and their flat
// maps' depth pass.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/ProgramCache.h"
#include "scenes/InstanceCulling.h"
#include "techniques/gl/Submitter.h"
#include "techniques/shadowmap/DepthLayers.h"
#include "techniques/shadowmap/OmniLightSet.h"

namespace sb {

/// Sets the bound lighting program's per-light uniforms from OmniLightSet::lightingArrays: the shadow
/// matrices (location 8, common/scene.vert), map kind and first layer (location 16) and omni depth range
/// (location 20, shadowmap/omni_lighting.glsl).
void setOmniLightingUniforms(const OmniLightSet& lights, int flatBase, int omniLayers);

/// Renders every flat map of `lights` into `layers` (layer flatBase + index) with `depthProgram`, each
/// light's casters culled against its frustum; viewport, bias and colour mask are the caller's. Returns
/// the casters culled over all flat maps.
size_t renderOmniFlatMaps(const OmniLightSet& lights, Submitter& submitter, const InstanceCulling& culling,
                          const Program& depthProgram, const DepthLayers& layers, int flatBase,
                          std::vector<uint8_t>& keep);

} // namespace sb
