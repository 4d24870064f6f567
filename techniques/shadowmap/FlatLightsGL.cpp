#include "techniques/shadowmap/FlatLightsGL.h"

#include <glm/gtc/type_ptr.hpp>

namespace sb {

namespace {
constexpr GLint kLightMatrixLocation = 8; // common/depth.vert; common/scene.vert's shadow matrices
} // namespace

void setFlatShadowMatrices(const FlatLightFits& lights) {
    const std::vector<glm::mat4>& matrices = lights.shadowMatrices();
    if (!matrices.empty())
        glUniformMatrix4fv(kLightMatrixLocation, GLsizei(matrices.size()), GL_FALSE,
                           glm::value_ptr(matrices[0]));
}

size_t renderFlatDepth(const FlatLightFits& lights, Submitter& submitter, const InstanceCulling& culling,
                       const DepthLayers& maps, std::vector<uint8_t>& keep, bool drawAll,
                       const ViewCull* view) {
    size_t culled = 0;
    for (size_t i = 0; i < lights.size(); ++i) {
        if (!lights.castsShadow(i)) continue;
        maps.beginLayer(int(i));
        glUniformMatrix4fv(kLightMatrixLocation, 1, GL_FALSE, glm::value_ptr(lights.viewProj()[i]));
        if (drawAll) {
            submitter.draw(DrawSet::All);
            continue;
        }
        culled += lights.cullCasters(i, culling, keep, view);
        // The nearest caster per texel: back faces of closed casters can go (scenes/BackFaceCulling.h).
        submitter.drawCulled(DrawSet::Casters, {lights.viewProj()[i], false}, keep);
    }
    return culled;
}

} // namespace sb
