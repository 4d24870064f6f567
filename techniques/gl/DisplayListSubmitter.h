#pragma once
#include <vector>

#include <epoxy/gl.h>

#include "techniques/gl/Submitter.h"

namespace sb {

/// One display list per mesh, compiled once at upload from the same glBegin/glEnd stream as the
/// immediate mode; each instance sets its uniforms and calls the list. The retained path of the
/// thesis era (section 6.2: "display lists ... greatly reduce the number of calls").
class DisplayListSubmitter final : public Submitter {
public:
    ~DisplayListSubmitter() override;
    SubmitMode mode() const override { return SubmitMode::DisplayList; }
    void uploadMode(const Scene& scene) override;

private:
    void drawKept(DrawSet set, InstanceMask keep) override;
    void release();
    const Scene* mScene = nullptr;
    GLuint mFirstList = 0;
    GLsizei mListCount = 0;
};

} // namespace sb
