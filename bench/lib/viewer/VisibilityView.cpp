#include "bench/lib/viewer/VisibilityView.h"

#include <string>

#include "gl/GlStateGuard.h"

namespace sb {

VisibilityView::VisibilityView(ProgramCache& programs) : mPrograms(programs) {
    program(); // compile now: a shader error shows when the viewer opens, not at the first V
    glCreateVertexArrays(1, &mVertexArray);
}

VisibilityView::~VisibilityView() {
    glDeleteVertexArrays(1, &mVertexArray);
}

const Program& VisibilityView::program() {
    return mPrograms.get({"common/fullscreen.vert", "viewer/visibility.frag", ""}, {});
}

void VisibilityView::draw(const FrameTargets& targets, int light, int width, int height) {
    GlStateGuard guard;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const Program& p = program();
    p.use();
    glUniform1i(p.uniform("uLight"), light);
    glUniform2f(p.uniform("uWindowSize"), float(width), float(height));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, targets.visibilityTexture());
    glBindVertexArray(mVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

} // namespace sb
