#include "scenes/MapCoverage.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sb {

namespace {

/// A triangle in clip space cut by GL's near plane z >= -w: the part in front, 0 to 4 vertices.
std::vector<glm::dvec4> clipNear(const glm::dvec4 (&tri)[3]) {
    std::vector<glm::dvec4> out;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec4& a = tri[k];
        const glm::dvec4& b = tri[(k + 1) % 3];
        const double da = a.z + a.w, db = b.z + b.w;
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

/// Marks in `map` the texels whose centre lies inside the convex polygon `poly` (window coordinates,
/// either winding): per row, each edge's half-plane bounds the centre's x from one side.
void fillConvex(const std::vector<glm::dvec2>& poly, int resolution, std::vector<uint8_t>& map) {
    const size_t n = poly.size();
    double area2 = 0.0; // twice the signed area: the winding
    double ylo = poly[0].y, yhi = poly[0].y;
    for (size_t k = 0; k < n; ++k) {
        const glm::dvec2& p = poly[k];
        const glm::dvec2& q = poly[(k + 1) % n];
        area2 += p.x * q.y - q.x * p.y;
        ylo = std::min(ylo, p.y);
        yhi = std::max(yhi, p.y);
    }
    if (area2 == 0.0) return; // no area: a rasteriser covers no sample
    const double s = area2 > 0.0 ? 1.0 : -1.0;
    // Clamped in double before the conversion: a caster far outside the map has window coordinates
    // beyond int's range.
    const double lastRow = double(resolution - 1);
    const int rowLo = int(std::clamp(std::ceil(ylo - 0.5), 0.0, lastRow + 1.0));
    const int rowHi = int(std::clamp(std::floor(yhi - 0.5), -1.0, lastRow));
    for (int row = rowLo; row <= rowHi; ++row) {
        const double y = row + 0.5;
        // The row's texel centres, 0.5 to resolution - 0.5, all of them: an edge beyond the map's left
        // side must leave the first texel at 0 (-0.5 made it -1, a write before the row).
        double xlo = 0.5, xhi = resolution - 0.5;
        bool empty = false;
        for (size_t k = 0; k < n && !empty; ++k) {
            const glm::dvec2& p = poly[k];
            const glm::dvec2 e = poly[(k + 1) % n] - p;
            // Inside: s * cross(e, c - p) >= 0, i.e. a x + b >= 0.
            const double a = -s * e.y, b = s * (e.x * (y - p.y) + e.y * p.x);
            if (a > 0.0)
                xlo = std::max(xlo, -b / a);
            else if (a < 0.0)
                xhi = std::min(xhi, -b / a);
            else if (b < 0.0)
                empty = true;
        }
        // xlo only grows from -0.5 and xhi only shrinks from resolution - 0.5: when xlo <= xhi both
        // lie in that range, so the conversions cannot overflow.
        if (empty || !(xlo <= xhi)) continue;
        const int first = int(std::ceil(xlo - 0.5)), end = int(std::floor(xhi - 0.5)) + 1;
        if (first < end) {
            const auto rowStart = map.begin() + ptrdiff_t(size_t(row) * size_t(resolution));
            std::fill(rowStart + first, rowStart + end, uint8_t(1));
        }
    }
}

} // namespace

MapCoverage MapCoverage::count(const Scene& scene, const glm::mat4& lightViewProj, int resolution) {
    MapCoverage out;
    if (resolution <= 0) return out;
    const size_t side = size_t(resolution);
    out.texels = side * side;
    std::vector<uint8_t> map(out.texels, 0);
    std::vector<glm::dvec2> window;
    for (const Instance& inst : scene.instances) {
        if (!inst.castsShadow || inst.mesh >= scene.meshes.size()) continue;
        const Mesh& mesh = scene.meshes[inst.mesh];
        const glm::dmat4 m = glm::dmat4(lightViewProj) * glm::dmat4(inst.model);
        std::vector<glm::dvec4> clip(mesh.positions.size());
        for (size_t v = 0; v < clip.size(); ++v) clip[v] = m * glm::dvec4(glm::dvec3(mesh.positions[v]), 1.0);
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const glm::dvec4 tri[3] = {clip[mesh.indices[t]], clip[mesh.indices[t + 1]],
                                       clip[mesh.indices[t + 2]]};
            const std::vector<glm::dvec4> poly = clipNear(tri);
            if (poly.size() < 3) continue;
            window.clear();
            for (const glm::dvec4& c : poly) // after the near plane w > 0 for either projection
                window.push_back((glm::dvec2(c) / c.w * 0.5 + 0.5) * double(resolution));
            fillConvex(window, resolution, map);
        }
    }
    out.covered = uint64_t(std::count(map.begin(), map.end(), uint8_t(1)));
    return out;
}

} // namespace sb
