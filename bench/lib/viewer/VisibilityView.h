#pragma once
// The viewer's visibility view (`V` in bench --window): one light's channel of the visibility target
// (gl/FrameTargets.h: RGBA16F, channel i = light i, 1 lit, 0 shadowed, fractions in penumbrae) drawn
// to the window through a false-colour ramp, instead of the raw attachment, whose four channels read
// as colours mean nothing to the eye. The ramp runs from dark blue (0, shadowed) through purple and
// orange to pale yellow (1, lit); values the target should never hold stand out: NaN magenta, anything
// outside [0, 1] (infinities included) pure green. The overlay's colour bar (bench/lib/viewer/Overlay.h)
// draws the same ramp as its legend (both include shaders/viewer/ramp.glsl).
#include "gl/FrameTargets.h"
#include "gl/ProgramCache.h"

namespace sb {

class VisibilityView {
public:
    /// Needs a current GL 4.5 context. The program (shaders/viewer/visibility.frag with
    /// shaders/common/fullscreen.vert) comes from `programs`, which must outlive this view.
    explicit VisibilityView(ProgramCache& programs);
    ~VisibilityView();
    VisibilityView(const VisibilityView&) = delete;
    VisibilityView& operator=(const VisibilityView&) = delete;

    /// Fills the default framebuffer (`width` x `height` pixels) with channel `light` (0..kMaxLights-1)
    /// of `targets`' visibility texture, scaled to the window, nearest texel. Leaves the GL state as it
    /// found it (gl/GlStateGuard.h).
    void draw(const FrameTargets& targets, int light, int width, int height);

private:
    /// Looked up on every draw, never kept: the cache hands out references valid until it is cleared.
    const Program& program();

    ProgramCache& mPrograms;
    GLuint mVertexArray = 0;
};

} // namespace sb
