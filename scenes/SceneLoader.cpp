#include "scenes/SceneLoader.h"
#include "core/Strings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/JsonReader.h"
#include "core/Paths.h"
#include "core/SplitMix64.h"
#include "core/Suggestion.h"
#include "scenes/BuiltinShadowPlanes.h"
#include "scenes/ClosedMesh.h"
#include "scenes/Math.h"
#include "scenes/MeshGeneratorTable.h"
#include "scenes/ModelLoader.h"
#include "scenes/Motion.h"
#include "scenes/SceneDocumentCost.h"

namespace sb {
namespace fs = std::filesystem;
namespace {

constexpr uint32_t kMaxInstances = 1000000;

/// Bytes per retained vertex (position + normal, 2 x vec3) and per-instance bookkeeping (model
/// matrix, colour, flags, uniforms) used by the memory estimate.
constexpr uint64_t kVertexBytes = 24;
constexpr uint64_t kInstanceBytes = 128;

/// Everything the parsing steps share.
struct Context {
    Scene scene;
    const SceneOptions& options;
    std::string source;
    /// A scene file's mesh name -> its meshes: one, or one per object of a multi-object model file.
    std::map<std::string, std::vector<uint32_t>> meshByName;
    std::optional<size_t> firstLayoutInstance;
    /// The entry of "instances" each instance placed before the layout comes from (3 for
    /// "/instances/3"; an index, not the pointer's text, which took more memory than the instance); the
    /// layout's instances, which follow them, all come from "/layout".
    std::vector<uint32_t> instanceEntries;
    /// What the scene file's text and its parsed document hold while the scene is built
    /// (SceneDocumentCost), part of every memory estimate.
    uint64_t documentBytes = 0;
    std::string replacedMesh; ///< the layout's mesh name when --model replaces it
    /// Mesh name -> instances that will draw it, read from the document before any mesh is built, so
    /// that a mesh's memory (its own and its instances' copies) is estimated before it is generated.
    std::map<std::string, uint64_t> references;
    /// The part of `references` that the entries of "instances" make (the layout's are checked with it).
    std::map<std::string, uint64_t> explicitReferences;
};

// ---- coordinate bounds ---------------------------------------------------------------------------

/// Each number of a scene is finite as a float (JsonReader), but sums and products of them (a scale
/// times a mesh's size, a position plus it) are not: every point that reaches a technique must lie
/// within ModelLoader::kMaxCoordinate, so that distances and their squares stay finite in float.
bool withinBound(const glm::vec3& p) {
    const double bound = ModelLoader::kMaxCoordinate;
    return std::abs(p.x) <= bound && std::abs(p.y) <= bound && std::abs(p.z) <= bound; // NaN fails too
}

bool withinBound(const Aabb& b) {
    return b.empty() || (withinBound(b.min) && withinBound(b.max));
}

std::string pointText(const glm::vec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", double(p.x), double(p.y), double(p.z));
    return text;
}

std::string beyondBound(const Aabb& b) {
    return "bounds " + pointText(b.min) + " to " + pointText(b.max) + " reach beyond +-1e18";
}

/// A point a camera or light sits at: within the bound (a view matrix normalises differences of them).
glm::vec3 boundedPoint(const JsonReader& r, const glm::vec3& p) {
    if (!withinBound(p)) r.error("the point " + pointText(p) + " lies beyond +-1e18");
    return p;
}

// ---- meshes -------------------------------------------------------------------------------------

int tessellationFor(const Context& ctx, const JsonReader& m, const MeshGeneratorEntry& generator) {
    int tess = m.has("tessellation") ? int(m["tessellation"].integer(1, 4096, "an integer in [1, 4096]"))
                                     : generator.defaultTessellation;
    if (!generator.followsTessellationOptions) return tess;
    if (ctx.options.tessellation) tess = *ctx.options.tessellation;
    if (ctx.options.tessellationFactor != 1.0f) {
        const long scaled = std::lround(double(tess) * double(ctx.options.tessellationFactor));
        tess = int(std::clamp<long>(scaled, generator.minimumTessellation, 4096));
    }
    return tess;
}

/// Bytes a mesh of `triangles` triangles costs, where a mesh of `sampleTriangles` took `sampleBytes`:
/// its buffers (vertices and indices scaled from the sample, which has more seam vertices per triangle
/// than a finer mesh: an overestimate) plus `uses` instance copies of 3 vertices per triangle.
double meshBytes(double triangles, double sampleTriangles, double sampleBytes, uint64_t uses) {
    return triangles * (sampleBytes / sampleTriangles) +
           double(uses) * triangles * 3.0 * double(kVertexBytes);
}

/// A tessellation past what the memory limit allows is refused before the mesh is built (a sphere at
/// 4096 took 8.8 s and 1.7 GB to be refused afterwards). Every generator tessellates grids and rows of
/// segments, so its triangle count is c2 t^2 + c1 t (a sphere: 4t^2 - 4t, a cylinder: 4t^2 + 4t); two
/// cheap sample meshes at t and 2t give c2 and c1 exactly, and the count at `tess` follows. Below
/// kCheapTessellation every generator's mesh is small, and nothing is estimated.
void checkTessellationMemory(const Context& ctx, const JsonReader& m, const MeshGeneratorEntry& generator,
                             int tess, uint64_t uses) {
    constexpr int kCheapTessellation = 64;
    if (tess <= kCheapTessellation) return;
    const int t1 = std::max(generator.minimumTessellation, 16), t2 = 2 * t1;
    const Mesh a = generator.build(m, t1), b = generator.build(m, t2);
    const double ta = double(std::max<size_t>(1, a.triangleCount()));
    const double tb = double(std::max<size_t>(1, b.triangleCount()));
    const double c2 = std::max(0.0, (tb / t2 - ta / t1) / double(t2 - t1)), c1 = tb / t2 - c2 * t2;
    const double triangles = std::max(tb, c2 * double(tess) * double(tess) + c1 * double(tess));
    const double sampleBytes = double(b.vertexCount() * kVertexBytes + b.indices.size() * 4);
    const double bytes = meshBytes(triangles, tb, sampleBytes, uses);
    if (bytes <= double(ctx.options.memoryLimitBytes)) return;
    const std::string what = "tessellation " + std::to_string(tess) + " (about " +
                             std::to_string(uint64_t(triangles)) + " triangles, " + std::to_string(uses) +
                             " instances): estimated memory " + byteSize(uint64_t(std::min(bytes, 1e19))) +
                             " exceeds the limit of " + byteSize(ctx.options.memoryLimitBytes) +
                             " (--max-memory-gib)";
    if (ctx.options.tessellation && generator.followsTessellationOptions)
        throw Error("--tess " + std::to_string(*ctx.options.tessellation) + ": mesh " +
                    JsonReader::excerpt(m["name"].string()) + ": " + what);
    m.error(what);
}

Mesh callGenerator(Context& ctx, const JsonReader& m, const std::string& name) {
    const MeshGeneratorEntry* generator = MeshGeneratorTable::find(name);
    if (!generator) m["generator"].fail("one of " + MeshGeneratorTable::names());
    // Each generator accepts its own parameters only, so a parameter given to the wrong generator
    // (a "radius" on a box) is reported instead of ignored.
    std::vector<std::string_view> keys = MeshGeneratorTable::commonKeys();
    keys.insert(keys.end(), generator->parameters.begin(), generator->parameters.end());
    m.requireObject(keys);
    const int tess = tessellationFor(ctx, m, *generator);
    const auto uses = ctx.references.find(m["name"].string());
    checkTessellationMemory(ctx, m, *generator, tess, uses == ctx.references.end() ? 0 : uses->second);
    return generator->build(m, tess);
}

/// Generator errors (a tessellation below the generator's minimum, an unreadable patch file) get the
/// mesh's JSON path in front.
Mesh generateMesh(Context& ctx, const JsonReader& m, const std::string& generator) {
    try {
        return callGenerator(ctx, m, generator);
    } catch (const Error& e) {
        const std::string message = e.what();
        if (message.rfind(ctx.source + ": ", 0) == 0) throw; // already located
        m.error(message);
    }
}

/// Estimated bytes: the scene file's text and document while the scene is built (`documentBytes`),
/// every mesh once (retained buffers), plus per instance the copy that immediate mode and display
/// lists make of its triangles (3 vertices of 24 B each) and its instance data.
uint64_t estimateMemory(const Scene& scene, const std::vector<uint32_t>& layoutMeshes, uint64_t layoutCount,
                        uint64_t documentBytes) {
    uint64_t bytes = documentBytes;
    for (const auto& mesh : scene.meshes)
        bytes += mesh.vertexCount() * kVertexBytes + mesh.indices.size() * 4;
    auto perInstance = [&](uint32_t mesh) {
        return uint64_t(scene.meshes[mesh].triangleCount()) * 3 * kVertexBytes + kInstanceBytes;
    };
    for (const auto& inst : scene.instances) bytes += perInstance(inst.mesh);
    for (uint32_t mesh : layoutMeshes) bytes += layoutCount * perInstance(mesh);
    return bytes;
}

/// A model file is refused before assimp reads it when its import (ModelLoader::estimateImport, from
/// its header or one streamed count) and the scene so far exceed the limit: a 10^7-triangle STL took
/// 8.9 GB to import under an estimate of 1.0 GiB made afterwards. Throws "model file '...': ...".
void checkModelMemory(const Context& ctx, const std::string& path) {
    const std::optional<ModelLoader::ImportEstimate> e = ModelLoader::estimateImport(path);
    if (!e) return;
    const uint64_t bytes = e->bytes + estimateMemory(ctx.scene, {}, 0, ctx.documentBytes);
    if (bytes <= ctx.options.memoryLimitBytes) return;
    throw Error("model file '" + path + "': " + std::to_string(e->triangles) + " triangles, " +
                std::to_string(e->corners) + " vertices before welding: estimated memory " + byteSize(bytes) +
                " to import exceeds the limit of " + byteSize(ctx.options.memoryLimitBytes) +
                " (--max-memory-gib)");
}

/// A "file" mesh's objects (scenes/ModelLoader.h), errors located at its "file" key (so they name the
/// scene file, the JSON path and the model file).
std::vector<Mesh> loadModelObjects(const Context& ctx, const JsonReader& m) {
    m.requireObject({"name", "file", "up", "shadow_planes", "proxies", "closed"});
    std::optional<ModelUp> up;
    if (m.has("up")) {
        up = parseModelUp(m["up"].string());
        if (!up) m["up"].fail("the file's up axis, one of " + modelUpChoices());
    }
    fs::path path = m["file"].string();
    if (path.is_relative()) path = fs::path(ctx.source).parent_path() / path;
    try {
        checkModelMemory(ctx, path.string());
        return ModelLoader::loadObjects(path.string(), up);
    } catch (const Error& e) {
        m["file"].error(e.what());
    }
}

// ---- shadow planes -------------------------------------------------------------------------------

/// The tolerance of ShadowPlane::validate for unit vectors.
constexpr float kUnitTolerance = 1e-3f;

/// A frame vector of a shadow plane: read as given (a user error is reported, not normalised away).
glm::vec3 planeVector(const JsonReader& r) {
    const glm::vec3 v = r.vec3();
    const float length = glm::length(v);
    if (!(std::abs(length - 1.0f) <= kUnitTolerance)) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", double(length));
        r.error("expected a unit vector (length 1 within 1e-3; shadow plane vectors are not normalised on "
                "load), got " +
                r.value().dump() + " of length " + text);
    }
    return v;
}

std::string partNames(const Mesh& mesh) {
    if (mesh.parts.empty()) return "the mesh has no named parts";
    return "parts: " + join(mesh.parts, ", ", [](const MeshPart& p) { return p.name; });
}

/// "texture": "auto" or an image file, made absolute relative to the scene file's directory.
std::string planeTexture(const Context& ctx, const JsonReader& r) {
    const std::string text = r.string();
    if (text == "auto") return text;
    if (text.empty()) r.fail("\"auto\" or an image file path");
    fs::path path = text;
    if (path.is_relative()) path = fs::path(ctx.source).parent_path() / path;
    path = fs::absolute(path).lexically_normal();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) r.error("texture file '" + path.string() + "' not found");
    return path.string();
}

ShadowPlane parseShadowPlane(const Context& ctx, const JsonReader& r, const Mesh& mesh) {
    r.requireObject({"name", "origin", "normal", "right", "up", "width", "height", "solid", "parts",
                     "texture", "texture_of", "section_only", "receivers"});
    ShadowPlane plane;
    plane.name = r["name"].string();
    if (plane.name.empty()) r["name"].fail("a non-empty name");
    plane.origin = r["origin"].vec3();
    plane.normal = planeVector(r["normal"]);
    plane.right = planeVector(r["right"]);
    plane.up = planeVector(r["up"]);
    plane.width = r["width"].positiveNumber();
    plane.height = r["height"].positiveNumber();
    if (r.has("solid")) plane.solid = r["solid"].boolean();
    if (r.has("section_only")) plane.sectionOnly = r["section_only"].boolean();
    for (const char* key : {"parts", "receivers"}) {
        if (!r.has(key)) continue;
        for (const auto& e : r[key].elements()) {
            const std::string part = e.string();
            const bool known = std::any_of(mesh.parts.begin(), mesh.parts.end(),
                                           [&](const MeshPart& p) { return p.name == part; });
            if (!known)
                e.error("unknown part \"" + part + "\" of mesh \"" + mesh.name + "\" (" + partNames(mesh) +
                        ")");
            (std::string(key) == "parts" ? plane.parts : plane.receivers).push_back(part);
        }
    }
    if (r.has("texture")) {
        plane.texture = planeTexture(ctx, r["texture"]);
        if (plane.solid && plane.texture != "auto")
            r["texture"].error(
                "a solid plane has no texture (every uv in [0, 1]^2 is shadow): remove \"texture\" "
                "or \"solid\"");
    }
    if (r.has("texture_of")) {
        plane.textureOf = r["texture_of"].string();
        if (plane.textureOf.empty()) r["texture_of"].fail("the name of another shadow plane of the mesh");
        if (plane.solid)
            r["texture_of"].error("a solid plane uses no texture: remove \"texture_of\" or \"solid\"");
        if (r.has("texture"))
            r["texture"].error("\"texture\" and \"texture_of\" both give the texture: keep one");
    }
    // Frame orthogonality and sizes (the non-unit cases were named at their keys above).
    plane.validate(ctx.source + ": " + r.path());
    return plane;
}

/// The "shadow_planes" of a mesh: names unique, texture_of naming another plane that owns a texture.
std::vector<ShadowPlane> parseShadowPlanes(const Context& ctx, const JsonReader& list, const Mesh& mesh) {
    const std::vector<JsonReader> entries = list.elements();
    std::vector<ShadowPlane> planes;
    for (const auto& e : entries) {
        ShadowPlane plane = parseShadowPlane(ctx, e, mesh);
        for (const auto& other : planes)
            if (other.name == plane.name)
                e["name"].error("duplicate shadow plane name \"" + plane.name + "\" in mesh \"" + mesh.name +
                                "\"");
        planes.push_back(std::move(plane));
    }
    for (size_t i = 0; i < planes.size(); ++i) {
        if (planes[i].textureOf.empty()) continue;
        const JsonReader r = entries[i]["texture_of"];
        const std::string& target = planes[i].textureOf;
        if (target == planes[i].name) r.error("a plane cannot use its own texture");
        const auto it = std::find_if(planes.begin(), planes.end(),
                                     [&](const ShadowPlane& p) { return p.name == target; });
        if (it == planes.end()) {
            const std::string known = join(planes, ", ", [](const ShadowPlane& p) { return p.name; });
            r.error("no shadow plane \"" + target + "\" in mesh \"" + mesh.name + "\" (planes: " + known +
                    ")");
        }
        if (!it->textureOf.empty())
            r.error("shadow plane \"" + target + "\" itself uses the texture of \"" + it->textureOf +
                    "\": name the plane that owns the texture");
        if (it->solid) r.error("shadow plane \"" + target + "\" is solid and has no texture to share");
    }
    return planes;
}

/// A colour [r, g, b] with every channel in [0, 1].
glm::vec3 colour(const JsonReader& r) {
    const glm::vec3 c = r.vec3();
    if (glm::any(glm::lessThan(c, glm::vec3(0.0f))) || glm::any(glm::greaterThan(c, glm::vec3(1.0f))))
        r.fail("a colour with channels in [0, 1]");
    return c;
}

/// A number of a proxy's frame as a float: finite and within float range (a 1e39 would become inf).
bool finiteFloat(const nlohmann::json& v) {
    return v.is_number() && std::abs(v.get<double>()) <= double(std::numeric_limits<float>::max());
}

/// A proxy's "position" or "rotation": [x, y, z], finite (an infinite frame poisons every distance).
glm::vec3 finiteVec3(const JsonReader& r) {
    // Checked before the conversion to float; vec3() reports the other mistakes (length, types).
    const nlohmann::json& v = r.value();
    if (v.is_array() && v.size() == 3)
        for (const auto& e : v)
            if (e.is_number() && !finiteFloat(e)) r.fail("an array of 3 finite numbers");
    return r.vec3();
}

/// A proxy's "size": one number for all three axes or [x, y, z], each finite and >= 0. Zero sizes are
/// allowed (degenerate, point- or sheet-like proxies are a hard case the technique must survive).
glm::vec3 proxySize(const JsonReader& r) {
    const nlohmann::json& v = r.value();
    std::vector<double> xyz;
    if (v.is_number()) {
        xyz.assign(3, v.get<double>());
    } else if (v.is_array() && v.size() == 3 &&
               std::all_of(v.begin(), v.end(), [](const auto& e) { return e.is_number(); })) {
        for (const auto& e : v) xyz.push_back(e.get<double>());
    } else {
        r.fail("a number or an array of 3 numbers");
    }
    for (size_t i = 0; i < 3; ++i)
        if (!(xyz[i] >= 0.0) || !finiteFloat(v.is_number() ? v : v[i]))
            r.fail("sizes >= 0 and finite (zero is allowed)");
    return glm::vec3(float(xyz[0]), float(xyz[1]), float(xyz[2]));
}

/// One entry of a mesh's "proxies" (object space): frame = T(position) * Rx * Ry * Rz * S(size), the
/// instances' Euler convention (composeTransform).
ShadowProxy parseProxy(const JsonReader& r) {
    r.requireObject({"shape", "position", "rotation", "size", "diffuse", "reflective"});
    ShadowProxy p;
    const JsonReader shapeKey = r["shape"];
    const std::optional<ShadowProxy::Shape> shape =
        ShadowProxy::shapeNames().parse(shapeKey.value().is_string() ? shapeKey.string() : "");
    if (!shape) shapeKey.fail("one of " + ShadowProxy::shapeNames().list());
    p.shape = *shape;
    if (!r.has("size"))
        r.error("missing required key \"size\" (radii / half extents: a number or [x, y, z])");
    const glm::vec3 size = proxySize(r["size"]);
    const glm::vec3 position = r.has("position") ? finiteVec3(r["position"]) : glm::vec3(0.0f);
    const glm::vec3 rotation = r.has("rotation") ? finiteVec3(r["rotation"]) : glm::vec3(0.0f);
    p.frame = composeTransform(position, rotation, 1.0f) * glm::scale(glm::mat4(1.0f), size);
    p.diffuseFromInstance = !r.has("diffuse");
    if (r.has("diffuse")) p.diffuse = colour(r["diffuse"]);
    if (r.has("reflective")) p.reflective = colour(r["reflective"]);
    return p;
}

/// Centre and radius of the sphere around the AABB centre that holds every vertex of `meshes`.
std::pair<glm::vec3, float> boundingSphere(const std::vector<Mesh>& meshes) {
    Aabb bounds;
    for (const Mesh& mesh : meshes) bounds.extend(mesh.computeBounds());
    const glm::vec3 centre = bounds.center();
    float radius = 0.0f;
    for (const Mesh& mesh : meshes)
        for (const auto& p : mesh.positions) radius = std::max(radius, glm::length(p - centre));
    return {centre, radius};
}

/// --model: the layout's mesh (`meshes`, before it is stored) becomes the model's objects, moved and
/// scaled together onto the replaced mesh's bounding sphere so the layout, cameras and light fits of
/// the scene still frame it. The meshes are named after the model file ("horse.3ds", or
/// "test1.3ds:Box01" per object), so every error about them names the file, not the replaced mesh.
void replaceWithModel(Context& ctx, std::vector<Mesh>& meshes) {
    checkModelMemory(ctx, ctx.options.modelPath);
    std::vector<Mesh> model = ModelLoader::loadObjects(ctx.options.modelPath);
    const auto [oldCentre, oldRadius] = boundingSphere(meshes);
    const auto [newCentre, newRadius] = boundingSphere(model);
    const float s = newRadius > 0.0f ? oldRadius / newRadius : 1.0f;
    const std::string file = fs::path(ctx.options.modelPath).filename().string();
    for (Mesh& object : model) {
        for (auto& p : object.positions) p = (p - newCentre) * s + oldCentre;
        object.name = model.size() == 1 ? file : file + ":" + object.name;
        // The replaced mesh's planes and declared proxies were for its geometry: a model file has no
        // planes, so the occluder technique chooses them for each object and the scene's lights
        // (scenes/ShadowPlaneChooser.h), and the proxy technique fits new proxies to each object.
        object.shadowPlanes.clear();
        object.shadowPlanesAuto = true;
        object.proxies.clear();
        object.proxiesDeclared = false;
    }
    meshes = std::move(model);
}

/// The meshes of one entry of "meshes": a generated mesh, or a model file's objects, each object its
/// own mesh "<name>:<object>" (one caster each for proxy and blob). A model whose entry declares
/// "shadow_planes" stays one mesh, its objects named parts, since a plane may name parts of several.
std::vector<Mesh> entryMeshes(Context& ctx, const JsonReader& m, const std::string& name,
                              const std::string& generator) {
    if (!generator.empty()) {
        Mesh mesh = generateMesh(ctx, m, generator);
        mesh.name = name;
        return {std::move(mesh)};
    }
    std::vector<Mesh> objects = loadModelObjects(ctx, m);
    if (objects.size() == 1 || m.has("shadow_planes")) return {ModelLoader::join(objects, name)};
    for (Mesh& object : objects) object.name = name + ":" + object.name;
    return objects;
}

void parseMesh(Context& ctx, const JsonReader& m) {
    if (!m.value().is_object()) m.fail("an object");
    const std::string name = m["name"].string();
    if (ctx.meshByName.count(name)) m["name"].error("duplicate mesh name \"" + name + "\"");
    if (m.has("generator") == m.has("file")) m.error("expected exactly one of \"generator\" or \"file\"");
    std::string generator = m.has("generator") ? m["generator"].string() : "";
    std::vector<Mesh> meshes = entryMeshes(ctx, m, name, generator);
    Mesh& mesh = meshes.front();
    // Planes live in the object space of the final mesh (after tessellation options and scaling).
    // Declared planes replace the built-in ones ([] means none); model files only get declared ones.
    if (m.has("shadow_planes")) {
        mesh.shadowPlanes = parseShadowPlanes(ctx, m["shadow_planes"], mesh);
    } else if (!generator.empty()) {
        try {
            mesh.shadowPlanes = BuiltinShadowPlanes::forGenerator(generator, mesh);
        } catch (const Error& e) {
            m["generator"].error(e.what());
        }
    }
    // No planes given or built in: the occluder technique chooses them (scenes/ShadowPlaneChooser.h).
    if (!m.has("shadow_planes") && mesh.shadowPlanes.empty())
        for (Mesh& object : meshes) object.shadowPlanesAuto = true;
    // Proxies (the `proxy` technique) in the mesh's object space; [] means none, no key: fitted. A
    // model's objects share one object space: the first holds the declared ones, the others none.
    if (m.has("proxies")) {
        for (Mesh& object : meshes) object.proxiesDeclared = true;
        for (const auto& e : m["proxies"].elements()) mesh.proxies.push_back(parseProxy(e));
    }
    if (name == ctx.replacedMesh) replaceWithModel(ctx, meshes);
    // Whether back faces may ever be culled (scenes/BackFaceCulling.h): computed from the final
    // geometry, or asserted by the file ("closed": true for a mesh whose back faces are never seen,
    // as a demo assumes of an open model; false to keep both faces of a closed one).
    const std::optional<bool> closed =
        m.has("closed") ? std::optional<bool>(m["closed"].boolean()) : std::nullopt;
    for (Mesh& object : meshes) {
        object.closed = closed ? *closed : isClosedMesh(object);
        object.closedDeclared = closed.has_value();
    }
    for (const Mesh& object : meshes)
        if (const Aabb b = object.computeBounds(); !withinBound(b))
            m.error("mesh " + JsonReader::excerpt(object.name) + ": " + beyondBound(b) + " in object space");
    std::vector<uint32_t>& indices = ctx.meshByName[name];
    for (Mesh& object : meshes) {
        indices.push_back(uint32_t(ctx.scene.meshes.size()));
        ctx.scene.meshes.push_back(std::move(object));
    }
}

/// The meshes a scene file's mesh name stands for (several for a multi-object model file).
const std::vector<uint32_t>& meshReference(const Context& ctx, const JsonReader& r) {
    const std::string name = r.string();
    const auto it = ctx.meshByName.find(name);
    if (it != ctx.meshByName.end()) return it->second;
    std::string known = join(ctx.meshByName, ", ", [](const auto& e) { return e.first; });
    r.error("unknown mesh \"" + name + "\" (meshes: " + known + ")");
}

// ---- instances and layout -------------------------------------------------------------------------

/// One instance per mesh of `meshes` (the objects of a model file), all with `inst`'s transform.
/// `entry` is the instance's index in "instances" (checkWorldBounds names it); layout instances pass
/// none.
void pushObjects(Context& ctx, Instance inst, const std::vector<uint32_t>& meshes,
                 std::optional<uint32_t> entry = std::nullopt) {
    for (uint32_t k = 0; k < meshes.size(); ++k) {
        inst.mesh = meshes[k];
        inst.object = k;
        ctx.scene.instances.push_back(inst);
        if (entry) ctx.instanceEntries.push_back(*entry);
    }
}

void parseInstanceFlags(Instance& inst, const JsonReader& r) {
    if (r.has("color")) inst.color = r["color"].vec3();
    if (r.has("casts_shadow")) inst.castsShadow = r["casts_shadow"].boolean();
    if (r.has("receives_shadow")) inst.receivesShadow = r["receives_shadow"].boolean();
}

void parseInstance(Context& ctx, const JsonReader& r, uint32_t entry) {
    r.requireObject({"mesh", "position", "rotation", "scale", "color", "casts_shadow", "receives_shadow"});
    Instance inst;
    const std::vector<uint32_t> meshes = meshReference(ctx, r["mesh"]);
    if (r.has("position")) inst.position = r["position"].vec3();
    if (r.has("rotation")) inst.rotationDeg = r["rotation"].vec3();
    if (r.has("scale")) inst.scale = r["scale"].positiveNumber();
    parseInstanceFlags(inst, r);
    pushObjects(ctx, inst, meshes, entry);
}

/// Before any explicit instance exists: the meshes, the document and every entry of "instances" at
/// what it will cost (Context::references, counted from the document), so that a long instances
/// array of a heavy mesh is refused before its instances are made.
void checkExplicitInstancesMemory(const Context& ctx, const JsonReader& root) {
    if (!root.has("instances")) return;
    uint64_t bytes = estimateMemory(ctx.scene, {}, 0, ctx.documentBytes), entries = 0;
    for (const auto& [name, count] : ctx.explicitReferences) {
        const auto meshes = ctx.meshByName.find(name);
        if (meshes == ctx.meshByName.end()) continue; // an unknown mesh: parseInstance reports it
        for (uint32_t mesh : meshes->second)
            bytes += count * (uint64_t(ctx.scene.meshes[mesh].triangleCount()) * 3 * kVertexBytes +
                              kInstanceBytes + sizeof(Instance));
    }
    if (root["instances"].value().is_array()) entries = root["instances"].value().size();
    if (bytes <= ctx.options.memoryLimitBytes) return;
    root["instances"].error(std::to_string(entries) + " instances: estimated memory " + byteSize(bytes) +
                            " exceeds the limit of " + byteSize(ctx.options.memoryLimitBytes) +
                            " (--max-memory-gib)");
}

/// Room for every instance the document asks for, made once (growing the vector doubled it).
void reserveInstances(Context& ctx, const JsonReader& root) {
    uint64_t count = 0;
    for (const auto& [name, uses] : ctx.references)
        if (const auto meshes = ctx.meshByName.find(name); meshes != ctx.meshByName.end())
            count += uses * meshes->second.size();
    ctx.scene.instances.reserve(size_t(count));
    if (root.has("instances") && root["instances"].value().is_array())
        ctx.instanceEntries.reserve(root["instances"].value().size());
}

/// The instance count of the layout: --instances wins over the file; both are bounded. The file's
/// value is validated even when overridden, so a broken scene file never passes unnoticed.
uint32_t layoutCount(const Context& ctx, const JsonReader& layout) {
    const JsonReader count = layout["count"];
    const int64_t n = count.integer(1, INT64_MAX, "a positive integer");
    if (n > int64_t(kMaxInstances))
        count.error(std::to_string(n) + " instances: more than the maximum of " +
                    std::to_string(kMaxInstances));
    if (ctx.options.instances) {
        const uint32_t o = *ctx.options.instances;
        if (o == 0) throw Error("--instances must be at least 1");
        if (o > kMaxInstances)
            throw Error("--instances " + std::to_string(o) + ": more than the maximum of " +
                        std::to_string(kMaxInstances));
        return o;
    }
    return uint32_t(n);
}

/// `layout` is null for a scene without one (then only the explicit instances count).
void checkMemory(const Context& ctx, const JsonReader& where, const JsonReader* layout,
                 const std::vector<uint32_t>& layoutMeshes, uint32_t count) {
    const uint64_t bytes = estimateMemory(ctx.scene, layoutMeshes, count, ctx.documentBytes);
    if (bytes <= ctx.options.memoryLimitBytes) return;
    const std::string what = "estimated memory " + byteSize(bytes) + " exceeds the limit of " +
                             byteSize(ctx.options.memoryLimitBytes);
    if (!layout) where.error(what);
    if (ctx.options.instances) throw Error("--instances " + std::to_string(count) + ": " + what);
    (*layout)["count"].error(std::to_string(count) + " instances: " + what);
}

/// Seeded uniform placement in the region box. Six numbers are drawn per instance whether or not
/// they are used, so the positions do not depend on yaw_only.
void placeLayout(Context& ctx, const JsonReader& layout, const std::vector<uint32_t>& meshes,
                 uint32_t count) {
    const auto region = layout["region"].elements();
    if (region.size() != 2) layout["region"].fail("[[min x, y, z], [max x, y, z]]");
    const glm::vec3 lo = region[0].vec3(), hi = region[1].vec3();
    if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)) layout["region"].fail("a box with min <= max");
    const uint64_t seed = ctx.options.seed ? *ctx.options.seed
                          : layout.has("seed")
                              ? uint64_t(layout["seed"].integer(0, INT64_MAX, "an integer >= 0"))
                              : 1;
    const float scale = (layout.has("scale") ? layout["scale"].positiveNumber() : 1.0f) * ctx.options.scale;
    const bool yawOnly = layout.has("yaw_only") ? layout["yaw_only"].boolean() : true;
    const double tilt =
        layout.has("max_tilt") ? layout["max_tilt"].numberIn(0, 90, "an angle in [0, 90]") : 10.0;
    Instance proto;
    proto.scale = scale;
    proto.fromLayout = true;
    parseInstanceFlags(proto, layout);
    SplitMix64 rng(seed);
    ctx.firstLayoutInstance = ctx.scene.instances.size();
    for (uint32_t i = 0; i < count; ++i) {
        Instance inst = proto;
        for (int a = 0; a < 3; ++a) inst.position[a] = float(rng.uniform(lo[a], hi[a]));
        const float yaw = float(rng.uniform(-180.0, 180.0));
        const float pitch = float(rng.uniform(-tilt, tilt)), roll = float(rng.uniform(-tilt, tilt));
        inst.rotationDeg = yawOnly ? glm::vec3(0.0f, yaw, 0.0f) : glm::vec3(pitch, yaw, roll);
        pushObjects(ctx, inst, meshes);
    }
}

void parseLayout(Context& ctx, const JsonReader& layout) {
    layout.requireObject({"mesh", "count", "seed", "region", "scale", "yaw_only", "max_tilt", "color",
                          "casts_shadow", "receives_shadow"});
    const std::vector<uint32_t> meshes = meshReference(ctx, layout["mesh"]);
    const uint32_t count = layoutCount(ctx, layout);
    checkMemory(ctx, layout, &layout, meshes, count);
    placeLayout(ctx, layout, meshes, count);
}

// ---- lights, cameras, effects ---------------------------------------------------------------------

LightingRate lightingRate(const JsonReader& r) {
    const auto rate = parseLightingRate(r.string());
    if (!rate) r.fail("one of " + lightingRateNames().list());
    return *rate;
}

LightType lightType(const JsonReader& r) {
    const auto type = parseLightType(r.string());
    if (!type) r.fail("one of " + lightTypeNames().list());
    return *type;
}

/// An emitter's extent (a rect's width or height, a disk's or sphere's radius): >= 0 and within
/// ModelLoader::kMaxCoordinate, the bound on every coordinate. A float-range size (3e38) turns the
/// samples on the emitter and every distance to them into inf, and the reference then judges a soft
/// shadow against nonsense.
float emitterExtent(const JsonReader& r) {
    const float extent = r.nonNegativeNumber();
    if (double(extent) > ModelLoader::kMaxCoordinate)
        r.fail("a size in [0, 1e18], the bound on coordinates (squared distances overflow float beyond it)");
    return extent;
}

/// "shape": point (default) | rect | disk | sphere; "size": [w, h] for rect, radius for disk/sphere;
/// directional lights take "shape": "disk" with "angular_radius_deg" (the sun's disk) instead.
void parseLightShapeKeys(const JsonReader& r, Light& light) {
    if (!r.has("shape")) {
        if (r.has("size") || r.has("angular_radius_deg"))
            r.error("\"size\"/\"angular_radius_deg\" need a \"shape\"");
        return;
    }
    const auto shape = parseLightShape(r["shape"].string());
    if (!shape) r["shape"].fail("one of " + lightShapeNames().list());
    light.shape = *shape;
    // Only the sun's disk has an angular size: on any other light the key would be ignored, and the
    // scene would not be what its file says.
    const bool sunDisk = light.type == LightType::Directional && light.shape == LightShape::Disk;
    if (r.has("angular_radius_deg") && !sunDisk)
        r["angular_radius_deg"].error(std::string("only a directional light with \"shape\": \"disk\" takes "
                                                  "\"angular_radius_deg\" (this is a ") +
                                      lightTypeName(light.type) + " light of shape \"" +
                                      lightShapeName(light.shape) +
                                      "\"; a point or spot light's emitter takes \"size\")");
    if (light.type == LightType::Directional) {
        if (light.shape != LightShape::Disk && light.shape != LightShape::Point)
            r["shape"].fail("\"disk\" (an angular disk) for a directional light");
        if (light.shape == LightShape::Disk)
            light.angularRadiusDeg = r["angular_radius_deg"].numberIn(0.0, 45.0, "an angle in [0, 45]");
        return;
    }
    if (light.shape == LightShape::Rect) {
        const JsonReader size = r["size"];
        std::vector<float> wh;
        for (const auto& e : size.elements()) wh.push_back(emitterExtent(e));
        if (wh.size() != 2) size.fail("[width, height]");
        light.size = glm::vec2(wh[0], wh[1]);
    } else if (light.shape != LightShape::Point) {
        light.size = glm::vec2(emitterExtent(r["size"]), 0.0f);
    }
}

void parseLight(Context& ctx, const JsonReader& r) {
    r.requireObject({"type", "direction", "position", "color", "intensity", "range", "spot_outer_deg",
                     "spot_inner_deg", "shape", "size", "angular_radius_deg", "casts_shadows"});
    Light light;
    if (r.has("type")) light.type = lightType(r["type"]);
    if (r.has("direction")) light.direction = r["direction"].unitDirection();
    if (r.has("position")) light.position = boundedPoint(r["position"], r["position"].vec3());
    if (r.has("color")) light.color = r["color"].vec3();
    if (r.has("intensity")) light.intensity = r["intensity"].nonNegativeNumber();
    if (r.has("range")) light.range = r["range"].nonNegativeNumber();
    if (r.has("spot_outer_deg"))
        light.spotOuterDeg = r["spot_outer_deg"].numberIn(0.1, 89.9, "an angle in [0.1, 89.9]");
    light.spotInnerDeg = std::min(light.spotInnerDeg, light.spotOuterDeg);
    if (r.has("spot_inner_deg"))
        light.spotInnerDeg =
            r["spot_inner_deg"].numberIn(0.0, light.spotOuterDeg, "an angle in [0, spot_outer_deg]");
    parseLightShapeKeys(r, light);
    if (r.has("casts_shadows")) light.castsShadows = r["casts_shadows"].boolean();
    ctx.scene.lights.push_back(light);
}

/// lookAt needs an up vector that is not parallel to the view direction (a camera looking straight
/// down with the default +Y up); -Z is then "up" on screen, i.e. north is at the top of the image.
glm::vec3 validUp(const CameraPreset& c) {
    const glm::vec3 dir = c.target - c.eye;
    if (glm::length(glm::cross(dir, c.up)) > 1e-4f * glm::length(dir) * glm::length(c.up)) return c.up;
    return std::abs(dir.z) > std::abs(dir.x) + std::abs(dir.y) ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, -1);
}

void followFirstInstance(const Context& ctx, CameraPreset& c, const JsonReader& r) {
    if (r["follow"].string() != "first_instance") r["follow"].fail("\"first_instance\"");
    if (!ctx.firstLayoutInstance) r["follow"].error("the scene has no layout whose first instance to follow");
    if (r.has("eye") || r.has("target"))
        r.error("\"follow\" computes eye and target; give \"offset\" instead");
    const Instance& inst = ctx.scene.instances[*ctx.firstLayoutInstance];
    // The offset is in units of the instance's scale, so --scale keeps the framing of the fill test.
    const glm::vec3 offset = r.has("offset") ? r["offset"].vec3() : glm::vec3(0.0f, 3.0f, 0.0f);
    c.target = inst.position;
    c.eye = inst.position + offset * inst.scale;
}

void parseCamera(Context& ctx, const JsonReader& r) {
    r.requireObject({"name", "eye", "target", "up", "fov", "near", "far", "follow", "offset"});
    CameraPreset c;
    c.name = r["name"].string();
    if (ctx.scene.findCamera(c.name)) r["name"].error("duplicate camera name \"" + c.name + "\"");
    if (r.has("follow"))
        followFirstInstance(ctx, c, r);
    else if (r.has("offset"))
        r["offset"].error("\"offset\" is only used with \"follow\"");
    if (r.has("eye")) c.eye = r["eye"].vec3();
    if (r.has("target")) c.target = r["target"].vec3();
    if (r.has("up")) c.up = r["up"].unitDirection();
    if (r.has("fov")) c.fovYDeg = r["fov"].numberIn(0.1, 179.0, "a field of view in [0.1, 179] degrees");
    if (r.has("near")) c.nearZ = r["near"].positiveNumber();
    if (r.has("far")) c.farZ = r["far"].positiveNumber();
    if (!(c.farZ > c.nearZ)) r.error("expected far > near");
    if (glm::length(c.target - c.eye) < 1e-6f) r.error("expected eye and target to differ");
    boundedPoint(r, c.eye);
    boundedPoint(r, c.target);
    c.up = validUp(c);
    ctx.scene.cameras.push_back(c);
}

EffectMask parseEffects(const JsonReader& r) {
    EffectMask mask = 0;
    for (const auto& e : r.elements()) {
        const auto effect = parseEffect(e.string());
        if (!effect) {
            e.fail("one of " + effectNames().list());
        }
        mask |= uint32_t(*effect);
    }
    return mask;
}

// ---- motion ---------------------------------------------------------------------------------------

uint32_t movedLight(const Context& ctx, const JsonReader& r, std::initializer_list<LightType> types,
                    const char* what) {
    const auto index =
        uint32_t(r.integer(0, int64_t(ctx.scene.lights.size()) - 1, "a light index of the scene"));
    const LightType type = ctx.scene.lights[index].type;
    if (std::find(types.begin(), types.end(), type) == types.end())
        r.error(std::string("light ") + std::to_string(index) + " is " + lightTypeName(type) + "; " + what);
    return index;
}

glm::vec2 numberPair(const JsonReader& r, double lo, double hi, const char* what) {
    std::vector<float> v;
    for (const auto& e : r.elements()) v.push_back(e.numberIn(lo, hi, what));
    if (v.size() != 2) r.fail(std::string("two numbers, ") + what);
    return {v[0], v[1]};
}

SunPath parseSun(const Context& ctx, const JsonReader& r) {
    r.requireObject({"light", "azimuth_deg", "elevation_deg"});
    SunPath sun;
    sun.light = movedLight(ctx, r["light"], {LightType::Directional}, "a sun path moves a directional light");
    if (r.has("azimuth_deg"))
        sun.azimuthDeg = numberPair(r["azimuth_deg"], -3600, 3600, "degrees in [-3600, 3600]");
    if (r.has("elevation_deg")) {
        sun.elevationDeg = numberPair(r["elevation_deg"], 0.0, 90.0, "degrees in [0, 90]");
        if (sun.elevationDeg.x > sun.elevationDeg.y)
            r["elevation_deg"].error("expected [low, high] with low <= high");
    }
    return sun;
}

OrbitPath parseOrbit(const Context& ctx, const JsonReader& r) {
    r.requireObject({"light", "centre", "radius", "turns", "target"});
    OrbitPath orbit;
    orbit.light = movedLight(ctx, r["light"], {LightType::Point, LightType::Spot},
                             "an orbit moves a point or spot light");
    orbit.centre = boundedPoint(r["centre"], r["centre"].vec3());
    orbit.radius = r["radius"].positiveNumber();
    boundedPoint(r["radius"], orbit.centre + glm::vec3(orbit.radius));
    if (r.has("turns")) orbit.turns = r["turns"].numberIn(-100.0, 100.0, "turns in [-100, 100]");
    orbit.target = r.has("target") ? boundedPoint(r["target"], r["target"].vec3())
                                   : glm::vec3(orbit.centre.x, 0.0f, orbit.centre.z);
    if (glm::length(orbit.target - orbit.centre) < 1e-6f && orbit.radius < 1e-6f)
        r.error("a spot on the orbit needs a target away from it");
    return orbit;
}

/// A key of the camera path: the name of one of the scene's cameras, or a camera of its own (the keys
/// of "cameras" but "name", "follow" and "offset").
CameraPreset cameraKey(const Context& ctx, const JsonReader& r) {
    if (r.value().is_string()) {
        const CameraPreset* c = ctx.scene.findCamera(r.string());
        if (!c) r.fail("the name of one of the scene's cameras or a camera object");
        return *c;
    }
    r.requireObject({"eye", "target", "up", "fov", "near", "far"});
    CameraPreset c;
    c.eye = boundedPoint(r["eye"], r["eye"].vec3());
    c.target = boundedPoint(r["target"], r["target"].vec3());
    if (r.has("up")) c.up = r["up"].unitDirection();
    if (r.has("fov")) c.fovYDeg = r["fov"].numberIn(0.1, 179.0, "a field of view in [0.1, 179] degrees");
    if (r.has("near")) c.nearZ = r["near"].positiveNumber();
    if (r.has("far")) c.farZ = r["far"].positiveNumber();
    if (!(c.farZ > c.nearZ)) r.error("expected far > near");
    if (glm::length(c.target - c.eye) < 1e-6f) r.error("expected eye and target to differ");
    c.up = validUp(c);
    return c;
}

CasterPath parseCasters(const Context& ctx, const JsonReader& r) {
    r.requireObject({"instances", "translate", "yaw_deg"});
    CasterPath path;
    const std::vector<Instance>& instances = ctx.scene.instances;
    const bool named = !r.has("instances") || r["instances"].value().is_string();
    if (named) {
        const std::string kind = r.has("instances") ? r["instances"].string() : "layout";
        if (kind != "layout" && kind != "casters")
            r["instances"].fail("\"layout\", \"casters\" or a list of instance indices");
        for (uint32_t i = 0; i < instances.size(); ++i)
            if (instances[i].castsShadow && (kind == "casters" || instances[i].fromLayout))
                path.instances.push_back(i);
    } else {
        for (const auto& e : r["instances"].elements(true)) {
            const auto i =
                uint32_t(e.integer(0, int64_t(instances.size()) - 1, "an instance index of the scene"));
            if (!instances[i].castsShadow)
                e.error("instance " + std::to_string(i) +
                        " casts no shadow: only casters move (receivers stay put)");
            path.instances.push_back(i);
        }
    }
    if (path.instances.empty()) r.error("no instance to move: the scene has no caster of that kind");
    if (r.has("translate")) path.translate = boundedPoint(r["translate"], r["translate"].vec3());
    if (r.has("yaw_deg"))
        path.yawDeg = r["yaw_deg"].numberIn(-36000.0, 36000.0, "degrees in [-36000, 36000]");
    // Every moved caster stays within the coordinate bound at both ends of the path.
    if (r.has("translate"))
        for (uint32_t i : path.instances)
            boundedPoint(r["translate"], instances[i].position + path.translate);
    return path;
}

/// A sun path's centre and, for a point or spot light (--light point on a scene with a sun), its
/// distance: known only once the lights have their final types.
void placeSun(Scene& scene) {
    auto motion = std::make_shared<Motion>(*scene.motion);
    Aabb bounds = scene.computeBounds(true);
    if (bounds.empty()) bounds = scene.computeBounds(false);
    motion->sun->centre = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
    const Light& light = scene.lights[motion->sun->light];
    motion->sun->distance = glm::length(light.position - motion->sun->centre);
    scene.motion = std::move(motion);
}

/// Every measured frame of the camera path has a view direction: the eye, interpolated between two
/// keys, must not reach the target (eye (0, 0, 10) to (0, 0, -10) around a target at the origin passes
/// through it halfway). A frame whose camera sits on its target draws nothing, and its time and
/// image would be taken for the technique's. Each key has been checked on its own (cameraKey); this
/// walks the frames a run measures, t = f / frames, with the tolerance cameraKey applies, scaled to
/// the points' magnitude so that float rounding of far points is not taken for a meeting.
void checkCameraPath(const JsonReader& r, const CameraPath& path, uint32_t frames) {
    Motion probe;
    probe.camera = path;
    for (uint32_t f = 0; f < frames; ++f) {
        const float t = float(f) / float(frames);
        const CameraPreset c = probe.cameraAt(t);
        const float scale = std::max({1.0f, glm::length(c.eye), glm::length(c.target)});
        if (glm::length(c.target - c.eye) >= 1e-6f * scale) continue;
        const size_t key = std::min(size_t(t * float(path.keys.size() - 1)), path.keys.size() - 2);
        char when[96];
        std::snprintf(when, sizeof when, "at frame %u of %u (path time %g, between keys %zu and %zu)", f,
                      frames, double(t), key, key + 1);
        r.error(std::string(when) + " the eye " + pointText(c.eye) +
                " reaches the target: the view direction is undefined (the path passes through its target)");
    }
}

void parseMotion(Context& ctx, const JsonReader& r) {
    r.requireObject({"frames", "sun", "orbit", "camera", "casters"});
    auto motion = std::make_shared<Motion>();
    if (r.has("frames")) motion->frames = uint32_t(r["frames"].integer(2, 1000000, "frames in [2, 1000000]"));
    if (r.has("sun")) motion->sun = parseSun(ctx, r["sun"]);
    if (r.has("orbit")) motion->orbit = parseOrbit(ctx, r["orbit"]);
    if (motion->sun && motion->orbit && motion->sun->light == motion->orbit->light)
        r["orbit"]["light"].error("light " + std::to_string(motion->orbit->light) +
                                  " already follows the sun path");
    if (r.has("camera")) {
        CameraPath path;
        for (const auto& k : r["camera"].elements()) path.keys.push_back(cameraKey(ctx, k));
        if (path.keys.size() < 2) r["camera"].fail("at least two key cameras");
        checkCameraPath(r["camera"], path, motion->frames);
        if (ctx.scene.findCamera(Motion::kCameraName))
            r["camera"].error("the scene already has a camera named \"path\", the camera path's name");
        motion->camera = std::move(path);
    }
    if (r.has("casters")) motion->casters = parseCasters(ctx, r["casters"]);
    if (!motion->sun && !motion->orbit && !motion->camera && !motion->casters)
        r.error("expected at least one of \"sun\", \"orbit\", \"camera\", \"casters\"");
    if (motion->camera) ctx.scene.cameras.push_back(motion->cameraAt(0.0f));
    ctx.scene.motion = std::move(motion);
}

// ---- options applied after parsing ----------------------------------------------------------------

/// --light TYPE: every light becomes TYPE. A directional light turned point/spot is placed on the
/// far side of its direction at twice the scene's radius (so it sees the whole scene) and a spot's
/// cone encloses the scene's bounding sphere; a point light turned directional/spot aims at the
/// centre. The casters' bounds define "the scene" (the ground plane would push the light far away).
void overrideLightType(Scene& scene, LightType type) {
    Aabb bounds = scene.computeBounds(true);
    if (bounds.empty()) bounds = scene.computeBounds(false);
    if (bounds.empty()) bounds.extend(glm::vec3(0.0f));
    const glm::vec3 centre = bounds.center();
    const float radius = std::max(0.5f * glm::length(bounds.extent()), 1e-3f);
    for (auto& light : scene.lights) {
        if (light.type == type) continue;
        if (light.type == LightType::Point) {
            const glm::vec3 toCentre = centre - light.position;
            if (glm::length(toCentre) > 1e-6f) light.direction = glm::normalize(toCentre);
        } else if (light.type == LightType::Directional) {
            light.position = centre - light.direction * (2.0f * radius);
        }
        if (type == LightType::Spot) {
            const float distance = std::max(glm::length(centre - light.position), radius * 1.01f);
            light.spotOuterDeg = std::min(glm::degrees(std::asin(radius / distance)) + 5.0f, 89.0f);
            light.spotInnerDeg = std::max(light.spotOuterDeg - 5.0f, 0.0f);
        }
        light.type = type;
    }
}

void checkOptionsApply(const Context& ctx, bool hasLayout) {
    if (hasLayout) return;
    if (ctx.options.instances)
        throw Error("--instances " + std::to_string(*ctx.options.instances) + ": scene '" + ctx.source +
                    "' has no layout to resize");
    if (!ctx.options.modelPath.empty())
        throw Error("--model " + ctx.options.modelPath + ": scene '" + ctx.source +
                    "' has no layout mesh to replace");
}

/// After updateTransforms: every instance's world-space bounds within the bound (each number was in
/// range, their products need not be), named by the instance's JSON pointer ("/layout" for the
/// layout's, whose scale and region are the numbers to blame). One bounds per mesh, one transform of
/// its corners per instance: linear in the instance count.
void checkWorldBounds(const Context& ctx) {
    std::vector<Aabb> meshBounds;
    for (const Mesh& mesh : ctx.scene.meshes) meshBounds.push_back(mesh.computeBounds());
    for (size_t i = 0; i < ctx.scene.instances.size(); ++i) {
        const Instance& inst = ctx.scene.instances[i];
        if (meshBounds[inst.mesh].empty()) continue;
        const Aabb world = transformBounds(meshBounds[inst.mesh], inst.model);
        if (withinBound(world)) continue;
        const std::string where = i < ctx.instanceEntries.size()
                                      ? "/instances/" + std::to_string(ctx.instanceEntries[i])
                                      : "/layout";
        char scale[48] = "";
        if (ctx.options.scale != 1.0f && i >= ctx.instanceEntries.size())
            std::snprintf(scale, sizeof scale, " (with --scale %g)", double(ctx.options.scale));
        throw Error(ctx.source + ": " + where + ": instance " + std::to_string(i) + " of mesh " +
                    JsonReader::excerpt(ctx.scene.meshes[inst.mesh].name) + std::string(scale) + ": world " +
                    beyondBound(world) + " (position + scale * the mesh's size)");
    }
}

/// Context::references from the document as written (a malformed entry counts nothing here; it is
/// reported when it is parsed). The layout counts with --instances or its "count".
void countReferences(Context& ctx, const JsonReader& root) {
    const nlohmann::json& doc = root.value();
    auto meshOf = [](const nlohmann::json& o) -> const nlohmann::json* {
        if (!o.is_object()) return nullptr;
        auto it = o.find("mesh");
        return it != o.end() && it->is_string() ? &*it : nullptr;
    };
    if (auto it = doc.find("instances"); it != doc.end() && it->is_array())
        for (const auto& i : *it)
            if (const nlohmann::json* mesh = meshOf(i)) {
                ++ctx.references[mesh->get<std::string>()];
                ++ctx.explicitReferences[mesh->get<std::string>()];
            }
    auto layout = doc.find("layout");
    if (layout == doc.end()) return;
    const nlohmann::json* mesh = meshOf(*layout);
    if (!mesh) return;
    uint64_t count = 1;
    if (ctx.options.instances)
        count = *ctx.options.instances;
    else if (auto c = layout->find("count"); c != layout->end() && c->is_number_integer() && *c > 0)
        count = std::min<uint64_t>(c->get<uint64_t>(), kMaxInstances);
    ctx.references[mesh->get<std::string>()] += std::min<uint64_t>(count, kMaxInstances);
}

void parseDocument(Context& ctx, const JsonReader& root) {
    root.requireObject({"name", "description", "meshes", "instances", "layout", "lights", "cameras",
                        "effects", "ambient", "lighting", "motion"});
    if (root.has("name")) ctx.scene.name = root["name"].string();
    if (root.has("description")) root["description"].string();
    checkOptionsApply(ctx, root.has("layout"));
    // --model replaces the layout's mesh as it is parsed, so explicit instances of it get the model too.
    if (!ctx.options.modelPath.empty()) ctx.replacedMesh = root["layout"]["mesh"].string();
    countReferences(ctx, root);
    for (const auto& m : root["meshes"].elements(true)) parseMesh(ctx, m);
    checkExplicitInstancesMemory(ctx, root);
    reserveInstances(ctx, root);
    if (root.has("instances")) {
        // One reader at a time: elements() would hold a reader (two strings) per entry at once.
        const JsonReader list = root["instances"];
        if (!list.value().is_array()) list.fail("an array");
        for (uint32_t i = 0; i < list.value().size(); ++i)
            parseInstance(ctx, JsonReader(list.value()[i], ctx.source, "/instances/" + std::to_string(i)), i);
    }
    if (root.has("layout"))
        parseLayout(ctx, root["layout"]);
    else
        checkMemory(ctx, root, nullptr, {}, 0);
    if (ctx.scene.instances.empty())
        root.error("expected at least one instance (\"instances\" or \"layout\")");
    // Before the cameras: a "follow" camera sits at its instance, so an instance out of bounds is
    // reported as the instance's fault, not the camera's.
    ctx.scene.updateTransforms();
    checkWorldBounds(ctx);
    if (root.has("lights"))
        for (const auto& l : root["lights"].elements(true)) parseLight(ctx, l);
    else
        ctx.scene.lights.push_back(Light{});
    if (root.has("cameras"))
        for (const auto& c : root["cameras"].elements()) parseCamera(ctx, c);
    if (root.has("effects")) ctx.scene.effects = parseEffects(root["effects"]);
    if (root.has("ambient")) ctx.scene.ambient = root["ambient"].vec3();
    if (root.has("lighting")) ctx.scene.lighting = lightingRate(root["lighting"]);
    if (root.has("motion")) parseMotion(ctx, root["motion"]);
}

/// What every explicit instance costs at least, known before its mesh is: its Instance, its entry
/// index, its instance data and the copies of one triangle (estimateMemory's terms for the smallest
/// mesh).
constexpr uint64_t kMinInstanceBytes =
    sizeof(Instance) + sizeof(uint32_t) + kInstanceBytes + 3 * kVertexBytes;

/// The text and the document it parses into, estimated (SceneDocumentCost) before the document is
/// made; with the least its instances cost, refused past the limit (a 10^7-element instances array
/// reached 8.8 GB before the limit was checked). Returns the text and document bytes.
uint64_t checkDocumentMemory(const std::string& text, const std::string& source,
                             const SceneOptions& options) {
    const SceneDocumentCost cost = SceneDocumentCost::measure(text);
    const uint64_t document = text.size() + cost.documentBytes;
    const uint64_t bytes = document + cost.instances * kMinInstanceBytes;
    if (bytes <= options.memoryLimitBytes) return document;
    throw Error(source + ": " + std::to_string(cost.values) + " JSON values, " +
                std::to_string(cost.instances) + " instances: estimated memory " + byteSize(bytes) +
                " to read them exceeds the limit of " + byteSize(options.memoryLimitBytes) +
                " (--max-memory-gib)");
}

/// A scene file's text, refused unread when the text alone exceeds the memory limit.
std::string readSceneText(const std::string& path, const SceneOptions& options) {
    std::error_code ec;
    const uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > options.memoryLimitBytes)
        throw Error("scene file '" + path + "': " + std::to_string(size) +
                    " bytes exceed the memory limit of " + byteSize(options.memoryLimitBytes) +
                    " (--max-memory-gib)");
    return Paths::readTextFile(path);
}

bool looksLikePath(const std::string& s) {
    return s.find('/') != std::string::npos || (s.size() > 5 && s.substr(s.size() - 5) == ".json");
}

} // namespace

Scene SceneLoader::parse(const std::string& jsonText, const std::string& sourceName,
                         const SceneOptions& options) {
    const uint64_t documentBytes = checkDocumentMemory(jsonText, sourceName, options);
    const nlohmann::json doc = JsonReader::parse(jsonText, sourceName);
    Context ctx{Scene{}, options, sourceName, {}, {}, {}};
    ctx.documentBytes = documentBytes;
    ctx.scene.name = fs::path(sourceName).stem().string();
    ctx.scene.sourcePath = sourceName;
    parseDocument(ctx, JsonReader(doc, sourceName));
    if (options.lightType) overrideLightType(ctx.scene, *options.lightType);
    if (options.lighting) ctx.scene.lighting = *options.lighting;
    if (ctx.scene.motion && ctx.scene.motion->sun) placeSun(ctx.scene);
    ctx.scene.cacheMeshBounds();
    return std::move(ctx.scene);
}

Scene SceneLoader::load(const std::string& nameOrPath, const SceneOptions& options) {
    std::error_code ec;
    std::string path = nameOrPath;
    if (!fs::is_regular_file(path, ec)) {
        // A relative path not found from here may be one of the source tree's (results/proxy/scenes/...),
        // so figure declarations and hard-case paths work from any working directory.
        const std::string inTree = fs::path(nameOrPath).is_relative() ? Paths::findResource(nameOrPath) : "";
        if (looksLikePath(nameOrPath) && inTree.empty())
            throw Error("scene file '" + nameOrPath + "': no such file");
        if (!inTree.empty()) return parse(readSceneText(inTree, options), inTree, options);
        path = Paths::findResource("scenes/data/" + nameOrPath + ".json");
        if (path.empty()) {
            const std::vector<std::string> builtin = listBuiltinScenes();
            throw Error("unknown scene '" + nameOrPath + "'" + Suggestion::didYouMean(nameOrPath, builtin) +
                        ": not a file, and not a built-in scene (" + join(builtin, ", ") + ")");
        }
    }
    return parse(readSceneText(path, options), path, options);
}

uint64_t SceneLoader::estimateBytes(const Scene& scene) {
    return estimateMemory(scene, {}, 0, 0); // the document is gone once the scene is built
}

std::vector<std::string> SceneLoader::listBuiltinScenes() {
    std::set<std::string> names;
    for (const auto& root : Paths::searchRoots()) {
        std::error_code ec;
        for (fs::directory_iterator it(fs::path(root) / "scenes/data", ec), end; !ec && it != end;
             it.increment(ec))
            if (it->path().extension() == ".json") names.insert(it->path().stem().string());
    }
    return {names.begin(), names.end()};
}

} // namespace sb
