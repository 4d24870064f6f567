#pragma once
// `shadowmap`: two-pass shadow mapping (Williams 1978; thesis section 2.4). Pass "depth" renders the
// casters from each light into a layer of a depth texture array, with glPolygonOffset as constant and
// slope-scaled bias; pass "lighting" renders the scene once, comparing each fragment's light-space
// depth with the map (PCF_SIZE^2 taps, hardware compare or shader compare) for every light.
// Directional lights get an orthographic light camera fitted to the casters; spot lights a perspective
// one with the spot cone (scenes/LightFit.h). Point lights need a cube map: refused with
// ExitCode::Unsupported.
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "techniques/Technique.h"

namespace sb {

class ShadowMapTechnique final : public Technique {
public:
    ShadowMapTechnique();
    ~ShadowMapTechnique() override;
    void setScene(const Scene& scene) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    void renderDepth(FrameContext& ctx);
    void renderLighting(FrameContext& ctx);
    void allocateMaps(int resolution, int layers);
    void releaseMaps();

    std::vector<glm::mat4> mLightViewProj; ///< per light
    std::vector<glm::mat4> mShadowMatrix;  ///< per light: bias * lightViewProj (to [0,1] texture space)
    GLuint mDepthArray = 0;
    std::vector<GLuint> mFbos; ///< per light: the layer as depth attachment
    int mResolution = 0, mLayers = 0;
    const Program* mDepthProgram = nullptr;
    const Program* mLightingProgram = nullptr;
    Counters mCounters;
};

} // namespace sb
