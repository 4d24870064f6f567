#include "techniques/gl/ReceiverStencil.h"

#include <algorithm>

namespace sb {

ReceiverStencil::~ReceiverStencil() {
    release();
}

void ReceiverStencil::release() {
    if (mVao) glDeleteVertexArrays(1, &mVao);
    if (mVbo) glDeleteBuffers(1, &mVbo);
    mVao = mVbo = 0;
}

void ReceiverStencil::upload(const std::vector<ReceiverPlane>& planes) {
    release();
    std::vector<glm::vec3> corners;
    for (const ReceiverPlane& p : planes) corners.insert(corners.end(), p.corners.begin(), p.corners.end());
    glCreateBuffers(1, &mVbo);
    glNamedBufferStorage(mVbo, GLsizeiptr(std::max<size_t>(1, corners.size()) * sizeof(glm::vec3)),
                         corners.empty() ? nullptr : corners.data(), 0);
    glCreateVertexArrays(1, &mVao);
    glVertexArrayVertexBuffer(mVao, 0, mVbo, 0, sizeof(glm::vec3));
    glEnableVertexArrayAttrib(mVao, 0);
    glVertexArrayAttribFormat(mVao, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(mVao, 0, 0);
}

const Program& ReceiverStencil::compile(ProgramCache& programs) {
    mProgram = &programs.get({"common/receiver.vert", "common/receiver.frag", ""}, {});
    return *mProgram;
}

void ReceiverStencil::mark(size_t plane, int ref, GLenum passOp) const {
    glStencilFunc(GL_ALWAYS, ref, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    mProgram->use();
    glBindVertexArray(mVao);
    glDrawArrays(GL_TRIANGLE_FAN, GLint(plane * 4), 4);
    glBindVertexArray(0);
    glStencilFunc(GL_EQUAL, ref, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, passOp);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

void ReceiverStencil::setDarkenBlending() {
    glEnable(GL_BLEND);
    glBlendEquationi(0, GL_FUNC_REVERSE_SUBTRACT);
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendEquationi(1, GL_FUNC_ADD);
    glBlendFunci(1, GL_ZERO, GL_SRC_COLOR);
}

} // namespace sb
