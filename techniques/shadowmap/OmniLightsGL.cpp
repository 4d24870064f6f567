#include "techniques/shadowmap/OmniLightsGL.h"

#include <glm/gtc/type_ptr.hpp>

namespace sb {

namespace {
constexpr GLint kShadowMatrixLocation = 8; // common/scene.vert, common/depth.vert
constexpr GLint kMapLocation = 16;         // shadowmap/omni_lighting.glsl: ivec2 (kind, layer) per light
constexpr GLint kDepthRangeLocation = 20;  // vec2 (near, far) per light
} // namespace

void setOmniLightingUniforms(const OmniLightSet& lights, int flatBase, int omniLayers) {
    const OmniLightSet::LightingArrays a = lights.lightingArrays(flatBase, omniLayers);
    const GLsizei n = GLsizei(a.maps.size());
    glUniformMatrix4fv(kShadowMatrixLocation, n, GL_FALSE, glm::value_ptr(a.shadowMatrices[0]));
    glUniform2iv(kMapLocation, n, glm::value_ptr(a.maps[0]));
    glUniform2fv(kDepthRangeLocation, n, glm::value_ptr(a.depthRanges[0]));
}

size_t renderOmniFlatMaps(const OmniLightSet& lights, Submitter& submitter, const InstanceCulling& culling,
                          const Program& depthProgram, const DepthLayers& layers, int flatBase,
                          std::vector<uint8_t>& keep) {
    size_t culled = 0;
    bool bound = false;
    for (const OmniLight& o : lights.lights()) {
        if (o.kind != OmniMapKind::Flat) continue;
        if (!bound) depthProgram.use();
        bound = true;
        layers.beginLayer(flatBase + o.index);
        glUniformMatrix4fv(kShadowMatrixLocation, 1, GL_FALSE, glm::value_ptr(o.viewProj));
        culled += lights.cullFlatCasters(o, culling, keep);
        submitter.drawCulled(DrawSet::Casters, {o.viewProj, false}, keep);
    }
    return culled;
}

} // namespace sb
