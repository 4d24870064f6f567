#include "techniques/MapTexels.h"

namespace sb {

bool MapTexels::looksUp(const glm::mat4& shadow, const glm::dvec3& p, double margin, bool clipFar) {
    const glm::dvec4 c = glm::dmat4(shadow) * glm::dvec4(p, 1.0);
    if (!(c.w > 0.0)) return false;
    const glm::dvec3 t = glm::dvec3(c) / c.w;
    return t.x >= margin && t.y >= margin && t.x <= 1.0 - margin && t.y <= 1.0 - margin &&
           (!clipFar || t.z <= 1.0);
}

glm::dvec2 MapTexels::projectedTexel(const glm::mat4& shadow, int resolution, const glm::dvec3& q) {
    const glm::dvec4 c = glm::dmat4(shadow) * glm::dvec4(q, 1.0);
    return glm::dvec2(c) / c.w * double(resolution);
}

} // namespace sb
