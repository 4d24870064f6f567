#pragma once
// Shadow-map texels per screen pixel at a judged sample: the sampling-rate ratio behind shadow-map
// aliasing, after the aliasing error m of Lloyd, Tuft, Yoon and Manocha, "Warping and Partitioning for
// Low Error Shadow Maps" (EGSR 2006), the section that defines m, and Lloyd, Govindaraju, Quammen, Molnar
// and Manocha, "Logarithmic Perspective Shadow Maps" (ACM TOG 27(4), 2008), the section deriving the
// aliasing error for general light positions: m is the size of a shadow-map texel projected onto the
// receiver over the size of the eye's pixel there (m > 1: a texel covers more than a pixel, the map
// undersamples the image).
//
// What is computed, per sample at world point p on a receiver with (seen) normal n, on the receiver's
// tangent plane through p with two orthonormal directions u, v:
//   A = d(screen pixels) / d(u, v): the camera's projection restricted to the plane, in closed form from
//       its view-projection M: with c = M p, a pixel is (c.xy / c.w + 1) / 2 * size, whose derivative is
//       (M_xy c.w - c.xy M_w) / c.w^2 * size / 2, taken along u and v;
//   B = d(map texels) / d(u, v): the technique's light-space mapping (techniques/MapTexels.h: the map
//       and mapping its lighting pass uses for p) restricted to the same plane, by central differences
//       along u and v with a step of a quarter of the pixel's footprint, 0.25 / sqrt|det A| world units,
//       inside the map p chose: exact up to rounding for orthographic maps, within a relative
//       O(step^2 / distance^2) for perspective maps (spot lights, cube faces) and the paraboloid's
//       nonlinear projection;
//   texels per pixel t = sqrt(|det B| / |det A|) = sqrt|det J|, with J = B A^-1 the Jacobian from screen
//       pixels to map texels through the receiver plane: the square root of the number of texels (by
//       area) that one pixel's footprint on the receiver holds.
// So t = 1 / m in the area-equivalent sense (the geometric mean over the two directions; Lloyd et al.
// quote m in the worse direction, which is at least 1 / t): t < 1 is undersampling, the map's texel
// larger than the pixel, blocky shadow edges about 1 / t pixels wide; t > 1 oversampling. Its low end
// (the `acc_texels_per_pixel_p5` and `_min` columns) is m's high end.
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/MapTexels.h"

namespace sb {

class TexelDensity {
public:
    /// t at sample `at` with receiver normal `normal` (unit), seen with camera `cameraViewProj` on an
    /// image of `size` pixels, for light `light` of `maps`; nothing where the technique reads no map for
    /// `at` or the plane is seen edge-on (no finite footprint).
    static std::optional<double> texelsPerPixel(const MapTexels& maps, size_t light, const ShadedPoint& at,
                                                const glm::dvec3& normal, const glm::mat4& cameraViewProj,
                                                glm::ivec2 size);
    /// d(screen pixels) / d(u, v) at `p` (A above; columns: along u, along v).
    static glm::dmat2 screenJacobian(const glm::mat4& cameraViewProj, glm::ivec2 size, const glm::dvec3& p,
                                     const glm::dvec3& u, const glm::dvec3& v);

    /// The columns' statistics over the samples that have a t (Statistics: type-7 percentiles).
    struct Summary {
        size_t samples = 0; ///< samples with a map
        double p50 = 0.0, p5 = 0.0, min = 0.0;
    };
    static Summary summarize(std::vector<double> values);
};

} // namespace sb
