#pragma once
#include <vector>

#include "techniques/submit/Submitter.h"

namespace sb {

/// glBegin/glEnd per instance, one glVertexAttrib call per attribute and vertex (normal, then position:
/// attribute 0 provokes the vertex). This is the thesis's CPU-bound case: every vertex of every
/// instance crosses the API each frame.
class ImmediateSubmitter final : public Submitter {
public:
    SubmitMode mode() const override { return SubmitMode::Immediate; }
    void upload(const Scene& scene) override;
    void draw(DrawSet set) override;

private:
    const Scene* mScene = nullptr;
};

} // namespace sb
