#pragma once
// `virtual` on GL, first slice (NOTES-virtual.md): one directional light that casts shadows (others are
// refused, ExitCode::Unsupported, naming the light), the atomic path (EEVEE-Next's: casters rasterized in
// the virtual map's coordinates into a framebuffer with no attachments, each fragment writing its depth
// into its page's slot of the atlas with imageAtomicMin, shaders/virtual/page_depth.frag). All of one
// frame's passes run inside pass "depth": the receivers' depth from the camera and the page marks
// (shaders/virtual/mark.frag, an image store per page a visible fragment's lookup reads), the marks read
// back and allocated on the CPU (VirtualPageCache, both APIs' one home of the rule), the table uploaded,
// the pages to draw cleared and drawn row run by row run under a scissor with the casters culled to the
// run. Pass "lighting": shaders/virtual/lighting.frag, each PCF tap through its own page.
//
// The light's map is fitted once to the whole scene (LightFitBounds::Scene) and refitted only when the
// light moves, so that casters moving and the camera moving leave the light's transform, and the cache,
// alone. Needs GL 4.5 (image load/store, framebuffers without attachments, glClearTexSubImage) and a
// viewport and framebuffer of virtual_resolution texels: a context with smaller limits is refused naming
// them.
#include <cstdint>
#include <optional>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/virtual/CasterFootprints.h"
#include "techniques/virtual/VirtualPageCache.h"

namespace sb {

class VirtualGL final : public GlTechnique {
public:
    VirtualGL();
    ~VirtualGL() override;
    void setScene(const Scene& scene) override;
    /// A moved light refits the map (the cache then drops every page); moved casters queue their old
    /// and new pages for the next frame's invalidation.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    /// The last frame's page counts (also in counters()).
    const PageCounts& pageCounts() const { return mCache->counts(); }

private:
    void release();
    void fitLight(const Scene& scene);
    void markPages(FrameContext& ctx);
    void allocatePages();
    void renderPages(FrameContext& ctx);
    void renderLighting(FrameContext& ctx);

    std::optional<VirtualPageCache> mCache;
    CasterFootprints mCasters;
    std::vector<PageRect> mMoved; ///< pages moved casters covered, for the next frame's invalidation
    int mLight = -1;              ///< the light with a map; -1: none casts shadows
    glm::mat4 mLightViewProj{1.0f};
    InstanceCulling mCulling;
    std::vector<uint8_t> mKeep;
    std::vector<uint8_t> mNeeded;
    std::vector<uint32_t> mWords;
    GLuint mRequests = 0; ///< R32UI, a texel per page: 1 where marked
    GLuint mTable = 0;    ///< R32UI, a texel per page: PageTable::packed
    GLuint mAtlas = 0;    ///< R32UI, the pool's slots: depth bits
    GLuint mEmptyFbo = 0; ///< no attachments, virtual_resolution^2
    const Program* mMarkProgram = nullptr;
    const Program* mPageProgram = nullptr;
    LitPrograms mLighting;
    Counters mCounters;
};

} // namespace sb
