#include "scenes/MeshGeneratorTable.h"

#include "core/Paths.h"
#include "core/Strings.h"
#include "scenes/MeshGenerators.h"

namespace sb {

namespace {

constexpr const char* kTeapotResource = "scenes/data/teapot.bpt";

/// Scales a generated mesh; normals follow the inverse scale (exact for the axis-aligned scales used).
void scaleMesh(Mesh& mesh, const glm::vec3& s) {
    for (auto& p : mesh.positions) p *= s;
    for (auto& n : mesh.normals) n = glm::normalize(n / s);
}

Mesh sphere(const JsonReader& m, int tess) {
    Mesh mesh = MeshGenerators::sphere(tess);
    if (m.has("radius")) scaleMesh(mesh, glm::vec3(m["radius"].positiveNumber()));
    return mesh;
}

Mesh box(const JsonReader& m, int tess) {
    return MeshGenerators::box(m.has("half_extent") ? m["half_extent"].positiveVec3() : glm::vec3(1.0f),
                               tess);
}

Mesh cylinder(const JsonReader& m, int tess) {
    Mesh mesh = MeshGenerators::cylinder(tess);
    const float radius = m.has("radius") ? m["radius"].positiveNumber() : 1.0f;
    const float height = m.has("height") ? m["height"].positiveNumber() : 2.0f;
    scaleMesh(mesh, glm::vec3(radius, 0.5f * height, radius));
    return mesh;
}

Mesh plane(const JsonReader& m, int tess) {
    return MeshGenerators::plane(m.has("size") ? m["size"].positiveNumber() : 100.0f, tess);
}

Mesh aircraft(const JsonReader&, int tess) {
    return MeshGenerators::aircraft(tess);
}

Mesh teapot(const JsonReader& m, int tess) {
    const std::string path = Paths::findResource(kTeapotResource);
    if (path.empty()) m["generator"].error(std::string("cannot find ") + kTeapotResource);
    return MeshGenerators::teapot(path, tess);
}

Mesh lantern(const JsonReader& m, int tess) {
    // "radius" (outer) and "thickness" (the shell's, radius - thickness is the inner radius) in scene
    // units; the generator builds outer radius 1, so the thickness is divided by the radius.
    const float radius = m.has("radius") ? m["radius"].positiveNumber() : 1.0f;
    const float thickness = m.has("thickness") ? m["thickness"].positiveNumber() : 0.08f;
    if (!(thickness < radius)) {
        const std::string r = m.has("radius") ? m["radius"].value().dump() : "1";
        if (m.has("thickness")) m["thickness"].fail("a thickness below the radius (" + r + ")");
        m["radius"].fail("a radius above the default thickness 0.08");
    }
    Mesh mesh = MeshGenerators::lantern(thickness / radius, tess);
    scaleMesh(mesh, glm::vec3(radius));
    return mesh;
}

} // namespace

const std::vector<std::string_view>& MeshGeneratorTable::commonKeys() {
    static const std::vector<std::string_view> kKeys = {"name",    "generator",    "shadow_planes",
                                                        "proxies", "tessellation", "closed"};
    return kKeys;
}

const std::vector<MeshGeneratorEntry>& MeshGeneratorTable::entries() {
    using G = MeshGenerators;
    // The one table of generators.
    static const std::vector<MeshGeneratorEntry> kEntries = {
        {"sphere", 16, G::kSphereMinimumTessellation, true, {"radius"}, sphere},
        {"box", 1, G::kBoxMinimumTessellation, true, {"half_extent"}, box},
        {"cylinder", 16, G::kCylinderMinimumTessellation, true, {"radius", "height"}, cylinder},
        {"plane", 16, G::kPlaneMinimumTessellation, false, {"size"}, plane},
        {"aircraft", 16, G::kAircraftMinimumTessellation, true, {}, aircraft},
        {"teapot", 8, G::kTeapotMinimumTessellation, true, {}, teapot},
        {"lantern", 16, G::kLanternMinimumTessellation, true, {"radius", "thickness"}, lantern},
    };
    return kEntries;
}

const MeshGeneratorEntry* MeshGeneratorTable::find(const std::string& name) {
    for (const MeshGeneratorEntry& e : entries())
        if (name == e.name) return &e;
    return nullptr;
}

std::string MeshGeneratorTable::names() {
    return join(entries(), ", ", [](const MeshGeneratorEntry& e) { return std::string(e.name); });
}

} // namespace sb
