#include "scenes/MeshGenerators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "core/Error.h"
#include "scenes/BezierPatch.h"
#include "scenes/MeshBuilder.h"

namespace sb {
namespace {

constexpr float kTwoPi = glm::two_pi<float>();

void requireTessellation(const char* generator, int tess, int minimum) {
    if (tess < minimum || tess > 4096)
        throw Error(std::string(generator) + ": tessellation must be in [" + std::to_string(minimum) +
                    ", 4096], got " + std::to_string(tess));
}

/// Angle of segment `j` of `count`; the seam column (j == count) reuses column 0's angle exactly so
/// the duplicated seam vertices coincide bit for bit (closedness tests weld by position).
float segmentAngle(int j, int count) {
    return kTwoPi * float(j % count) / float(count);
}

/// Triangulates a (rows+1) x (cols+1) grid whose first row and/or last row collapse to a point
/// (sphere and fuselage poles): the degenerate half of each pole quad is left out.
void addPolarGrid(MeshBuilder& b, uint32_t first, int rows, int cols, bool firstRowPole, bool lastRowPole) {
    const uint32_t stride = uint32_t(cols + 1);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            const uint32_t a = first + uint32_t(r) * stride + uint32_t(c);
            const uint32_t bb = a + 1, d = a + stride, e = d + 1;
            if (!(firstRowPole && r == 0)) b.addTriangle(a, bb, e);
            if (!(lastRowPole && r == rows - 1)) b.addTriangle(a, e, d);
        }
    }
}

// ---- box ------------------------------------------------------------------------------------------

/// One face of a box: normal n, tangents u and v with cross(u, v) = n, so the grid built along u
/// (columns) and v (rows) is counter-clockwise seen from outside.
void addBoxFace(MeshBuilder& b, glm::vec3 n, glm::vec3 u, const glm::vec3& half, int tess) {
    const glm::vec3 v = glm::cross(n, u);
    const glm::vec3 centre = n * half, du = u * half, dv = v * half;
    const uint32_t first = b.vertexCount();
    for (int r = 0; r <= tess; ++r) {
        for (int c = 0; c <= tess; ++c) {
            const float s = 2.0f * float(c) / float(tess) - 1.0f, t = 2.0f * float(r) / float(tess) - 1.0f;
            b.addVertex(centre + s * du + t * dv, n);
        }
    }
    b.addGrid(first, tess, tess);
}

// ---- aircraft -----------------------------------------------------------------------------------

constexpr float kAircraftSpan = 1.4f;
constexpr float kSlabThickness = 0.02f * kAircraftSpan;
constexpr float kFuselageMaxRadius = 0.11f;
constexpr float kFuselageWidthRatio = 1.3f; ///< elliptic cross section: wider than tall
constexpr float kFinCantDeg = 25.0f;

/// Fuselage radius (height semi-axis) at s in [0,1] from the nose (x = +1) to the tail (x = -1):
/// a parabolic ogive nose, a constant mid-body and a linear taper to an engine nozzle.
float fuselageRadius(float s) {
    if (s < 0.35f) {
        const float t = 1.0f - s / 0.35f;
        return kFuselageMaxRadius * (1.0f - t * t);
    }
    if (s > 0.65f) return kFuselageMaxRadius * (1.0f - 0.45f * (s - 0.65f) / 0.35f);
    return kFuselageMaxRadius;
}

glm::vec3 fuselagePoint(float s, float theta) {
    const float r = fuselageRadius(s);
    return {1.0f - 2.0f * s, r * std::sin(theta), kFuselageWidthRatio * r * std::cos(theta)};
}

/// Smooth normal from the analytic tangents: around (d/dtheta) and along the body (d/dx, the radius
/// slope by central differences). cross(d/dx, d/dtheta) points outward.
glm::vec3 fuselageNormal(float s, float theta) {
    const float h = 1e-3f;
    const float s0 = std::max(s - h, 0.0f), s1 = std::min(s + h, 1.0f);
    const float dr = (fuselageRadius(s1) - fuselageRadius(s0)) / ((s1 - s0) * -2.0f); // d r / d x
    const float r = fuselageRadius(s);
    const glm::vec3 alongX(1.0f, dr * std::sin(theta), kFuselageWidthRatio * dr * std::cos(theta));
    const glm::vec3 around(0.0f, r * std::cos(theta), -kFuselageWidthRatio * r * std::sin(theta));
    return glm::cross(alongX, around);
}

void addFuselage(MeshBuilder& b, int tess) {
    const int rings = 2 * tess, segments = 2 * tess;
    const uint32_t first = b.vertexCount();
    for (int i = 0; i <= rings; ++i) {
        const float s = float(i) / float(rings);
        for (int j = 0; j <= segments; ++j) {
            const float theta = segmentAngle(j, segments);
            // The nose is a pole: its normal is the body axis, where the tangents degenerate.
            b.addVertex(fuselagePoint(s, theta), i == 0 ? glm::vec3(1, 0, 0) : fuselageNormal(s, theta));
        }
    }
    addPolarGrid(b, first, rings, segments, true, false);
    // Flat nozzle cap at the tail, its own vertices so the normal is faceted.
    const uint32_t centre = b.addVertex(glm::vec3(-1.0f, 0.0f, 0.0f), glm::vec3(-1, 0, 0));
    const uint32_t ring = b.vertexCount();
    for (int j = 0; j <= segments; ++j)
        b.addVertex(fuselagePoint(1.0f, segmentAngle(j, segments)), glm::vec3(-1, 0, 0));
    for (int j = 0; j < segments; ++j) b.addTriangle(centre, ring + uint32_t(j), ring + uint32_t(j) + 1);
}

/// A thin closed slab around the planar quad q[0..3] (any winding): top and bottom faces split
/// n x n, four side strips split n x 1 so their edges meet the faces' edges (no T-junctions), flat
/// normals throughout.
class Slab {
public:
    Slab(const std::array<glm::vec3, 4>& q, float thickness, int n) : mQ(q), mN(n) {
        mNormal = glm::normalize(glm::cross(q[1] - q[0], q[3] - q[0]));
        mHalf = 0.5f * thickness * mNormal;
    }

    void build(MeshBuilder& b) const {
        addFace(b, +1.0f);
        addFace(b, -1.0f);
        for (int edge = 0; edge < 4; ++edge) addSide(b, edge);
    }

private:
    /// Bilinear point of the planform at integer grid coordinates (exact on shared edges).
    glm::vec3 at(int c, int r) const {
        const float a = float(c) / float(mN), t = float(r) / float(mN);
        return (1 - a) * (1 - t) * mQ[0] + a * (1 - t) * mQ[1] + a * t * mQ[2] + (1 - a) * t * mQ[3];
    }

    /// Grid coordinates of point j (0..n) along edge 0..3, walking q0 -> q1 -> q2 -> q3 -> q0.
    glm::ivec2 edgePoint(int edge, int j) const {
        switch (edge) {
        case 0:
            return {j, 0};
        case 1:
            return {mN, j};
        case 2:
            return {mN - j, mN};
        default:
            return {0, mN - j};
        }
    }

    void addFace(MeshBuilder& b, float side) const {
        const uint32_t first = b.vertexCount();
        for (int r = 0; r <= mN; ++r)
            for (int c = 0; c <= mN; ++c) b.addVertex(at(c, r) + side * mHalf, side * mNormal);
        b.addGrid(first, mN, mN, side < 0.0f);
    }

    void addSide(MeshBuilder& b, int edge) const {
        const glm::vec3 p0 = at(edgePoint(edge, 0).x, edgePoint(edge, 0).y);
        const glm::vec3 p1 = at(edgePoint(edge, mN).x, edgePoint(edge, mN).y);
        const glm::vec3 outward = glm::cross(p1 - p0, mNormal);
        const uint32_t first = b.vertexCount();
        for (int j = 0; j <= mN; ++j) {
            const glm::ivec2 g = edgePoint(edge, j);
            b.addVertex(at(g.x, g.y) + mHalf, outward);
            b.addVertex(at(g.x, g.y) - mHalf, outward);
        }
        // Quad top_j, bottom_j, bottom_j+1, top_j+1 faces along cross(edge, normal) = outward.
        for (uint32_t j = 0; j < uint32_t(mN); ++j)
            b.addQuad(first + 2 * j, first + 2 * j + 1, first + 2 * j + 3, first + 2 * j + 2);
    }

    std::array<glm::vec3, 4> mQ;
    int mN;
    glm::vec3 mNormal, mHalf;
};

/// Planform in the y = 0 plane, mirrored to z -> -z for the other side: root leading/trailing edge
/// x at z = rootZ, tip leading/trailing edge x at z = tipZ.
void addMirroredPlanform(MeshBuilder& b, float rootLe, float rootTe, float tipLe, float tipTe, float rootZ,
                         float tipZ, int n) {
    for (float side : {1.0f, -1.0f}) {
        Slab({glm::vec3(rootLe, 0, side * rootZ), glm::vec3(rootTe, 0, side * rootZ),
              glm::vec3(tipTe, 0, side * tipZ), glm::vec3(tipLe, 0, side * tipZ)},
             kSlabThickness, n)
            .build(b);
    }
}

/// A tail fin canted outward by kFinCantDeg from vertical; side = +1 for the fin at +z, -1 for -z.
/// Facing the nose (+X) with +Y up, the pilot's right is +Z: the right fin is side +1.
void addFin(MeshBuilder& b, float side, int n) {
    const float cant = glm::radians(kFinCantDeg);
    const glm::vec3 up(0.0f, std::cos(cant), side * std::sin(cant));
    const glm::vec3 root(0.0f, 0.03f, side * 0.07f);
    const float height = 0.38f;
    auto point = [&](float x, float h) { return root + glm::vec3(x, 0, 0) + h * up; };
    Slab({point(-0.50f, 0.0f), point(-0.82f, 0.0f), point(-0.90f, height), point(-0.74f, height)},
         kSlabThickness, n)
        .build(b);
}

// ---- teapot -------------------------------------------------------------------------------------

/// The data is Z-up; shadowbench is Y-up: (x, y, z) -> (x, z, -y), a proper rotation (det = +1) so
/// the winding is kept. The data's z already starts at 0, so the teapot stands on y = 0.
glm::vec3 toYUp(const glm::vec3& p) {
    return {p.x, p.z, -p.y};
}

/// Outward normal of the patch at (u, v). The teapot patches are oriented so that dS/dv x dS/du
/// points outward. At collapsed edges (the lid knob's top, the bottom's centre) both the tangent
/// cross product vanishes; the normal there is the limit from the interior, approximated by the
/// normal a small step towards the patch centre, and +Y if even that is degenerate.
glm::vec3 patchNormal(const BezierPatch& patch, float u, float v) {
    for (float step : {0.0f, 1e-3f, 1e-2f, 5e-2f}) {
        const float uu = u + (0.5f - u) * step * 2.0f, vv = v + (0.5f - v) * step * 2.0f;
        const glm::vec3 n = glm::cross(patch.derivativeV(uu, vv), patch.derivativeU(uu, vv));
        const float len = glm::length(n);
        if (len > 1e-6f && std::isfinite(len)) return toYUp(n / len);
    }
    return glm::vec3(0.0f, 1.0f, 0.0f);
}

void addPatch(MeshBuilder& b, const BezierPatch& patch, int tess) {
    const uint32_t first = b.vertexCount();
    for (int r = 0; r <= tess; ++r) {
        for (int c = 0; c <= tess; ++c) {
            const float u = float(r) / float(tess), v = float(c) / float(tess);
            b.addVertex(toYUp(patch.evaluate(u, v)), patchNormal(patch, u, v));
        }
    }
    // Grid normal cross(d/dcolumn, d/drow) = dS/dv x dS/du: the same side as patchNormal.
    b.addGrid(first, tess, tess);
}

struct PatchGroup {
    const char* name;
    int first, count;
};
/// Patch groups of the standard 32-patch Utah teapot (checked against the data's extents: the rim
/// is the ring at z 2.4..2.53, the handle the only patches at x < -1.5, the spout at x > 1.7, the
/// lid the patches above the rim, the bottom the disc at z 0..0.15).
constexpr PatchGroup kTeapotGroups[] = {{"rim", 0, 4},    {"body", 4, 8}, {"handle", 12, 4},
                                        {"spout", 16, 4}, {"lid", 20, 8}, {"bottom", 28, 4}};

// ---- lantern ------------------------------------------------------------------------------------

/// A face hole of the lantern in latitude (degrees above the equator) and longitude (degrees from +Z
/// towards -X, i.e. phi - 90): rows whose centre latitude is in [latBottom, latTop] remove the cells
/// whose centre longitude is within halfWidth(lat) of centreLon.
struct LanternHole {
    float centreLon, latBottom, latTop;
    float (*halfWidth)(float lat);
};

/// Eyes: triangles with the apex up, 28 degrees wide at the base (8 degrees above the equator), 26 high.
float eyeHalfWidth(float lat) {
    return 14.0f * (34.0f - lat) / 26.0f;
}
/// Mouth: the lower half of an ellipse, flat top 12 degrees below the equator, 96 degrees wide, 28 deep.
float mouthHalfWidth(float lat) {
    const float t = (lat + 12.0f) / 28.0f;
    return 48.0f * std::sqrt(std::max(0.0f, 1.0f - t * t));
}
constexpr LanternHole kLanternFaceHoles[] = {{-30.0f, 8.0f, 34.0f, eyeHalfWidth},
                                             {30.0f, 8.0f, 34.0f, eyeHalfWidth},
                                             {0.0f, -40.0f, -12.0f, mouthHalfWidth}};
/// The bottom hole: every cell whose centre lies more than 62 degrees below the equator.
constexpr float kLanternBottomLat = -62.0f;

/// Hole id (0..3) of every grid cell (rows x segments, row-major), -1 where the shell is kept. Throws if
/// the tessellation is too coarse for the holes (a hole without cells, two holes sharing a vertex, a
/// face hole in a pole row).
std::vector<int> lanternHoles(int rows, int segments) {
    std::vector<int> hole(size_t(rows) * size_t(segments), -1);
    auto cell = [&](int r, int c) -> int& { return hole[size_t(r) * size_t(segments) + size_t(c)]; };
    const float rowDeg = 180.0f / float(rows), colDeg = 360.0f / float(segments);
    for (int h = 0; h < 3; ++h) {
        const LanternHole& shape = kLanternFaceHoles[h];
        // Columns are numbered from phi = 0 (+X); longitude 0 is +Z (phi = 90 degrees).
        const float centreCol = (shape.centreLon + 90.0f) / colDeg; // in column units, cell j spans [j, j+1)
        std::vector<int> lo(size_t(rows), 0), hi(size_t(rows), -1); // empty where hi < lo
        int first = rows, last = -1;
        for (int r = 0; r < rows; ++r) {
            const float lat = 90.0f - (float(r) + 0.5f) * rowDeg;
            if (lat < shape.latBottom || lat > shape.latTop) continue;
            const float w = shape.halfWidth(lat) / colDeg;
            // Cells whose centre j + 0.5 lies in [centreCol - w, centreCol + w].
            lo[size_t(r)] = int(std::ceil(centreCol - w - 0.5f));
            hi[size_t(r)] = int(std::floor(centreCol + w - 0.5f));
            if (hi[size_t(r)] < lo[size_t(r)]) continue;
            first = std::min(first, r);
            last = std::max(last, r);
        }
        const int centreCell = std::clamp(int(std::floor(centreCol)), 0, segments - 1);
        if (last < 0) { // too coarse for the outline: the cell under its centre
            const float lat = 0.5f * (shape.latBottom + shape.latTop);
            first = last = std::clamp(int((90.0f - lat) / rowDeg), 0, rows - 1);
            lo[size_t(first)] = hi[size_t(first)] = centreCell;
        }
        // Row intervals that do not overlap their predecessor (an empty row in between, or a step of
        // the outline wider than a cell) would leave cells touching only at a corner: widen them, so
        // the cells are 4-connected without pinches and the hole's border is one simple loop.
        for (int r = first; r <= last; ++r) {
            if (hi[size_t(r)] < lo[size_t(r)]) lo[size_t(r)] = hi[size_t(r)] = centreCell;
            if (r > first) {
                hi[size_t(r)] = std::max(hi[size_t(r)], lo[size_t(r) - 1]);
                lo[size_t(r)] = std::min(lo[size_t(r)], hi[size_t(r) - 1]);
            }
        }
        for (int r = first; r <= last; ++r) {
            if (r == 0 || r == rows - 1 || lo[size_t(r)] < 0 || hi[size_t(r)] >= segments)
                throw Error("lantern: tessellation " + std::to_string(rows) + " puts a face hole on a pole");
            for (int c = lo[size_t(r)]; c <= hi[size_t(r)]; ++c) {
                if (cell(r, c) >= 0)
                    throw Error("lantern: tessellation " + std::to_string(rows) +
                                " is too coarse for the holes");
                cell(r, c) = h;
            }
        }
    }
    // The bottom hole: whole rows around the pole (the last row, the pole's fan, always qualifies).
    for (int r = 0; r < rows; ++r)
        if (90.0f - (float(r) + 0.5f) * rowDeg < kLanternBottomLat || r == rows - 1)
            for (int c = 0; c < segments; ++c) {
                if (cell(r, c) >= 0)
                    throw Error("lantern: tessellation " + std::to_string(rows) +
                                " is too coarse for the holes");
                cell(r, c) = 3;
            }
    // No two holes may share a vertex: the kept cells between them must form a ring of shell.
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < segments; ++c)
            for (int dr = -1; dr <= 1; ++dr)
                for (int dc = -1; dc <= 1; ++dc) {
                    const int rr = r + dr, cc = (c + dc + segments) % segments;
                    if (rr < 0 || rr >= rows || cell(r, c) < 0 || cell(rr, cc) < 0) continue;
                    if (cell(r, c) != cell(rr, cc))
                        throw Error("lantern: tessellation " + std::to_string(rows) +
                                    " makes two holes touch");
                }
    return hole;
}

/// Removes the vertices no triangle uses (the grid vertices inside the lantern's holes), keeping the
/// order of the others.
void dropUnusedVertices(Mesh& mesh) {
    constexpr uint32_t kUnused = UINT32_MAX;
    std::vector<uint32_t> remap(mesh.positions.size(), kUnused);
    for (uint32_t i : mesh.indices) remap[i] = 0;
    uint32_t next = 0;
    for (size_t v = 0; v < remap.size(); ++v) {
        if (remap[v] == kUnused) continue;
        remap[v] = next;
        mesh.positions[next] = mesh.positions[v];
        mesh.normals[next] = mesh.normals[v];
        ++next;
    }
    mesh.positions.resize(next);
    mesh.normals.resize(next);
    for (uint32_t& i : mesh.indices) i = remap[i];
}

} // namespace

Mesh MeshGenerators::sphere(int tess) {
    requireTessellation("sphere", tess, kSphereMinimumTessellation);
    MeshBuilder b("sphere");
    const int rings = tess, segments = 2 * tess;
    for (int i = 0; i <= rings; ++i) {
        const float theta = glm::pi<float>() * float(i) / float(rings);
        // Exact poles, so that all pole vertices coincide and the normal is exactly +-Y.
        const float sinT = (i == 0 || i == rings) ? 0.0f : std::sin(theta);
        const float cosT = i == 0 ? 1.0f : i == rings ? -1.0f : std::cos(theta);
        for (int j = 0; j <= segments; ++j) {
            const float phi = segmentAngle(j, segments);
            const glm::vec3 p(sinT * std::cos(phi), cosT, sinT * std::sin(phi));
            b.addVertex(p, p);
        }
    }
    addPolarGrid(b, 0, rings, segments, true, true);
    return b.finish();
}

Mesh MeshGenerators::box(glm::vec3 halfExtent, int tess) {
    requireTessellation("box", tess, kBoxMinimumTessellation);
    MeshBuilder b("box");
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {1.0f, -1.0f}) {
            glm::vec3 n(0.0f), u(0.0f);
            n[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            addBoxFace(b, n, u, halfExtent, tess);
        }
    }
    return b.finish();
}

Mesh MeshGenerators::cylinder(int tess) {
    requireTessellation("cylinder", tess, kCylinderMinimumTessellation);
    MeshBuilder b("cylinder");
    const int rows = tess, segments = 2 * tess;
    // Side: rows from the top (y = 1) down, so cross(d/dsegment, d/drow) points outward.
    for (int r = 0; r <= rows; ++r) {
        const float y = 1.0f - 2.0f * float(r) / float(rows);
        for (int j = 0; j <= segments; ++j) {
            const float phi = segmentAngle(j, segments);
            const glm::vec3 radial(std::cos(phi), 0.0f, std::sin(phi));
            b.addVertex(radial + glm::vec3(0, y, 0), radial);
        }
    }
    b.addGrid(0, rows, segments);
    // Caps: fans with their own vertices (flat normals).
    for (float y : {1.0f, -1.0f}) {
        const uint32_t centre = b.addVertex(glm::vec3(0, y, 0), glm::vec3(0, y, 0));
        const uint32_t ring = b.vertexCount();
        for (int j = 0; j < segments; ++j) {
            const float phi = segmentAngle(j, segments);
            b.addVertex(glm::vec3(std::cos(phi), y, std::sin(phi)), glm::vec3(0, y, 0));
        }
        for (int j = 0; j < segments; ++j) {
            const uint32_t a = ring + uint32_t(j), c = ring + uint32_t((j + 1) % segments);
            if (y > 0)
                b.addTriangle(centre, c, a);
            else
                b.addTriangle(centre, a, c);
        }
    }
    return b.finish();
}

Mesh MeshGenerators::plane(float size, int tess) {
    requireTessellation("plane", tess, kPlaneMinimumTessellation);
    MeshBuilder b("plane");
    const float h = 0.5f * size;
    // Rows run from +z to -z so the grid is counter-clockwise seen from +Y.
    for (int r = 0; r <= tess; ++r)
        for (int c = 0; c <= tess; ++c)
            b.addVertex(
                glm::vec3(-h + size * float(c) / float(tess), 0.0f, h - size * float(r) / float(tess)),
                glm::vec3(0, 1, 0));
    b.addGrid(0, tess, tess);
    return b.finish();
}

Mesh MeshGenerators::aircraft(int tess) {
    requireTessellation("aircraft", tess, kAircraftMinimumTessellation);
    MeshBuilder b("aircraft");
    // The flat parts are subdivided too (more slowly than the curved fuselage) so the knob raises
    // the vertex load of every part, as the thesis's vertex-bound measurements need.
    const int n = std::max(1, tess / 4);
    b.beginPart("fuselage");
    addFuselage(b, tess);
    b.beginPart("wings");
    addMirroredPlanform(b, 0.28f, -0.42f, -0.20f, -0.40f, 0.05f, 0.5f * kAircraftSpan, n);
    b.beginPart("stabilisers");
    addMirroredPlanform(b, -0.62f, -0.95f, -0.82f, -0.97f, 0.05f, 0.40f, n);
    b.beginPart("fin_left");
    addFin(b, -1.0f, n);
    b.beginPart("fin_right");
    addFin(b, 1.0f, n);
    return b.finish();
}

Mesh MeshGenerators::teapot(const std::string& bptPath, int tess) {
    requireTessellation("teapot", tess, kTeapotMinimumTessellation);
    const std::vector<BezierPatch> patches = BezierPatch::readBptFile(bptPath);
    MeshBuilder b("teapot");
    if (patches.size() != 32) {
        // Not the standard teapot: no known grouping, one part per file.
        b.beginPart("patches");
        for (const auto& patch : patches) addPatch(b, patch, tess);
        return b.finish();
    }
    for (const auto& group : kTeapotGroups) {
        b.beginPart(group.name);
        for (int p = group.first; p < group.first + group.count; ++p) addPatch(b, patches[size_t(p)], tess);
    }
    return b.finish();
}

Mesh MeshGenerators::lantern(float thickness, int tess) {
    requireTessellation("lantern", tess, kLanternMinimumTessellation);
    if (!(thickness > 0.0f && thickness < 1.0f))
        throw Error("lantern: thickness must be in (0, 1) (the outer radius is 1), got " +
                    std::to_string(thickness));
    const int rows = tess, segments = 2 * tess;
    const std::vector<int> hole = lanternHoles(rows, segments);
    auto removed = [&](int r, int c) {
        return hole[size_t(r) * size_t(segments) + size_t(c % segments)] >= 0;
    };
    const float innerRadius = 1.0f - thickness;
    MeshBuilder b("lantern");
    // The grid of sphere(tess), once at radius 1 (normals outward) and once at the inner radius
    // (normals towards the centre: out of the solid shell).
    std::vector<glm::vec3> grid;
    grid.reserve(size_t(rows + 1) * size_t(segments + 1));
    for (int i = 0; i <= rows; ++i) {
        const float theta = glm::pi<float>() * float(i) / float(rows);
        const float sinT = (i == 0 || i == rows) ? 0.0f : std::sin(theta);
        const float cosT = i == 0 ? 1.0f : i == rows ? -1.0f : std::cos(theta);
        for (int j = 0; j <= segments; ++j) {
            const float phi = segmentAngle(j, segments);
            grid.emplace_back(sinT * std::cos(phi), cosT, sinT * std::sin(phi));
        }
    }
    const uint32_t outer = b.vertexCount();
    for (const auto& p : grid) b.addVertex(p, p);
    const uint32_t inner = b.vertexCount();
    for (const auto& p : grid) b.addVertex(innerRadius * p, -p);
    const uint32_t stride = uint32_t(segments + 1);
    auto at = [&](int i, int j) { return uint32_t(i) * stride + uint32_t(j); };

    b.beginPart("shell");
    // The kept cells, triangulated as sphere() does (the pole rows as single triangles); the inner
    // sphere with the reverse winding.
    for (uint32_t base : {outer, inner}) {
        for (int i = 0; i < rows; ++i) {
            for (int j = 0; j < segments; ++j) {
                if (removed(i, j)) continue;
                const uint32_t a = base + at(i, j), bb = base + at(i, j + 1), d = base + at(i + 1, j),
                               e = base + at(i + 1, j + 1);
                if (base == outer) {
                    if (i != 0) b.addTriangle(a, bb, e);
                    if (i != rows - 1) b.addTriangle(a, e, d);
                } else {
                    if (i != 0) b.addTriangle(a, e, bb);
                    if (i != rows - 1) b.addTriangle(a, d, e);
                }
            }
        }
    }

    b.beginPart("holes");
    // A kept outer cell runs its border (i,j) -> (i,j+1) -> (i+1,j+1) -> (i+1,j); where it meets a
    // removed cell along u -> v, the wall quad v, u, u', v' (primes: inner sphere) uses v -> u on the
    // outer and u' -> v' on the inner sphere, the reverses of the kept cells' edges there, and
    // consecutive walls share their radial edges oppositely: closed. The quad is planar (u, v and the
    // centre span it), so one faceted normal fits it.
    auto wall = [&](int ui, int uj, int vi, int vj) {
        const glm::vec3 uo = grid[at(ui, uj)], vo = grid[at(vi, vj)];
        const glm::vec3 ui3 = innerRadius * uo, vi3 = innerRadius * vo;
        const glm::vec3 n = glm::cross(uo - vo, ui3 - vo);
        const uint32_t first = b.addVertex(vo, n);
        b.addVertex(uo, n);
        b.addVertex(ui3, n);
        b.addVertex(vi3, n);
        b.addQuad(first, first + 1, first + 2, first + 3);
    };
    // Edges along ring i between cell (i-1, j) above and (i, j) below (the pole rings have none).
    for (int i = 1; i < rows; ++i)
        for (int j = 0; j < segments; ++j) {
            const bool above = removed(i - 1, j), below = removed(i, j);
            if (above == below) continue;
            if (above)
                wall(i, j, i, j + 1); // kept below: its top edge runs (i,j) -> (i,j+1)
            else
                wall(i, j + 1, i, j); // kept above: its bottom edge runs (i,j+1) -> (i,j)
        }
    // Edges along meridian j between cell (i, j-1) on the left and (i, j) on the right.
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < segments; ++j) {
            const bool left = removed(i, j + segments - 1), right = removed(i, j);
            if (left == right) continue;
            if (left)
                wall(i + 1, j, i, j); // kept right: its left edge runs (i+1,j) -> (i,j)
            else
                wall(i, j, i + 1, j); // kept left: its right edge runs (i,j) -> (i+1,j)
        }
    Mesh mesh = b.finish();
    dropUnusedVertices(mesh);
    return mesh;
}

} // namespace sb
