#include "scenes/ShadowPlaneChooser.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include <glm/gtc/constants.hpp>

#include "scenes/BuiltinShadowPlanes.h"
#include "scenes/Math.h"

namespace sb {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kMaxSamples = 3000;
constexpr float kJudgedCosine = 0.05f; ///< n.L above which a sample is judged (the accuracy judge's)
constexpr float kConeDegrees = 10.0f;
constexpr double kFalseWeight = 3.0;
constexpr float kQuantiles[] = {0.2f, 0.35f, 0.5f, 0.65f, 0.8f};

struct Triangle {
    glm::vec3 a, b, c;
};

/// A bounding-volume hierarchy over the mesh's triangles (median split on the longest axis): the exact
/// occlusion of each sample's ray, the chooser's ground truth.
class Bvh {
public:
    explicit Bvh(std::vector<Triangle> tris) : mTris(std::move(tris)) {
        mOrder.resize(mTris.size());
        std::iota(mOrder.begin(), mOrder.end(), 0u);
        if (mTris.empty()) return;
        mNodes.resize(1);
        buildAt(0, 0, uint32_t(mTris.size()));
    }
    /// True when the ray o + t d, t in (0, inf), meets a triangle.
    bool occluded(const glm::vec3& o, const glm::vec3& d) const {
        if (mNodes.empty()) return false;
        const glm::vec3 inv = 1.0f / d;
        uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& n = mNodes[stack[--top]];
            if (!hitsBox(n.box, o, inv)) continue;
            if (n.count > 0) {
                for (uint32_t i = n.first; i < n.first + n.count; ++i)
                    if (hitsTriangle(mTris[mOrder[i]], o, d)) return true;
            } else if (top + 2 <= 64) {
                stack[top++] = n.first;
                stack[top++] = n.first + 1;
            }
        }
        return false;
    }

private:
    struct Node {
        Aabb box;
        uint32_t first = 0, count = 0; ///< leaf: triangles [first, first + count); inner: children first, +1
    };
    glm::vec3 centroid(uint32_t t) const { return (mTris[t].a + mTris[t].b + mTris[t].c) / 3.0f; }
    /// Builds the subtree of [first, first + count) into node `slot`; children are allocated in pairs.
    void buildAt(uint32_t slot, uint32_t first, uint32_t count) {
        Aabb box, centres;
        for (uint32_t i = first; i < first + count; ++i) {
            const Triangle& t = mTris[mOrder[i]];
            box.extend(t.a);
            box.extend(t.b);
            box.extend(t.c);
            centres.extend(centroid(mOrder[i]));
        }
        mNodes[slot].box = box;
        const glm::vec3 e = centres.extent();
        if (count <= 4 || std::max({e.x, e.y, e.z}) <= 0.0f) {
            mNodes[slot].first = first;
            mNodes[slot].count = count;
            return;
        }
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
        const uint32_t half = count / 2;
        std::nth_element(mOrder.begin() + first, mOrder.begin() + first + half,
                         mOrder.begin() + first + count,
                         [&](uint32_t x, uint32_t y) { return centroid(x)[axis] < centroid(y)[axis]; });
        const uint32_t left = uint32_t(mNodes.size());
        mNodes.resize(left + 2);
        buildAt(left, first, half);
        buildAt(left + 1, first + half, count - half);
        mNodes[slot].first = left;
        mNodes[slot].count = 0;
    }
    static bool hitsBox(const Aabb& b, const glm::vec3& o, const glm::vec3& inv) {
        float t0 = 0.0f, t1 = kInf;
        for (int k = 0; k < 3; ++k) {
            float a = (b.min[k] - o[k]) * inv[k], c = (b.max[k] - o[k]) * inv[k];
            if (a > c) std::swap(a, c);
            if (std::isnan(a) || std::isnan(c)) continue; // the ray lies in a slab plane
            t0 = std::max(t0, a);
            t1 = std::min(t1, c);
        }
        return t0 <= t1;
    }
    /// Moller-Trumbore, both facings.
    static bool hitsTriangle(const Triangle& t, const glm::vec3& o, const glm::vec3& d) {
        const glm::vec3 e1 = t.b - t.a, e2 = t.c - t.a, p = glm::cross(d, e2);
        const float det = glm::dot(e1, p);
        if (std::abs(det) < 1e-12f) return false;
        const float inv = 1.0f / det;
        const glm::vec3 s = o - t.a;
        const float u = glm::dot(s, p) * inv;
        if (u < 0.0f || u > 1.0f) return false;
        const glm::vec3 q = glm::cross(s, e1);
        const float v = glm::dot(d, q) * inv;
        if (v < 0.0f || u + v > 1.0f) return false;
        return glm::dot(e2, q) * inv > 0.0f;
    }
    std::vector<Triangle> mTris;
    std::vector<uint32_t> mOrder;
    std::vector<Node> mNodes;
};

/// A point of the surface with its geometric normal and area weight.
struct Sample {
    glm::vec3 p, n;
    float weight;
};

std::vector<Triangle> triangles(const Mesh& mesh) {
    std::vector<Triangle> out;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
        out.push_back({mesh.positions[mesh.indices[i]], mesh.positions[mesh.indices[i + 1]],
                       mesh.positions[mesh.indices[i + 2]]});
    return out;
}

/// Triangle centroids, every k-th one when there are more than kMaxSamples, weighted by area.
std::vector<Sample> samples(const std::vector<Triangle>& tris) {
    const size_t step = std::max<size_t>(1, (tris.size() + kMaxSamples - 1) / kMaxSamples);
    std::vector<Sample> out;
    for (size_t i = 0; i < tris.size(); i += step) {
        const Triangle& t = tris[i];
        const glm::vec3 c = glm::cross(t.b - t.a, t.c - t.a);
        const float area2 = glm::length(c);
        if (!(area2 > 0.0f) || !std::isfinite(area2)) continue;
        out.push_back({(t.a + t.b + t.c) / 3.0f, c / area2, 0.5f * area2});
    }
    return out;
}

/// Of nine rays from `p` into the hemisphere around `n` (along it and eight 50 degrees off), how many
/// leave the mesh.
int escapes(const Bvh& bvh, const glm::vec3& p, const glm::vec3& n, float epsilon) {
    const glm::vec3 e1 = glm::normalize(glm::cross(anyPerpendicularUp(n), n)), e2 = glm::cross(n, e1);
    const glm::vec3 o = p + epsilon * n;
    int count = bvh.occluded(o, n) ? 0 : 1;
    for (int k = 0; k < 8; ++k) {
        const float a = float(k) * glm::quarter_pi<float>();
        const glm::vec3 d = std::cos(glm::radians(50.0f)) * n +
                            std::sin(glm::radians(50.0f)) * (std::cos(a) * e1 + std::sin(a) * e2);
        count += bvh.occluded(o, d) ? 0 : 1;
    }
    return count;
}

/// Each direction and four around it on a cone of kConeDegrees.
std::vector<glm::vec3> directions(const std::vector<glm::vec3>& towardLight) {
    std::vector<glm::vec3> base = towardLight;
    if (base.empty())
        for (int x = -1; x <= 1; ++x)
            for (int y = -1; y <= 1; ++y)
                for (int z = -1; z <= 1; ++z) {
                    const int nonzero = (x != 0) + (y != 0) + (z != 0);
                    if (nonzero == 1 || nonzero == 3) base.push_back(glm::normalize(glm::vec3(x, y, z)));
                }
    std::vector<glm::vec3> out;
    const float t = std::tan(glm::radians(kConeDegrees));
    for (const glm::vec3& d0 : base) {
        const glm::vec3 d = glm::normalize(d0);
        const glm::vec3 e1 = glm::normalize(glm::cross(anyPerpendicularUp(d), d)), e2 = glm::cross(d, e1);
        out.push_back(d);
        for (const glm::vec3& e : {e1, -e1, e2, -e2}) out.push_back(glm::normalize(d + t * e));
    }
    return out;
}

/// A candidate plane with its CPU occluder texture (true = black), kResolution^2, row 0 = v near 0.
struct Candidate {
    ShadowPlane plane;
    std::vector<bool> black;
    bool shadows(const glm::vec3& p, const glm::vec3& towardLight) const {
        const ShadowCoord c = plane.project(p, towardLight);
        if (!(c.s > 0.0f) || c.uv.x < 0.0f || c.uv.x > 1.0f || c.uv.y < 0.0f || c.uv.y > 1.0f) return false;
        const int n = ShadowPlaneChooser::kResolution;
        const int i = std::min(n - 1, int(c.uv.x * float(n))), j = std::min(n - 1, int(c.uv.y * float(n)));
        return black[size_t(j) * size_t(n) + size_t(i)];
    }
};

/// Adds `value` to the texels whose centres a triangle (in texel coordinates) covers.
void rasterise(std::vector<int>& grid, glm::vec2 a, glm::vec2 b, glm::vec2 c, int value) {
    const int n = ShadowPlaneChooser::kResolution;
    auto edge = [](glm::vec2 p, glm::vec2 q, glm::vec2 r) {
        return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    };
    const float area = edge(a, b, c);
    if (area == 0.0f) return;
    if (area < 0.0f) std::swap(b, c);
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x})))),
              x1 = std::min(n - 1, int(std::ceil(std::max({a.x, b.x, c.x})))),
              y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y})))),
              y1 = std::min(n - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
            if (edge(a, b, p) >= 0.0f && edge(b, c, p) >= 0.0f && edge(c, a, p) >= 0.0f)
                grid[size_t(y) * size_t(n) + size_t(x)] += value;
        }
}

/// The CPU counterpart of OccluderTextures::bake at kResolution: the silhouette (every triangle) and the
/// cross-section (winding number of the triangles on the normal's side, +1 facing along the normal).
std::vector<bool> bakeCpu(const std::vector<Triangle>& tris, const ShadowPlane& p, bool silhouette) {
    const int n = ShadowPlaneChooser::kResolution;
    std::vector<int> cover(size_t(n) * size_t(n), 0), winding(cover.size(), 0);
    auto uv = [&](const glm::vec3& q) {
        const glm::vec3 d = q - p.origin;
        return glm::vec2(glm::dot(p.right, d) / p.width, glm::dot(p.up, d) / p.height) * float(n);
    };
    for (const Triangle& t : tris) {
        if (silhouette) rasterise(cover, uv(t.a), uv(t.b), uv(t.c), 1);
        // Clip to the normal's side: a triangle fan of the clipped polygon.
        const glm::vec3 v[3] = {t.a, t.b, t.c};
        float dist[3];
        for (int k = 0; k < 3; ++k) dist[k] = glm::dot(p.normal, v[k] - p.origin);
        std::vector<glm::vec3> poly;
        for (int k = 0; k < 3; ++k) {
            const int m = (k + 1) % 3;
            if (dist[k] >= 0.0f) poly.push_back(v[k]);
            if ((dist[k] >= 0.0f) != (dist[m] >= 0.0f))
                poly.push_back(v[k] + (v[m] - v[k]) * (dist[k] / (dist[k] - dist[m])));
        }
        if (poly.size() < 3) continue;
        const float facing = glm::dot(glm::cross(t.b - t.a, t.c - t.a), p.normal);
        if (facing == 0.0f) continue;
        for (size_t k = 1; k + 1 < poly.size(); ++k)
            rasterise(winding, uv(poly[0]), uv(poly[k]), uv(poly[k + 1]), facing > 0.0f ? 1 : -1);
    }
    std::vector<bool> black(cover.size());
    for (size_t i = 0; i < black.size(); ++i) black[i] = cover[i] > 0 || winding[i] != 0;
    // The technique clears the border texels of baked textures (clamped lookups would extend them).
    for (int i = 0; i < n; ++i) {
        black[size_t(i)] = black[size_t(n - 1) * size_t(n) + size_t(i)] = false;
        black[size_t(i) * size_t(n)] = black[size_t(i) * size_t(n) + size_t(n - 1)] = false;
    }
    return black;
}

/// The plane with normal `normal` at `offset` along it from the origin, covering the mesh's projection
/// with the bake's margin.
ShadowPlane planeAcross(const std::vector<glm::vec3>& points, const glm::vec3& normal, float offset,
                        const std::string& name) {
    const glm::vec3 right = glm::normalize(glm::cross(anyPerpendicularUp(normal), normal));
    const glm::vec3 up = glm::cross(normal, right);
    float u0 = kInf, u1 = -kInf, v0 = kInf, v1 = -kInf;
    for (const glm::vec3& q : points) {
        u0 = std::min(u0, glm::dot(right, q));
        u1 = std::max(u1, glm::dot(right, q));
        v0 = std::min(v0, glm::dot(up, q));
        v1 = std::max(v1, glm::dot(up, q));
    }
    const float margin = BuiltinShadowPlanes::kMarginFraction * std::max(u1 - u0, v1 - v0);
    ShadowPlane p;
    p.name = name;
    p.normal = normal;
    p.right = right;
    p.up = up;
    p.origin = offset * normal + (u0 - margin) * right + (v0 - margin) * up;
    p.width = std::max(u1 - u0 + 2.0f * margin, 1e-6f);
    p.height = std::max(v1 - v0 + 2.0f * margin, 1e-6f);
    return p;
}

std::vector<Candidate> candidates(const Mesh& mesh, const std::vector<Triangle>& tris,
                                  const std::vector<glm::vec3>& towardLight) {
    const PrincipalAxes axes = principalAxes(mesh.positions);
    std::vector<std::pair<std::string, glm::vec3>> normals = {
        {"axis0", axes.axes[0]}, {"axis1", axes.axes[1]}, {"axis2", axes.axes[2]}};
    for (size_t l = 0; l < towardLight.size(); ++l)
        normals.emplace_back("light" + std::to_string(l), glm::normalize(towardLight[l]));
    std::vector<Candidate> out;
    for (const auto& [label, n] : normals) {
        if (!std::isfinite(n.x) || glm::length(n) < 0.5f) continue;
        std::vector<float> along;
        for (const glm::vec3& q : mesh.positions) along.push_back(glm::dot(n, q));
        std::sort(along.begin(), along.end());
        // Offsets at quantiles of the vertices (where the detail is) and at the same fractions of the
        // extent (where a thin part far from the bulk of the vertices lies, a plate over a floor).
        std::vector<std::pair<std::string, float>> offsets;
        for (float f : kQuantiles) {
            const int percent = int(std::lround(f * 100.0f));
            offsets.emplace_back("q" + std::to_string(percent),
                                 along[std::min(along.size() - 1, size_t(f * float(along.size())))]);
            offsets.emplace_back("x" + std::to_string(percent), glm::mix(along.front(), along.back(), f));
        }
        for (const auto& [where, offset] : offsets) {
            char name[64];
            std::snprintf(name, sizeof(name), "auto_%s_%s", label.c_str(), where.c_str());
            ShadowPlane plane = planeAcross(mesh.positions, n, offset, name);
            for (bool silhouette : {false, true}) {
                Candidate c{plane, bakeCpu(tris, plane, silhouette)};
                c.plane.sectionOnly = !silhouette;
                if (!silhouette) c.plane.name += "_section";
                out.push_back(std::move(c));
            }
        }
    }
    return out;
}

} // namespace

ShadowPlaneChoice ShadowPlaneChooser::choose(const Mesh& mesh, const std::vector<glm::vec3>& towardLight,
                                             int maxPlanes) {
    ShadowPlaneChoice choice;
    const std::vector<Triangle> tris = triangles(mesh);
    if (tris.empty() || mesh.positions.empty()) {
        choice.reason = "no triangles";
        return choice;
    }
    const Bvh bvh(tris);
    const std::vector<Sample> points = samples(tris);
    const std::vector<glm::vec3> dirs = directions(towardLight);
    const Aabb bounds = mesh.computeBounds();
    const float epsilon = 1e-4f * glm::length(bounds.extent());
    // The judged (sample, direction) pairs and their truth.
    struct Judged {
        uint32_t sample, dir;
        float weight;
        bool shadowed;
    };
    std::vector<Judged> judged;
    double shadowedWeight = 0.0;
    for (uint32_t s = 0; s < points.size(); ++s) {
        // The side a camera sees: model files are not always consistently wound, so the normal is flipped
        // where clearly more rays leave the mesh from the other side (an inverted face of a closed mesh:
        // nothing escapes inwards); an open surface, whose both sides see out, keeps its winding.
        glm::vec3 n = points[s].n;
        if (escapes(bvh, points[s].p, -n, epsilon) >= escapes(bvh, points[s].p, n, epsilon) + 4) n = -n;
        for (uint32_t d = 0; d < dirs.size(); ++d) {
            if (glm::dot(n, dirs[d]) <= kJudgedCosine) continue;
            const bool shadowed = bvh.occluded(points[s].p + epsilon * n, dirs[d]);
            judged.push_back({s, d, points[s].weight, shadowed});
            choice.judgedWeight += points[s].weight;
            if (shadowed) shadowedWeight += points[s].weight;
        }
    }
    if (choice.judgedWeight <= 0.0) {
        choice.reason = "no surface faces the light";
        return choice;
    }
    choice.shadowedPct = 100.0 * shadowedWeight / choice.judgedWeight;
    std::vector<Candidate> pool = candidates(mesh, tris, towardLight);
    std::vector<bool> covered(judged.size(), false);
    double captured = 0.0, falseShadow = 0.0, bestRejected = -kInf;
    for (int round = 0; round < maxPlanes && !pool.empty(); ++round) {
        double bestGain = -kInf, bestTrue = 0.0, bestFalse = 0.0;
        size_t best = 0;
        for (size_t c = 0; c < pool.size(); ++c) {
            double t = 0.0, f = 0.0;
            for (size_t j = 0; j < judged.size(); ++j) {
                if (covered[j] || !pool[c].shadows(points[judged[j].sample].p, dirs[judged[j].dir])) continue;
                (judged[j].shadowed ? t : f) += judged[j].weight;
            }
            const double gain = t - kFalseWeight * f;
            if (gain > bestGain) {
                bestGain = gain;
                best = c;
                bestTrue = t;
                bestFalse = f;
            }
        }
        if (bestGain < kMinGain * choice.judgedWeight) {
            bestRejected = bestGain;
            break;
        }
        for (size_t j = 0; j < judged.size(); ++j)
            if (!covered[j] && pool[best].shadows(points[judged[j].sample].p, dirs[judged[j].dir]))
                covered[j] = true;
        captured += bestTrue;
        falseShadow += bestFalse;
        choice.planes.push_back(pool[best].plane);
        pool.erase(pool.begin() + std::ptrdiff_t(best));
    }
    choice.capturedPct = 100.0 * captured / choice.judgedWeight;
    choice.falsePct = 100.0 * falseShadow / choice.judgedWeight;
    for (const ShadowPlane& p : choice.planes)
        p.validate("automatic shadow planes of mesh '" + mesh.name + "'");
    if (choice.planes.empty() && shadowedWeight == 0.0) {
        choice.reason = "it casts no shadow on itself under these lights (no lit sample's ray meets it)";
    } else if (choice.planes.empty()) {
        char line[256];
        std::snprintf(
            line, sizeof(line),
            "no candidate plane shadows more than three times the lit surface it would falsely darken "
            "(%.2f%% of the lit surface is in self-shadow; the best plane gains %.2f%%, %.2f%% "
            "needed)",
            choice.shadowedPct, 100.0 * std::max(0.0, bestRejected) / choice.judgedWeight, 100.0 * kMinGain);
        choice.reason = line;
    }
    return choice;
}

} // namespace sb
