#pragma once
// `virtual` on GL (NOTES-virtual.md): one directional or spot light that casts shadows (others refused,
// ExitCode::Unsupported, naming the light: VirtualMaps), the atomic path (EEVEE-Next's: casters
// rasterized in the virtual map's coordinates into a framebuffer with no attachments, each fragment
// writing its depth into its page's slot of the atlas with imageAtomicMin, shaders/virtual/
// page_depth.frag). All of one frame's passes but the lighting run inside pass "depth": the receivers'
// depth from the camera and the page marks (shaders/virtual/mark.frag, an image store per page a
// visible fragment's lookup reads, at the level its pixel's footprint picks), the marks read back and
// allocated on the CPU (VirtualMaps, both APIs' one home of the rule), the table uploaded, the pages to
// draw cleared and drawn run by run under a scissor with the casters culled to the run. Pass "lighting":
// shaders/virtual/lighting.frag, each PCF tap through its own page.
//
// Needs GL 4.5 (image load/store, framebuffers without attachments, glClearTexSubImage) and a viewport
// and framebuffer of virtual_resolution texels: a context with smaller limits is refused naming them.
// The view's depth is drawn here by the marking program itself rather than read from the shared pre-pass
// (techniques/gl/ViewDepthGL.h): the marking's EQUAL re-draw must meet depths written by the same vertex
// program, as GLSL's invariance holds only within one program; a depth from common/depth.vert a bit off
// would leave a visible pixel's pages unmarked. Its level comes from the rasterized footprint's
// derivatives, as the lighting pass's does, which a full-screen pass over a depth image could not repeat.
#include <cstdint>
#include <vector>

#include <epoxy/gl.h>

#include "scenes/InstanceCulling.h"
#include "techniques/gl/ContactShadowsGL.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/virtual/VirtualMaps.h"

namespace sb {

class VirtualGL final : public GlTechnique {
public:
    VirtualGL();
    ~VirtualGL() override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    void setScene(const Scene& scene) override;
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mMaps.texels(); }
    /// The last frame's page counts (also in counters()).
    const PageCounts& pageCounts() const { return mMaps.counts(); }

private:
    void release();
    void markPages(FrameContext& ctx);
    void allocatePages();
    void renderPages(FrameContext& ctx);
    void renderLighting(FrameContext& ctx);

    VirtualMaps mMaps;
    InstanceCulling mCulling;
    std::vector<uint8_t> mKeep;
    std::vector<uint32_t> mWords;
    GLuint mRequests = 0; ///< R32UI, a texel per page (PageGeometry::tableRows rows): 1 where marked
    GLuint mTable = 0;    ///< R32UI, the same layout: PageTable::packed
    GLuint mAtlas = 0;    ///< R32UI, the pool's slots: depth bits
    GLuint mEmptyFbo = 0; ///< no attachments, virtual_resolution^2
    const Program* mMarkProgram = nullptr;
    const Program* mPageProgram = nullptr;
    LitPrograms mLighting;
    ContactShadowsGL mContact; ///< contact=on: the view depth pre-pass and its binding
    Counters mCounters;
};

} // namespace sb
