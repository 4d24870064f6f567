#pragma once
// An orthographic clip volume written out by hand for the culling tests (tests/InstanceCullingTest.cpp,
// tests/BackFaceCullingTest.cpp): x, y in [-2, 2], depth along -z from 1 to 9, so each verdict follows
// from the planes alone and not from glm's own projection code.
#include <glm/glm.hpp>

namespace sb::test {

/// glm::ortho(-2, 2, -2, 2, 1, 9) by its definition: x' = x / 2, y' = y / 2, z' = -(z + 5) / 4, w = 1.
inline glm::mat4 handOrtho() {
    glm::mat4 m(0.0f); // column-major: m[column][row]
    m[0][0] = 0.5f;
    m[1][1] = 0.5f;
    m[2][2] = -0.25f;
    m[3][2] = -1.25f;
    m[3][3] = 1.0f;
    return m;
}

} // namespace sb::test
