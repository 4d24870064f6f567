#pragma once
// `proxy`: ShadowProxies (van der Spek, "ShadowProxies", OpenGL Insights): analytic sphere, box and
// cylinder volumes around the casters darken (and tint) the receivers within ProxyOffset of them.
// Soft, "infinitely soft" shadows and colour bleeding for a diffusely lit scene; not exact shadows.
//
// The pipeline of section 1.3, per frame:
//   1. the proxies: declared per mesh in the scene file (Mesh::proxies) or fitted to each caster
//      instance (ShadowProxy::fit: the tightest of sphere, box, cylinder), world frames precomputed in
//      setScene (instances do not move) by scenes/ProxyCollection, which planar's proxy occluders share;
//   2. clipped against the view frustum and numbered, and 3. the IndexMap built (ProxyIndexGrid: the
//      viewport split into cells x cells, each proxy's index in every cell its projected influence
//      box overlaps), both on the CPU inside the timed frame as the chapter does;
//   4. the parameters of the proxies in view and the IndexMap uploaded to two storage buffers, and the
//      scene drawn once with the proxy-enabled fragment shader (shaders/proxy/lit.frag: Listings
//      1.1-1.4, the self-shadow skip).
//
// Past the chapter: indices are 32-bit (its bytes capped them at 255); the cell capacity and grid size
// are properties and a proxy that does not fit a full cell is counted (counter `grid_overflow`, and a
// warning once), never silently dropped; grid=off tests every proxy in view (the grid's value,
// measured); the exponent shapes the attenuation as section 1.2 describes (exponent_on=factor
// reproduces Listing 1.3 as printed); multiple coloured lights each get their own modulated shadow
// (the chapter's suggested extension). Colour bleeding is compiled in only when the scene asks for
// colour_bleeding, the directional modulation only when the scene has a light to modulate towards.
#include <epoxy/gl.h>

#include "techniques/gl/GlTechnique.h"
#include "techniques/proxy/Proxy.h"
#include "techniques/proxy/ProxyPlan.h"

namespace sb {

class ProxyGL final : public GlTechnique {
public:
    ProxyGL();
    ~ProxyGL() override;
    void setScene(const Scene& scene) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    void uploadFrame(FrameContext& ctx);
    void release();

    ProxyPlan mPlan; ///< proxies, permutation, grid and counters (shared with ProxyVulkan)
    GLuint mProxyBuffer = 0, mIndexBuffer = 0;
    size_t mProxyCapacity = 0, mIndexCapacity = 0; ///< buffer sizes in elements
    const Program* mProgram = nullptr;
    Counters mCounters;
};

} // namespace sb
