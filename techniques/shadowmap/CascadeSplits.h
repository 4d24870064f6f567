#pragma once
// Where `cascaded` cuts the view frustum (Zhang et al. 2006, Parallel-Split Shadow Maps for
// Large-scale Virtual Environments, section 3, the practical split scheme): split i of N lies at
//     C_i = lambda * C_log_i + (1 - lambda) * C_uni_i,
//     C_log_i = n (f / n)^(i / N)   (the logarithmic split: the ideal for perspective aliasing),
//     C_uni_i = n + (f - n) i / N   (the uniform split: what the log split starves far away),
// with the weight lambda as written in Zhang, Sun, Nyman 2007 (GPU Gems 3, ch. 10, section 10.2.1).
// n and f are the camera's near and far distances, read from its projection each frame, then clipped
// at both ends to the view depths the scene's receivers occupy: a far plane of 1000 over a 20-unit
// scene would put every split but the first into empty space, and a near plane of 1 under a camera
// 150 above the nearest roof would spend the first splits on air. Pure math: no GL, no scene state
// beyond the boxes it is given.
//
// fit=sdsm (Lauritzen, Salvi and Lefohn 2011, Sample Distribution Shadow Maps, I3D: its z-partitioning of
// the tight depth range) clips [n, f] instead to the min and max depth of the pixels the camera sees,
// which a depth pre-pass and a GPU reduction find (shaders/shadowmap/depth_range.comp), and splits that
// interval logarithmically (lambda = 1): with the range tight, the log split's starvation of the far end
// that the practical scheme's uniform part guards against is gone, the paper's argument for it.
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Mesh.h"

namespace sb {

class CascadeSplits {
public:
    /// The N + 1 split distances C_0 = n < C_1 < ... < C_N = f (view depth, positive) for `count` = N
    /// cascades and weight `lambda` in [0, 1] (0 uniform, 1 logarithmic). Needs 0 < n < f and N >= 1;
    /// the ends are exactly n and f.
    static std::vector<float> practical(float nearZ, float farZ, int count, float lambda);

    /// The near and far distances (x, y; positive view depth) of an OpenGL perspective or orthographic
    /// projection, as glm::perspective and glm::ortho build them. A translation of the image in NDC (the
    /// harness's sub-pixel shifts) does not change them.
    static glm::vec2 nearFar(const glm::mat4& proj);

    /// `nearFar` clipped to the view-depth interval of the receivers' world-space boxes that may reach
    /// the camera's frustum (each box's 8 corners), padded by 1% of the interval plus 1e-5 of the far
    /// distance on both sides (a plane's box is flat: its pixels must stay inside, not on, the end), and
    /// kept at least 1e-4 x far thick. With no receiver in view the camera's own interval is returned.
    static glm::vec2 clipToReceivers(glm::vec2 nearFar, const glm::mat4& view, const glm::mat4& proj,
                                     const std::vector<Aabb>& receivers);

    /// The sample distribution split: `samples` (the view depths of the nearest and farthest pixel)
    /// padded as clipToReceivers pads the receivers' interval and kept within `nearFar`, then split
    /// logarithmically into `count` cascades (practical with lambda = 1). An empty interval (x > y: no
    /// pixel covered) splits `nearFar` instead.
    static std::vector<float> sampleDistribution(glm::vec2 samples, glm::vec2 nearFar, int count);

    /// [lo, hi] padded by 1% of its length plus 1e-5 of the far distance on both sides, clamped to
    /// `nearFar` and kept at least 1e-4 x far thick: what a split interval found from samples or boxes
    /// needs so that its end pixels lie inside, not on, its ends.
    static glm::vec2 pad(float lo, float hi, glm::vec2 nearFar);
};

} // namespace sb
