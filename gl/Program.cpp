#include "gl/ProgramCache.h"

namespace sb {

Program::~Program() {
    glDeleteProgram(mId);
}

GLint Program::uniform(const char* name) const {
    auto it = mUniforms.find(name);
    if (it != mUniforms.end()) return it->second;
    // -1 is cached too: asking again for an optimised-out uniform every draw would cost a GL call each time.
    GLint location = glGetUniformLocation(mId, name);
    mUniforms.emplace(name, location);
    return location;
}

} // namespace sb
