#pragma once
// Where the lit passes evaluate the lights: once per fragment (Phong-style interpolation of the normal,
// the default and what every golden shows) or once per vertex with the result interpolated (Gouraud
// shading: glmark2's model and a common mobile one). The choice changes the image wherever a light's
// term is not affine across a triangle (point and spot lights, curved meshes) and costs the lit passes
// the light's work per vertex instead of per fragment. Set by a scene file's "lighting" key and by
// `--lighting`; shaders/common/lighting.glsl implements both.
#include <optional>
#include <string>

#include "core/NameTable.h"

namespace sb {

enum class LightingRate { Fragment, Vertex };

/// fragment, vertex: for the option, the scene key, help and errors.
const NameTable<Named<LightingRate>>& lightingRateNames();
/// "fragment" or "vertex": the CSV column `lighting`.
const char* lightingRateName(LightingRate rate);
/// The rate named `text`, or nothing for another word.
std::optional<LightingRate> parseLightingRate(const std::string& text);

} // namespace sb
