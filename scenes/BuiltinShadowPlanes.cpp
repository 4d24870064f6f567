#include "scenes/BuiltinShadowPlanes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <set>

#include <glm/gtc/constants.hpp>

#include "core/Error.h"

namespace sb {
namespace {

using Principal = PrincipalAxes;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kTwoPi = glm::two_pi<float>();

const MeshPart* findPart(const Mesh& mesh, const std::string& name) {
    for (const auto& part : mesh.parts)
        if (part.name == name) return &part;
    return nullptr;
}

bool hasParts(const Mesh& mesh, std::initializer_list<const char*> names) {
    return std::all_of(names.begin(), names.end(),
                       [&](const char* n) { return findPart(mesh, n) != nullptr; });
}

/// The distinct positions of the vertices that the named parts' triangles use. The generators duplicate
/// seam, pole and patch-border vertices (for normals); counted once, a symmetric part's vertex set
/// stays symmetric, and so do its mean and principal axes.
std::vector<glm::vec3> partVertices(const Mesh& mesh, std::initializer_list<const char*> names) {
    std::vector<bool> used(mesh.positions.size(), false);
    std::vector<glm::vec3> out;
    for (const char* name : names) {
        const MeshPart& part = *findPart(mesh, name);
        for (uint32_t i = part.firstIndex; i < part.firstIndex + part.indexCount; ++i) {
            if (used[mesh.indices[i]]) continue;
            used[mesh.indices[i]] = true;
            out.push_back(mesh.positions[mesh.indices[i]]);
        }
    }
    auto less = [](const glm::vec3& a, const glm::vec3& b) {
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    };
    std::sort(out.begin(), out.end(), less);
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

Principal principal(const std::vector<glm::vec3>& points) {
    return principalAxes(points);
}

} // namespace

PrincipalAxes principalAxes(const std::vector<glm::vec3>& points) {
    glm::dvec3 mean(0.0);
    for (const auto& p : points) mean += glm::dvec3(p);
    mean /= double(std::max<size_t>(points.size(), 1));
    double a[3][3] = {};
    for (const auto& p : points) {
        const glm::dvec3 d = glm::dvec3(p) - mean;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) a[i][j] += d[i] * d[j];
    }
    double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int sweep = 0; sweep < 64; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const double diagonal = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (!(off > 1e-30 * diagonal)) break;
        for (int p = 0; p < 2; ++p) {
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0) continue;
                // The rotation that zeroes a[p][q] (Numerical Recipes, section 11.1).
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t =
                    (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) {
                    const double kp = a[k][p], kq = a[k][q];
                    a[k][p] = c * kp - s * kq;
                    a[k][q] = s * kp + c * kq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double pk = a[p][k], qk = a[q][k];
                    a[p][k] = c * pk - s * qk;
                    a[q][k] = s * pk + c * qk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double kp = v[k][p], kq = v[k][q];
                    v[k][p] = c * kp - s * kq;
                    v[k][q] = s * kp + c * kq;
                }
            }
        }
    }
    std::array<int, 3> order = {0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int i, int j) { return a[i][i] > a[j][j]; });
    PrincipalAxes out;
    out.mean = glm::vec3(mean);
    for (int k = 0; k < 3; ++k) {
        const int i = order[size_t(k)];
        out.axes[size_t(k)] = glm::normalize(glm::vec3(float(v[0][i]), float(v[1][i]), float(v[2][i])));
        out.variance[size_t(k)] = a[i][i] / double(std::max<size_t>(points.size(), 1));
    }
    return out;
}

namespace {

/// An eigenvector's sign is arbitrary: this one has its largest component positive (deterministic).
glm::vec3 canonical(const glm::vec3& v) {
    const glm::vec3 m = glm::abs(v);
    const int i = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
    return v[i] < 0.0f ? -v : v;
}

/// `dir` without its component along the unit `normal`, normalised.
glm::vec3 inPlane(const glm::vec3& dir, const glm::vec3& normal) {
    return glm::normalize(dir - normal * glm::dot(dir, normal));
}

/// `v` pointing the way of `towards` (flipped if it points away).
glm::vec3 orient(const glm::vec3& v, const glm::vec3& towards) {
    return glm::dot(v, towards) < 0.0f ? -v : v;
}

/// In-plane extents of points relative to a point of the plane: u along right, v along up.
struct Rect {
    float u0 = kInf, u1 = -kInf, v0 = kInf, v1 = -kInf;
    void extend(float u, float v) {
        u0 = std::min(u0, u);
        u1 = std::max(u1, u);
        v0 = std::min(v0, v);
        v1 = std::max(v1, v);
    }
    float margin() const { return BuiltinShadowPlanes::kMarginFraction * std::max(u1 - u0, v1 - v0); }
};

Rect extents(const std::vector<glm::vec3>& points, const glm::vec3& centre, const glm::vec3& right,
             const glm::vec3& up) {
    Rect r;
    for (const auto& p : points) r.extend(glm::dot(right, p - centre), glm::dot(up, p - centre));
    return r;
}

/// The plane through `centre` with the frame given, covering `r` plus `margin` on each side.
ShadowPlane rectanglePlane(const std::string& name, const glm::vec3& centre, const glm::vec3& normal,
                           const glm::vec3& right, const glm::vec3& up, const Rect& r, float margin,
                           std::vector<std::string> parts) {
    ShadowPlane p;
    p.name = name;
    p.normal = normal;
    p.right = right;
    p.up = up;
    p.origin = centre + (r.u0 - margin) * right + (r.v0 - margin) * up;
    p.width = r.u1 - r.u0 + 2.0f * margin;
    p.height = r.v1 - r.v0 + 2.0f * margin;
    p.parts = std::move(parts);
    return p;
}

// ---- teapot ---------------------------------------------------------------------------------------

/// The lid's axis (through its vertices' mean, pointing to the knob) and the knob's widest ring.
struct LidGeometry {
    glm::vec3 centre{0.0f}, axis{0.0f, 1.0f, 0.0f};
    float knobHeight = 0.0f; ///< of the widest ring above `centre` along `axis`
    float knobRadius = 0.0f;
    float maxRadius = 0.0f;
};

LidGeometry lidGeometry(const Mesh& mesh, const std::vector<glm::vec3>& lid) {
    // The lid is a surface of revolution: two of its principal variances are equal (the plane of its
    // rings), the third, the odd one out, belongs to the axis. It points away from the rest of the
    // teapot (the lid sits on top).
    const Principal pl = principal(lid);
    const bool firstPairEqual =
        std::abs(pl.variance[0] - pl.variance[1]) < std::abs(pl.variance[1] - pl.variance[2]);
    LidGeometry g;
    g.centre = pl.mean;
    g.axis = orient(firstPairEqual ? pl.axes[2] : pl.axes[0], pl.mean - mesh.computeBounds().center());
    // The profile: height along the axis and distance from it, grouped into the rings of equal height
    // (each tessellated row of a lid patch is one circle), scanned from the top down. From the knob's
    // top the radius grows to the knob's widest ring, then shrinks into the neck before the lid widens
    // to its rim: the widest ring is the first one after which the radius shrinks.
    std::vector<std::pair<float, float>> profile; // (height, radius)
    for (const auto& p : lid) {
        const float h = glm::dot(g.axis, p - g.centre);
        profile.emplace_back(h, glm::length(p - g.centre - h * g.axis));
        g.maxRadius = std::max(g.maxRadius, profile.back().second);
    }
    std::sort(profile.begin(), profile.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    const float heightTolerance = 1e-4f * (profile.front().first - profile.back().first);
    std::vector<std::pair<float, float>> rings; // (height, largest radius)
    for (const auto& [h, r] : profile) {
        if (rings.empty() || rings.back().first - h > heightTolerance)
            rings.emplace_back(h, r);
        else
            rings.back().second = std::max(rings.back().second, r);
    }
    const float radiusTolerance = 1e-4f * g.maxRadius;
    size_t widest = std::min<size_t>(1, rings.size() - 1); // too coarse to show a neck: the top's ring
    for (size_t i = 0; i + 1 < rings.size(); ++i) {
        if (rings[i + 1].second < rings[i].second - radiusTolerance) {
            widest = i;
            break;
        }
    }
    g.knobHeight = rings[widest].first;
    g.knobRadius = rings[widest].second;
    return g;
}

void addLidPlanes(std::vector<ShadowPlane>& planes, const Mesh& mesh, const glm::vec3& spoutward) {
    const std::vector<glm::vec3> lid = partVertices(mesh, {"lid"});
    const LidGeometry g = lidGeometry(mesh, lid);
    // Section 5, Figure 16: "Two perpendicular planes cut the geometry vertically with the same
    // silhouette": both contain the axis, one facing the side of the teapot (u along the spout-handle
    // line), the other turned 90 degrees about the axis, facing the spout. The lid is round, so the
    // second sees the same profile in the same place of its frame and shares the first's texture (one
    // texture unit less: the thesis's hardware limit). Both rectangles are centred on the axis with the
    // larger half-width of the two, so the shared texture maps alike.
    const glm::vec3 sideRight = inPlane(spoutward, g.axis);
    const glm::vec3 frontRight = glm::cross(g.axis, sideRight);
    Rect side = extents(lid, g.centre, sideRight, g.axis), front = extents(lid, g.centre, frontRight, g.axis);
    const float half = std::max({-side.u0, side.u1, -front.u0, front.u1});
    Rect profile;
    profile.extend(-half, std::min(side.v0, front.v0));
    profile.extend(half, std::max(side.v1, front.v1));
    const float margin = profile.margin();
    planes.push_back(rectanglePlane("lid_side", g.centre, glm::cross(sideRight, g.axis), sideRight, g.axis,
                                    profile, margin, {"lid"}));
    ShadowPlane front90 = rectanglePlane("lid_front", g.centre, glm::cross(frontRight, g.axis), frontRight,
                                         g.axis, profile, margin, {"lid"});
    front90.textureOf = "lid_side";
    planes.push_back(front90);

    // "A third plane intersected the widest point of the knob on the top of the teapot with a circular
    // silhouette": with the light from above, the vertical planes are edge-on and cast nothing. This
    // plane stands for the knob alone (the lid above its neck), not for the whole lid: its square
    // circumscribes the knob's widest ring, and its occluder should be that ring's disc. An orthographic
    // bake of all of {lid} along the normal fills the whole square (the dome lies under the knob); the
    // disc is the knob's cross-section at the plane, or the lid's geometry on the normal's side of the
    // plane (the knob's upper half) projected.
    const glm::vec3 knobCentre = g.centre + g.knobHeight * g.axis;
    Rect knob;
    knob.extend(-g.knobRadius, -g.knobRadius);
    knob.extend(g.knobRadius, g.knobRadius);
    planes.push_back(rectanglePlane("lid_knob", knobCentre, g.axis, sideRight, glm::cross(g.axis, sideRight),
                                    knob, knob.margin(), {"lid"}));
    planes.back().sectionOnly = true; // the disc of the knob's widest ring, not the dome's silhouette
}

void addSpoutPlanes(std::vector<ShadowPlane>& planes, const Mesh& mesh, const glm::vec3& teapotUp) {
    const std::vector<glm::vec3> spout = partVertices(mesh, {"spout"});
    const Principal ps = principal(spout);
    // Section 5, Figure 18: three planes "similar to the way the top was represented ... except on an
    // angle": the spout's principal axis (largest spread, from the body out to the tip) takes the lid
    // axis's role. Two planes contain it, as the lid's vertical planes contain the knob's axis: the
    // vertical profile (its normal horizontal: the teapot's mirror plane, the side view of the spout's
    // S) and the horizontal profile (its normal the upward perpendicular of the axis: the spout's width
    // seen from above along the spout). Both go through the spout's mean, cutting it in halves.
    const glm::vec3 axis = orient(ps.axes[0], ps.mean - mesh.computeBounds().center());
    const glm::vec3 sideNormal = glm::normalize(glm::cross(axis, teapotUp));
    const glm::vec3 upward = glm::cross(sideNormal, axis);
    const Rect vertical = extents(spout, ps.mean, axis, upward);
    planes.push_back(rectanglePlane("spout_vertical", ps.mean, sideNormal, axis, upward, vertical,
                                    vertical.margin(), {"spout"}));
    const glm::vec3 across = glm::cross(upward, axis);
    const Rect horizontal = extents(spout, ps.mean, axis, across);
    planes.push_back(rectanglePlane("spout_horizontal", ps.mean, upward, axis, across, horizontal,
                                    horizontal.margin(), {"spout"}));
    // The cap "to avoid seeing the X pattern at the tip of the shadow": with the light along the spout
    // the two profiles are edge-on and cast an X; the cap, perpendicular to the axis, holds the spout's
    // end-on silhouette (its rectangle covers the projection of the whole spout along the axis). It
    // stands at the tip (the spout's farthest point along the axis, moved in by the margin so it still
    // cuts the tip), so its shadow lands where the shadow of the spout's tip does.
    {
        const glm::vec3 right = -sideNormal;
        const Rect r = extents(spout, ps.mean, right, upward);
        float tip = -kInf;
        for (const auto& p : spout) tip = std::max(tip, glm::dot(axis, p - ps.mean));
        const float margin = r.margin();
        planes.push_back(rectanglePlane("spout_cap", ps.mean + (tip - margin) * axis, axis, right, upward, r,
                                        margin, {"spout"}));
    }
}

/// The handle's C: its plane (normal `normal` through `point`), an in-plane basis and the C's centre.
struct HandleFrame {
    glm::vec3 point{0.0f}, normal{0.0f}, e1{0.0f}, e2{0.0f};
    glm::vec2 centre{0.0f};
    float start = 0.0f; ///< angle of one end of the C (around `centre`, from e1 towards e2)
    float span = 0.0f;  ///< the C's angular extent from `start` (the other end)

    glm::vec2 planar(const glm::vec3& p) const {
        return glm::vec2(glm::dot(e1, p - point), glm::dot(e2, p - point)) - centre;
    }
    /// Angle from the start end, in [0, 2 pi).
    float phi(const glm::vec3& p) const {
        const glm::vec2 q = planar(p);
        float a = std::atan2(q.y, q.x) - start;
        a = std::fmod(a, kTwoPi);
        return a < 0.0f ? a + kTwoPi : a;
    }
    glm::vec3 at(float phiValue, float radius) const {
        const float a = start + phiValue;
        return point + (centre.x + radius * std::cos(a)) * e1 + (centre.y + radius * std::sin(a)) * e2;
    }
};

HandleFrame handleFrame(const std::vector<glm::vec3>& handle) {
    // The handle is a bent tube whose C lies in the plane of its two larger spreads: the smallest
    // principal axis is the C plane's normal. Its centre is the middle of the C's in-plane extents; the
    // C's ends are the two sides of the largest angular gap between its vertices around that centre
    // (where the C opens towards the body).
    const Principal ph = principal(handle);
    HandleFrame f;
    f.point = ph.mean;
    f.normal = canonical(ph.axes[2]);
    f.e1 = canonical(ph.axes[0]);
    f.e2 = glm::cross(f.normal, f.e1);
    glm::vec2 lo(kInf), hi(-kInf);
    for (const auto& p : handle) {
        const glm::vec2 q(glm::dot(f.e1, p - f.point), glm::dot(f.e2, p - f.point));
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    f.centre = 0.5f * (lo + hi);
    std::vector<float> angles;
    for (const auto& p : handle) {
        const glm::vec2 q = f.planar(p);
        angles.push_back(std::atan2(q.y, q.x));
    }
    std::sort(angles.begin(), angles.end());
    float gap = angles.front() + kTwoPi - angles.back();
    f.start = angles.front();
    for (size_t i = 0; i + 1 < angles.size(); ++i) {
        if (angles[i + 1] - angles[i] > gap) {
            gap = angles[i + 1] - angles[i];
            f.start = angles[i + 1];
        }
    }
    f.span = kTwoPi - gap;
    return f;
}

/// The C's centre curve, sampled by angle around its centre: at each angle, the ray from the centre
/// crosses the handle's outline (its triangles' edges projected on the C's plane) from the inner to
/// the outer side of the tube; the curve runs midway. Independent of the tessellation's vertex
/// placement. Returns (angle, point) pairs, ends first to last, and the tube's mean thickness in the C's
/// plane (outer minus inner side).
std::vector<std::pair<float, glm::vec3>> handleCentreCurve(const Mesh& mesh, const MeshPart& part,
                                                           const HandleFrame& f, float& thickness) {
    constexpr int kSamples = 121;
    std::vector<float> inner(kSamples, kInf), outer(kSamples, -kInf);
    auto sampleAngle = [&](int k) { return f.span * float(k) / float(kSamples - 1); };
    auto cross2 = [](const glm::vec2& a, const glm::vec2& b) { return a.x * b.y - a.y * b.x; };
    for (uint32_t t = part.firstIndex; t + 3 <= part.firstIndex + part.indexCount; t += 3) {
        for (int e = 0; e < 3; ++e) {
            const glm::vec3& pa = mesh.positions[mesh.indices[t + uint32_t(e)]];
            const glm::vec3& pb = mesh.positions[mesh.indices[t + uint32_t((e + 1) % 3)]];
            const float phiA = f.phi(pa), phiB = f.phi(pb);
            if (std::abs(phiA - phiB) > glm::pi<float>()) continue; // across the C's opening
            const glm::vec2 a = f.planar(pa), edge = f.planar(pb) - a;
            const float lo = std::min(phiA, phiB), hi = std::max(phiA, phiB);
            const int k0 = std::max(0, int(std::ceil(lo / f.span * float(kSamples - 1))));
            const int k1 = std::min(kSamples - 1, int(std::floor(hi / f.span * float(kSamples - 1))));
            for (int k = k0; k <= k1; ++k) {
                // The ray r * d meets the edge a + s * edge at r = (a x edge) / (d x edge).
                const float angle = f.start + sampleAngle(k);
                const glm::vec2 d(std::cos(angle), std::sin(angle));
                const float denominator = cross2(d, edge);
                if (std::abs(denominator) < 1e-12f) continue;
                const float r = cross2(a, edge) / denominator, s = cross2(a, d) / denominator;
                if (r <= 0.0f || s < -1e-4f || s > 1.0f + 1e-4f) continue;
                inner[size_t(k)] = std::min(inner[size_t(k)], r);
                outer[size_t(k)] = std::max(outer[size_t(k)], r);
            }
        }
    }
    std::vector<std::pair<float, glm::vec3>> curve;
    thickness = 0.0f;
    for (int k = 0; k < kSamples; ++k) {
        if (!(inner[size_t(k)] <= outer[size_t(k)])) continue;
        curve.emplace_back(sampleAngle(k),
                           f.at(sampleAngle(k), 0.5f * (inner[size_t(k)] + outer[size_t(k)])));
        thickness += outer[size_t(k)] - inner[size_t(k)];
    }
    thickness /= float(std::max<size_t>(curve.size(), 1));
    return curve;
}

/// The centres of the tube's open ends (where the handle meets the body; the rays there cut the slanted
/// end only partly): the mean of each end's boundary vertices (of the edges that only one triangle
/// uses, positions welded), the ends told apart by the half of the C they lie in. Empty when the part
/// has no open end.
std::vector<std::pair<float, glm::vec3>> handleEnds(const Mesh& mesh, const MeshPart& part,
                                                    const HandleFrame& f,
                                                    const std::vector<glm::vec3>& handle) {
    Aabb bounds;
    for (const auto& p : handle) bounds.extend(p);
    const float quantum = 1e-5f * std::max({bounds.extent().x, bounds.extent().y, bounds.extent().z});
    std::map<std::array<int64_t, 3>, uint32_t> ids;
    std::vector<glm::vec3> welded;
    auto weld = [&](const glm::vec3& p) {
        const std::array<int64_t, 3> key = {std::llround(p.x / quantum), std::llround(p.y / quantum),
                                            std::llround(p.z / quantum)};
        const auto [it, added] = ids.emplace(key, uint32_t(welded.size()));
        if (added) welded.push_back(p);
        return it->second;
    };
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    for (uint32_t t = part.firstIndex; t + 3 <= part.firstIndex + part.indexCount; t += 3) {
        uint32_t v[3];
        for (int k = 0; k < 3; ++k) v[k] = weld(mesh.positions[mesh.indices[t + uint32_t(k)]]);
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = v[k], b = v[(k + 1) % 3];
            if (a != b) ++edges[{std::min(a, b), std::max(a, b)}];
        }
    }
    std::set<uint32_t> boundary;
    for (const auto& [edge, count] : edges)
        if (count == 1) {
            boundary.insert(edge.first);
            boundary.insert(edge.second);
        }
    glm::vec3 sum[2] = {glm::vec3(0.0f), glm::vec3(0.0f)};
    int count[2] = {0, 0};
    for (uint32_t id : boundary) {
        const int end = f.phi(welded[id]) < 0.5f * f.span ? 0 : 1;
        sum[end] += welded[id];
        ++count[end];
    }
    if (count[0] == 0 || count[1] == 0) return {};
    const glm::vec3 first = sum[0] / float(count[0]), last = sum[1] / float(count[1]);
    return {{f.phi(first), first}, {f.phi(last), last}};
}

void addHandlePlanes(std::vector<ShadowPlane>& planes, const Mesh& mesh, const glm::vec3& teapotUp) {
    const std::vector<glm::vec3> handle = partVertices(mesh, {"handle"});
    const MeshPart& part = *findPart(mesh, "handle");
    const HandleFrame f = handleFrame(handle);
    float thickness = 0.0f;
    std::vector<std::pair<float, glm::vec3>> curve = handleCentreCurve(mesh, part, f, thickness);
    // The curve runs between the centres of the open ends (the joints with the body).
    const auto ends = handleEnds(mesh, part, f, handle);
    if (ends.size() == 2) {
        std::vector<std::pair<float, glm::vec3>> inside = {ends[0]};
        for (const auto& sample : curve)
            if (sample.first > ends[0].first && sample.first < ends[1].first) inside.push_back(sample);
        inside.push_back(ends[1]);
        curve = std::move(inside);
    }
    if (curve.size() < 2) throw Error("teapot: cannot trace the handle's centre curve");
    // Section 5, Figure 20: one C-shaped plane casts nothing with the light above ("the thickness of
    // the handle should actually cast a shadow straight down"), and overlapping textured planes showed
    // their seams; "the best results were obtained using five segments ... and no occluder textures at
    // all": solid strips end to end along the C. Each spans one fifth of the centre curve's length, as
    // the chord between its ends, and the handle's width across the C (the extent along the C plane's
    // normal of the handle's vertices in its angular range), so that from any light in the C's plane
    // the strips' shadows join into the handle's.
    std::vector<float> length(curve.size(), 0.0f);
    for (size_t i = 1; i < curve.size(); ++i)
        length[i] = length[i - 1] + glm::length(curve[i].second - curve[i - 1].second);
    std::vector<std::pair<float, glm::vec3>> cuts; // (angle, point) where the segments meet
    for (int s = 0; s <= BuiltinShadowPlanes::kHandleSegments; ++s) {
        const float target = length.back() * float(s) / float(BuiltinShadowPlanes::kHandleSegments);
        size_t i = 1;
        while (i + 1 < curve.size() && length[i] < target) ++i;
        const float w =
            length[i] > length[i - 1] ? (target - length[i - 1]) / (length[i] - length[i - 1]) : 0.0f;
        const float t = std::clamp(w, 0.0f, 1.0f);
        cuts.emplace_back((1 - t) * curve[i - 1].first + t * curve[i].first,
                          (1 - t) * curve[i - 1].second + t * curve[i].second);
    }
    // Numbered from the upper joint down.
    if (glm::dot(teapotUp, cuts.front().second - cuts.back().second) < 0.0f)
        std::reverse(cuts.begin(), cuts.end());
    float allLo = kInf, allHi = -kInf;
    for (const auto& p : handle) {
        allLo = std::min(allLo, glm::dot(f.normal, p - f.point));
        allHi = std::max(allHi, glm::dot(f.normal, p - f.point));
    }
    if (!(allHi - allLo > 1e-3f * thickness)) {
        // Tessellation 1 keeps only the patches' corners, all on the C's plane: the tube's thickness
        // in that plane stands in for its width (a round tube).
        allLo = -0.5f * thickness;
        allHi = 0.5f * thickness;
    }
    for (int s = 0; s < BuiltinShadowPlanes::kHandleSegments; ++s) {
        const auto& [phi0, p0] = cuts[size_t(s)];
        const auto& [phi1, p1] = cuts[size_t(s) + 1];
        // Widened a little: mirror-image vertices (z and -z) differ in angle by rounding only.
        const float slack = 1e-3f * f.span;
        const float phiLo = std::min(phi0, phi1) - slack, phiHi = std::max(phi0, phi1) + slack;
        float lo = kInf, hi = -kInf;
        for (const auto& p : handle) {
            const float phi = f.phi(p);
            if (phi < phiLo || phi > phiHi) continue;
            lo = std::min(lo, glm::dot(f.normal, p - f.point));
            hi = std::max(hi, glm::dot(f.normal, p - f.point));
        }
        if (!(hi - lo > 1e-3f * thickness)) { // too coarse for vertices in this fifth: the handle's width
            lo = allLo;
            hi = allHi;
        }
        ShadowPlane p;
        p.name = "handle_" + std::to_string(s + 1);
        p.right = glm::normalize(p1 - p0);
        p.up = f.normal;
        p.normal = glm::cross(p.right, p.up);
        p.origin = p0 + lo * f.normal;
        p.width = glm::length(p1 - p0);
        p.height = hi - lo;
        p.solid = true;
        p.parts = {"handle"};
        planes.push_back(p);
    }
}

} // namespace

std::vector<ShadowPlane> BuiltinShadowPlanes::forGenerator(const std::string& generator, const Mesh& mesh) {
    std::vector<ShadowPlane> planes;
    if (generator == "aircraft") planes = aircraft(mesh);
    if (generator == "teapot") planes = teapot(mesh);
    for (const auto& p : planes) p.validate("built-in shadow planes of generator '" + generator + "'");
    return planes;
}

std::vector<ShadowPlane> BuiltinShadowPlanes::aircraft(const Mesh& mesh) {
    if (!hasParts(mesh, {"fuselage", "wings", "stabilisers", "fin_left", "fin_right"})) return {};
    std::vector<ShadowPlane> planes;
    // Texture A (Figure 13, section 5): "the wings, fuselage, and horizontal stabilizers (basically,
    // everything on the X-Y plane [of the thesis's Z-up model]) are chosen as a single shadow plane",
    // "a third shadow plane that cut the entire aircraft into a top half and bottom half". The wings and
    // stabilisers are thin slabs in one plane: the direction of least spread of their vertices is that
    // plane's normal and their mean lies on the slabs' mid-plane (both faces are offset alike).
    const std::vector<glm::vec3> flatParts = partVertices(mesh, {"wings", "stabilisers"});
    const Principal flat = principal(flatParts);
    const glm::vec3 wingNormal = canonical(flat.axes[2]);
    // u along the fuselage (its largest spread), v spanwise; up = normal x right, a view from above.
    const std::vector<glm::vec3> fuselage = partVertices(mesh, {"fuselage"});
    const Principal body = principal(fuselage);
    const glm::vec3 along = inPlane(canonical(body.axes[0]), wingNormal);
    const glm::vec3 spanwise = glm::cross(wingNormal, along);
    // Its silhouette is the top view without the fins ("the vertical tail fin geometry had to be
    // removed so that it did not show up"): the rectangle covers fuselage, wings and stabilisers.
    Rect wings = extents(fuselage, flat.mean, along, spanwise);
    const Rect flatExtents = extents(flatParts, flat.mean, along, spanwise);
    wings.extend(flatExtents.u0, flatExtents.v0);
    wings.extend(flatExtents.u1, flatExtents.v1);
    planes.push_back(rectanglePlane("wings", flat.mean, wingNormal, along, spanwise, wings, wings.margin(),
                                    {"fuselage", "wings", "stabilisers"}));

    // The tail fins (Figures 7 and 9): each fin is a slab, its plane the mid-plane (least spread, through
    // the mean). u along the fuselage's axis, v from the fin's root to its tip.
    const std::vector<glm::vec3> right = partVertices(mesh, {"fin_right"});
    const std::vector<glm::vec3> left = partVertices(mesh, {"fin_left"});
    const Principal fin = principal(right);
    const glm::vec3 finNormal0 = fin.axes[2];
    const glm::vec3 chord = inPlane(canonical(body.axes[0]), finNormal0);
    const glm::vec3 rootToTip = orient(glm::cross(finNormal0, chord), fin.mean - body.mean);
    const glm::vec3 finNormal = glm::cross(chord, rootToTip);
    // "The other vertical tail fin has exactly the same shape", and both used one texture: the left
    // fin's plane is the mirror image of the right's across the aircraft's plane of symmetry (through
    // the fuselage's axis, normal spanwise), frame included, so that a point and its mirror image get
    // the same uv. The rectangle covers both fins (the left one mirrored) in the shared frame.
    auto mirror = [&](const glm::vec3& p) { return p - 2.0f * glm::dot(spanwise, p - body.mean) * spanwise; };
    auto mirrorDir = [&](const glm::vec3& d) { return d - 2.0f * glm::dot(spanwise, d) * spanwise; };
    Rect fins = extents(right, fin.mean, chord, rootToTip);
    for (const auto& p : left) {
        const glm::vec3 q = mirror(p);
        fins.extend(glm::dot(chord, q - fin.mean), glm::dot(rootToTip, q - fin.mean));
    }
    const float margin = fins.margin();
    // Section 5: the artist extended the fin's silhouette "downward so that ... the black silhouette
    // penetrated down into the object rather than just touching the edge", since a raster edge never
    // matches the geometric one. The rectangle reaches below the root, through the fuselage's upper half
    // down to the wings' plane (below it the wings' texture takes over), plus the margin: room for that
    // extension (the bake marks the fuselage's section there).
    const float upAcross = glm::dot(wingNormal, rootToTip);
    if (std::abs(upAcross) > 0.1f) {
        for (float u : {fins.u0, fins.u1}) {
            // The point c + u * chord + v * rootToTip on the wings' plane.
            const float v = glm::dot(wingNormal, flat.mean - fin.mean - u * chord) / upAcross;
            fins.v0 = std::min(fins.v0, v);
        }
    }
    ShadowPlane finRight =
        rectanglePlane("fin_right", fin.mean, finNormal, chord, rootToTip, fins, margin, {"fin_right"});
    ShadowPlane finLeft = finRight;
    finLeft.name = "fin_left";
    finLeft.origin = mirror(finRight.origin);
    finLeft.normal = mirrorDir(finRight.normal);
    finLeft.right = mirrorDir(finRight.right);
    finLeft.up = mirrorDir(finRight.up);
    finLeft.parts = {"fin_left"};
    finLeft.textureOf = "fin_right";
    planes.push_back(finRight);
    planes.push_back(finLeft);
    return planes;
}

std::vector<ShadowPlane> BuiltinShadowPlanes::teapot(const Mesh& mesh) {
    if (!hasParts(mesh, {"lid", "spout", "handle"})) return {};
    // Section 5: the round body "cannot cast shadows onto itself" (shading shows its shape), so the
    // body, rim and bottom get no planes; the lid, spout and handle are the protrusions that cast
    // shadows, each needing several planes because none of them is flat.
    std::vector<ShadowPlane> planes;
    const std::vector<glm::vec3> lid = partVertices(mesh, {"lid"});
    const glm::vec3 up = lidGeometry(mesh, lid).axis; // the teapot's up: the lid's (and knob's) axis
    const glm::vec3 spoutward =
        principal(partVertices(mesh, {"spout"})).mean - principal(partVertices(mesh, {"handle"})).mean;
    // The receiver sections (section 5): "the front of the teapot can only receive shadows from the
    // spout. The back of the teapot can only receive shadows from the handle. The top of the teapot can
    // only receive shadows from the top", so the thesis cut the teapot into three objects, each drawn with
    // its own planes only, and "the spout does not self-shadow". What makes the sections necessary here
    // is the spout: its horizontal profile and its cap cut across it, and their silhouettes (the spout's
    // width seen from above, its end-on outline) cover its own lit surface next to the cuts, so a point on
    // the tip's upper side whose ray to the light crosses the cap or the profile inside the silhouette
    // passes beside the spout, not through it: a false shadow on the tip. Those two planes therefore
    // shadow every part but the spout. The other planes keep every part as receiver: the lid's and the
    // spout's vertical profile are surfaces of revolution or tubes cut through their axis, whose
    // silhouettes are their cross-sections (a ray through them goes through the solid), and the solid
    // handle strips lie inside the handle. Measured against the Embree reference (six lights, four
    // cameras, 256^2) this split has the fewest wrong pixels of the splits tried: summed over the 24
    // views 61.8 points, against 114.4 with every plane on every part and 108.5 for the thesis's three
    // sections by part (lid planes on the top and body, spout and handle planes on the body only, which
    // loses the lid's and handle's true shadows on spout and handle).
    const std::vector<std::string> notSpout = {"rim", "body", "handle", "lid", "bottom"};
    addLidPlanes(planes, mesh, spoutward);
    addSpoutPlanes(planes, mesh, up);
    for (ShadowPlane& p : planes)
        if (p.name == "spout_horizontal" || p.name == "spout_cap") p.receivers = notSpout;
    addHandlePlanes(planes, mesh, up);
    return planes;
}

} // namespace sb
