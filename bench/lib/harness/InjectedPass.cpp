#include "bench/lib/harness/InjectedPass.h"

#include "core/Injection.h"

namespace sb {

InjectedPass::~InjectedPass() {
    if (mVao) glDeleteVertexArrays(1, &mVao);
}

void InjectedPass::execute(ProgramCache& programs, PassTimer& passes, int colourAttachments) {
    if (!injected(Injection::ExtraFullscreenPass)) return;
    passes.begin("injected_fullscreen");
    if (!mVao) glCreateVertexArrays(1, &mVao);
    const Program& program = programs.get({"common/fullscreen.vert", "calibrate/injected.frag", ""}, {});
    program.use();
    for (int i = 1; i < colourAttachments; ++i)
        glColorMaski(GLuint(i), GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_DST_COLOR, GL_ZERO);
    glBindVertexArray(mVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glEnable(GL_DEPTH_TEST);
    for (int i = 1; i < colourAttachments; ++i) glColorMaski(GLuint(i), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

} // namespace sb
