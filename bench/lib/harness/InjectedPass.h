#pragma once
// The harness's part of the perf gate's deliberate regressions (core/Injection.h): with
// SHADOWBENCH_INJECT=extra_fullscreen_pass every frame gets one more full-screen pass after the
// technique's, named "injected_fullscreen" in the pass timer and the work census, so the gate's
// report can name it. Without the switch nothing is created and frames are untouched.
#include <epoxy/gl.h>

#include "gl/ProgramCache.h"
#include "techniques/gl/PassTimer.h"

namespace sb {

class InjectedPass {
public:
    InjectedPass() = default;
    ~InjectedPass();
    InjectedPass(const InjectedPass&) = delete;
    InjectedPass& operator=(const InjectedPass&) = delete;

    /// Draws the pass into the bound frame targets when the switch is on (colour attachment 0 only;
    /// the other attachments are masked so the visibility target stays the technique's).
    void execute(ProgramCache& programs, PassTimer& passes, int colourAttachments);

private:
    GLuint mVao = 0;
};

} // namespace sb
