#pragma once
// One frame of a technique rendered through the Harness and read back, for the GL tests that judge
// visibility and colour per pixel at its world position.
#include <memory>
#include <string>
#include <vector>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/Math.h"

namespace sb::test {

struct RenderedFrame {
    std::vector<float> visibility;     ///< 4 per pixel, rows bottom-up
    std::vector<unsigned char> colour; ///< RGBA8
    std::vector<glm::vec4> world;      ///< unprojected depth; w = 0: background
    std::string permutation;
    std::vector<std::pair<std::string, double>> counters;
};

/// Prepares `technique` on `harness`, renders one frame and reads the targets back.
inline RenderedFrame renderOnce(Harness& harness, GlTechnique& technique) {
    harness.prepare(technique);
    harness.renderFrame(technique);
    RenderedFrame f;
    FrameTargets& targets = harness.targets();
    f.visibility = targets.readVisibilityRGBA32F();
    f.colour = targets.readColorRGBA8();
    const float aspect = float(targets.width()) / float(targets.height());
    const glm::mat4 viewProj = cameraProjection(harness.camera(), aspect) * cameraView(harness.camera());
    f.world = unprojectDepth(targets.readDepth(), targets.width(), targets.height(), viewProj);
    f.permutation = technique.permutationKey();
    f.counters = technique.counters();
    return f;
}

/// The technique `spec` ("planar:stencil=false") on `scene` from camera `camera`, size x size.
inline RenderedFrame renderSpec(const std::string& scene, const std::string& camera, int size,
                                const std::string& spec) {
    Harness h(quickConfig(scene, camera, size));
    std::unique_ptr<GlTechnique> t = TechniqueRegistry::create(TechniqueSpec::parse(spec));
    return renderOnce(h, *t);
}

} // namespace sb::test
