#include "techniques/shadowmap/DepthPassState.h"

#include <epoxy/gl.h>

namespace sb {

DepthPassState::DepthPassState(int size, float biasSlope, float biasConstant) {
    glViewport(0, 0, size, size);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(biasSlope, biasConstant);
}

DepthPassState::~DepthPassState() {
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

} // namespace sb
