#pragma once
#include <vector>

#include "techniques/gl/Submitter.h"

namespace sb {

/// glBegin/glEnd per instance, one glVertexAttrib call per attribute and vertex (normal, then position:
/// attribute 0 provokes the vertex). This is the thesis's CPU-bound case: every vertex of every
/// instance crosses the API each frame.
///
/// After draw() returns no vertex is left buffered in the driver. GL says a state change applies only
/// to later commands, but Mesa (22.3, llvmpipe and OSMesa alike) keeps the vertices of the last
/// glBegin/glEnd in a buffer until a command flushes it, and glBindTextureUnit(unit, 0) (and
/// glBindTextures with a 0 or null name) changes the binding without that flush: a technique that
/// unbinds its texture after drawing, as projective, shadowmap and reference do, had its last
/// instance drawn with the default texture (black: every receiver of projective's final draw
/// shadowed). The other modes submit with draw calls, which Mesa never buffers.
class ImmediateSubmitter final : public Submitter {
public:
    SubmitMode mode() const override { return SubmitMode::Immediate; }
    void uploadMode(const Scene& scene) override;

private:
    void drawKept(DrawSet set, InstanceMask keep) override;
    /// Makes the driver draw what it has buffered: one GL call, no fragments.
    static void flushBufferedVertices();
    const Scene* mScene = nullptr;
};

} // namespace sb
