#pragma once
// GLSL literals of C++ floats, for the defines that put scene constants into shaders (the lights'
// colours and cones, techniques/Technique.h's addLightKindDefines; the emitters of the ray-traced soft
// shadows, techniques/raytraced/Emitters.h). Each float is written so that it parses back to the
// identical float: the constant a shader compiles in is the uniform's value (or the CPU's), bit for bit.
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sb {

/// `v` as a GLSL float literal that parses back to the identical float (to_chars' shortest round trip),
/// with a decimal point where to_chars writes none ("0" -> "0.0").
std::string glslFloat(float v);

/// A GLSL vecN constant of `v`'s N floats; one argument where they are all equal (a grey ambient, a zero
/// padding), so that the common case stays short in the permutation key.
template <int N>
std::string glslVec(const glm::vec<N, float>& v) {
    bool same = true;
    for (int k = 1; k < N; ++k) same = same && v[k] == v[0];
    std::string text = "vec" + std::to_string(N) + "(" + glslFloat(v[0]);
    for (int k = 1; k < N && !same; ++k) text += "," + glslFloat(v[k]);
    return text + ")";
}

/// A GLSL array constant of `values`: "vecN[count](v0,v1,...)".
template <int N>
std::string glslVecArray(const std::vector<glm::vec<N, float>>& values) {
    std::string text = "vec" + std::to_string(N) + "[" + std::to_string(values.size()) + "](";
    for (size_t i = 0; i < values.size(); ++i) text += (i ? "," : "") + glslVec<N>(values[i]);
    return text + ")";
}

} // namespace sb
