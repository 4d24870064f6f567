#include "techniques/occluder/OccluderPlan.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <utility>

#include "core/Error.h"
#include "scenes/Math.h"
#include "scenes/Motion.h"
#include "scenes/ShadowPlaneChooser.h"
#include "scenes/ShadowWork.h"
#include "shading/ShaderLimits.h"
#include "techniques/occluder/Occluder.h"
#include "techniques/occluder/OccluderMeshCache.h"
#include "techniques/occluder/ReceiverSections.h"

namespace sb {

namespace {
/// Whitens the outermost texel ring. Lookups are clamped to [0, 1] (Appendix B), so every projection
/// that leaves the plane's rectangle reads a border texel: a black border would extend the occluder to
/// infinity along it (a silhouette or cross-section touching the rectangle's edge does that).
void clearBorder(std::vector<uint8_t>& texels, int size) {
    for (int i = 0; i < size; ++i) {
        texels[size_t(i)] = texels[size_t(size - 1) * size_t(size) + size_t(i)] = 255;
        texels[size_t(i) * size_t(size)] = texels[size_t(i) * size_t(size) + size_t(size - 1)] = 255;
    }
}

template <typename T>
void appendBytes(std::string& key, const T& value) {
    key.append(reinterpret_cast<const char*>(&value), sizeof(value));
}
void appendText(std::string& key, const std::string& text) {
    appendBytes(key, text.size());
    key += text;
}
/// Unit directions towards the scene's lights in the object space of (up to 8 of) the mesh's instances:
/// what the automatic choice scores its planes for. Near-duplicates (within ~2.5 degrees) are dropped.
std::vector<glm::vec3> lightsInObjectSpace(const Scene& scene, uint32_t mesh) {
    std::vector<const Instance*> instances;
    for (const Instance& inst : scene.instances)
        if (inst.mesh == mesh) instances.push_back(&inst);
    const size_t step = std::max<size_t>(1, (instances.size() + 7) / 8);
    const Aabb bounds = scene.meshBoundsOf(mesh);
    const glm::vec3 centre = bounds.center();
    std::vector<glm::vec3> out;
    for (size_t i = 0; i < instances.size(); i += step) {
        const glm::mat4 inverse = glm::inverse(instances[i]->model);
        for (const Light& l : scene.lights) {
            // A light inside the mesh's bounds has no one direction to it (the jack-o'-lantern's).
            const glm::vec3 local = glm::vec3(inverse * glm::vec4(l.position, 1.0f));
            if (l.type != LightType::Directional && glm::all(glm::greaterThanEqual(local, bounds.min)) &&
                glm::all(glm::lessThanEqual(local, bounds.max)))
                continue;
            const glm::vec3 world =
                l.type == LightType::Directional
                    ? -l.direction
                    : l.position - glm::vec3(instances[i]->model * glm::vec4(centre, 1.0f));
            const glm::vec3 d = glm::normalize(glm::vec3(inverse * glm::vec4(world, 0.0f)));
            if (!std::isfinite(d.x)) continue;
            if (std::none_of(out.begin(), out.end(),
                             [&](const glm::vec3& o) { return glm::dot(o, d) > 0.999f; }))
                out.push_back(d);
        }
    }
    return out;
}
/// 2D bounds of a box's corners in the basis (a, b) perpendicular to the light, and its extent along d.
struct LightSpaceBounds {
    glm::vec2 lo{1e30f}, hi{-1e30f};
    float nearest = 1e30f, farthest = -1e30f; ///< along d, the direction the light travels
};
LightSpaceBounds lightSpace(const Aabb& box, const glm::vec3& a, const glm::vec3& b, const glm::vec3& d) {
    LightSpaceBounds r;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 c((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                          (i & 4) ? box.max.z : box.min.z);
        const glm::vec2 q(glm::dot(a, c), glm::dot(b, c));
        r.lo = glm::min(r.lo, q);
        r.hi = glm::max(r.hi, q);
        r.nearest = std::min(r.nearest, glm::dot(d, c));
        r.farthest = std::max(r.farthest, glm::dot(d, c));
    }
    return r;
}
} // namespace

/// Bilinear resample of a single-channel image (loaded textures of another size than `resolution`).
std::vector<uint8_t> OccluderPlan::resample(const std::vector<uint8_t>& src, int w, int h, int size) {
    if (w == size && h == size) return src;
    std::vector<uint8_t> out(size_t(size) * size_t(size));
    auto at = [&](int x, int y) {
        return float(src[size_t(std::clamp(y, 0, h - 1)) * size_t(w) + size_t(std::clamp(x, 0, w - 1))]);
    };
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float fx = (float(x) + 0.5f) * float(w) / float(size) - 0.5f;
            const float fy = (float(y) + 0.5f) * float(h) / float(size) - 0.5f;
            const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
            const float tx = fx - float(x0), ty = fy - float(y0);
            const float v = glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), tx),
                                     glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), tx), ty);
            out[size_t(y) * size_t(size) + size_t(x)] = uint8_t(std::lround(std::clamp(v, 0.0f, 255.0f)));
        }
    return out;
}
/// Every input of an automatic bake but the mesh, as bytes: what OccluderTextures::bake reads of the
/// plane (and its name, in its messages), the options, and the renderer that rasterises it.
std::string OccluderPlan::bakeKey(const ShadowPlane& plane, const OccluderBakeOptions& options,
                                  const std::string& renderer) {
    std::string key;
    appendText(key, renderer);
    appendText(key, plane.name);
    for (const glm::vec3& v : {plane.origin, plane.normal, plane.right, plane.up}) appendBytes(key, v);
    for (float f : {plane.width, plane.height}) appendBytes(key, f);
    appendBytes(key, plane.parts.size());
    for (const std::string& part : plane.parts) appendText(key, part);
    for (int i : {options.resolution, options.dilate, int(options.crossSection), int(options.silhouette)})
        appendBytes(key, i);
    return key;
}

std::vector<uint8_t> OccluderPlan::finishBake(const std::vector<uint8_t>& texels, int w, int h,
                                              int resolution) {
    std::vector<uint8_t> out = resample(texels, w, h, resolution);
    clearBorder(out, resolution);
    return out;
}

void OccluderPlan::choosePlanes(const Scene& scene, const std::vector<bool>& drawn) {
    // Meshes without given planes (a --model file, a generated box, sphere or cylinder, a model file the
    // scene names without planes) get automatically chosen ones, for the scene's lights. Only meshes
    // with an instance that casts shadows: a plane shadows its own mesh, and a mesh that casts nothing
    // (the ground) must not shadow itself.
    mMeshPlanes.assign(scene.meshes.size(), {});
    mNoUsefulPlanes = 0;
    std::vector<bool> casts(scene.meshes.size(), false);
    for (const Instance& inst : scene.instances) casts[inst.mesh] = casts[inst.mesh] || inst.castsShadow;
    std::vector<std::string> lines;
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        if (!mesh.shadowPlanesAuto || !drawn[m] || !casts[m]) {
            mMeshPlanes[m] = mesh.shadowPlanes;
            continue;
        }
        // Lights inside the mesh's bounds (the jack-o'-lantern's) give no direction: without any, the
        // chooser would fall back to its 14 light-independent directions, whose planes shadow what the
        // light reaches (measured: worse than no shadow on the built-in jack_o_lantern scene).
        const std::vector<glm::vec3> towardLight = lightsInObjectSpace(scene, uint32_t(m));
        ShadowPlaneChoice choice;
        if (towardLight.empty() && !scene.lights.empty())
            choice.reason = "no light direction (every light inside its bounds)";
        else
            choice = OccluderMeshCache::choose(mesh, towardLight, kAutoPlanes);
        mMeshPlanes[m] = choice.planes;
        if (choice.planes.empty()) {
            ++mNoUsefulPlanes;
            lines.push_back("occluder: mesh '" + mesh.name +
                            "': no useful shadow plane, it is drawn unshadowed: " + choice.reason);
        }
    }
    mAnyPlane = reportUnshadowed(scene, drawn, lines);
}

bool OccluderPlan::reportUnshadowed(const Scene& scene, const std::vector<bool>& drawn,
                                    const std::vector<std::string>& meshLines) const {
    // With no plane on any drawn mesh the technique draws none's image: the row must not claim the
    // shadows (effects_delivered) and one line says so, as planar and blob do without a receiver.
    bool any = false;
    for (size_t m = 0; m < scene.meshes.size(); ++m) any = any || (drawn[m] && !mMeshPlanes[m].empty());
    if (any) {
        for (const std::string& line : meshLines) std::cerr << line << "\n";
        return true;
    }
    std::cerr << "occluder: scene '" << scene.name << "': no mesh has a shadow plane"
              << (meshLines.empty() ? ""
                                    : " (" + std::to_string(meshLines.size()) + " chosen for, none useful)")
              << ": nothing is shadowed\n";
    return false;
}

void OccluderPlan::collectPlanes(const Scene& scene, const PropertySet& properties) {
    const int limit = int(properties.getInt(Occluder::kPlanes));
    mPlanes.clear();
    mPlaneSource.clear();
    mMeshFirst.assign(scene.meshes.size(), 0);
    mMeshCount.assign(scene.meshes.size(), 0);
    std::vector<bool> drawn(scene.meshes.size(), false);
    for (const Instance& inst : scene.instances) drawn[inst.mesh] = true;
    choosePlanes(scene, drawn);
    mPlaneSlots = 1;
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const std::vector<ShadowPlane>& planes = mMeshPlanes[m];
        if (!drawn[m]) continue;
        if (planes.size() > size_t(Occluder::kMaxPlanes) && limit > Occluder::kMaxPlanes)
            throw Error("occluder: mesh '" + mesh.name + "' has " + std::to_string(planes.size()) +
                            " shadow planes; at most " + std::to_string(Occluder::kMaxPlanes) +
                            " are used per mesh",
                        ExitCode::Unsupported);
        const int count = std::min<int>(int(planes.size()), limit);
        mMeshFirst[m] = uint32_t(mPlanes.size());
        mMeshCount[m] = uint32_t(count);
        mPlaneSlots = std::max(mPlaneSlots, count);
        for (int k = 0; k < count; ++k) {
            const ShadowPlane& p = planes[size_t(k)];
            p.validate("occluder: mesh '" + mesh.name + "'");
            GpuPlane g;
            g.origin = glm::vec4(p.origin, -1.0f); // layer set in buildTextures
            g.normal = glm::vec4(p.normal, 0.0f);
            g.right = glm::vec4(p.right / p.width, 0.0f);
            g.up = glm::vec4(p.up / p.height, 0.0f);
            mPlanes.push_back(g);
            mPlaneSource.emplace_back(int(m), k);
        }
    }
}

EffectMask OccluderPlan::setScene(const Scene& scene, const PropertySet& properties) {
    mScene = &scene;
    mLights = std::clamp<int>(int(scene.lights.size()), 1, kMaxLights);
    const std::string& space = properties.getEnum(Occluder::kLightSpace);
    mPerInstance = space == "per_instance";
    mTextureMatrix = space == "texture_matrix";
    if (mTextureMatrix)
        for (const Light& l : scene.lights)
            if (l.type != LightType::Directional && l.castsShadows)
                throw Error(
                    "occluder: light_space=texture_matrix needs directional lights (for a point light the "
                    "projection onto a plane is not affine in the vertex); use per_instance",
                    ExitCode::Unsupported);
    collectPlanes(scene, properties);
    mInverseModel.clear();
    for (const Instance& inst : scene.instances) mInverseModel.push_back(glm::inverse(inst.model));
    mReceiveAll = properties.getEnum(Occluder::kReceivers) == "all";
    if (mReceiveAll) collectCandidates(scene);
    buildReceiverSections(scene);
    // Per instance: (first plane, plane count, first section slot, section slots) as raw bits, then one
    // vec4 per light.
    const size_t stride = 1 + size_t(mLights);
    mInstanceData.assign(scene.instances.size() * stride, glm::vec4(0.0f));
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const uint32_t mesh = scene.instances[i].mesh;
        glm::uvec4 range(mMeshFirst[mesh], mMeshCount[mesh], mMeshSections[mesh].x, mMeshSections[mesh].y);
        std::memcpy(&mInstanceData[i * stride], &range, sizeof(range));
    }
    if (mTextureMatrix)
        mMatrices.assign(scene.instances.size() * size_t(mLights * mPlaneSlots) * 3, glm::vec4(0.0f));
    EffectMask effects = Occluder::declaration().effects;
    if (!mAnyPlane) effects &= ~(Effect::HardShadows | Effect::SelfShadowing);
    return effects;
}

void OccluderPlan::buildReceiverSections(const Scene& scene) {
    mSectionTable.clear();
    mMeshSections.assign(scene.meshes.size(), glm::uvec2(0));
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const std::vector<ShadowPlane> used(mMeshPlanes[m].begin(), mMeshPlanes[m].begin() + mMeshCount[m]);
        if (!ReceiverSections::needed(used)) continue;
        const std::vector<glm::uvec4> table = ReceiverSections::build(scene.meshes[m], used);
        mMeshSections[m] = glm::uvec2(uint32_t(mSectionTable.size()), uint32_t(table.size()));
        mSectionTable.insert(mSectionTable.end(), table.begin(), table.end());
    }
}

void OccluderPlan::collectCandidates(const Scene& scene) {
    // receivers=all: for every receiver instance, the other instances whose planes may shadow it. For
    // directional lights a caster can only shadow a receiver whose bounds its own bounds overlap seen
    // along the light, and only if some of the caster lies before some of the receiver along it; point
    // and spot lights keep every pair (their shadows diverge; conservative). Instance planes are in the
    // world list in instance order, so a candidate is an instance (its planes are contiguous).
    const size_t n = scene.instances.size();
    std::vector<Aabb> bounds(n);
    for (size_t i = 0; i < n; ++i) {
        const Instance& inst = scene.instances[i];
        for (const glm::vec3& p : scene.meshes[inst.mesh].positions)
            bounds[i].extend(glm::vec3(inst.model * glm::vec4(p, 1.0f)));
    }
    bool directional = !scene.lights.empty();
    for (const Light& l : scene.lights) directional = directional && l.type == LightType::Directional;
    mCandidates.clear();
    mCandidateRange.assign(n, glm::uvec2(0));
    std::vector<std::vector<LightSpaceBounds>> views;
    std::vector<glm::vec3> dirs;
    if (directional)
        for (const Light& l : scene.lights) {
            const glm::vec3 d = glm::normalize(l.direction);
            const glm::vec3 e1 = glm::normalize(glm::cross(anyPerpendicularUp(d), d)), e2 = glm::cross(d, e1);
            std::vector<LightSpaceBounds> v(n);
            for (size_t i = 0; i < n; ++i) v[i] = lightSpace(bounds[i], e1, e2, d);
            views.push_back(std::move(v));
        }
    for (size_t r = 0; r < n; ++r) {
        mCandidateRange[r].x = uint32_t(mCandidates.size());
        for (size_t c = 0; c < n; ++c) {
            if (c == r || mMeshCount[scene.instances[c].mesh] == 0) continue;
            bool may = !directional;
            for (const auto& v : views) {
                const LightSpaceBounds &rc = v[r], &cc = v[c];
                may = may || (cc.lo.x <= rc.hi.x && rc.lo.x <= cc.hi.x && cc.lo.y <= rc.hi.y &&
                              rc.lo.y <= cc.hi.y && cc.nearest <= rc.farthest);
            }
            if (may) mCandidates.push_back(uint32_t(c));
        }
        mCandidateRange[r].y = uint32_t(mCandidates.size()) - mCandidateRange[r].x;
    }
}

void OccluderPlan::worldPlanes(std::vector<GpuPlane>& world, std::vector<glm::uvec2>& table) {
    // Every instance's planes in world space (instances have uniform scale: M = T R s), in the units
    // of equations 6 and 8: u = (R right).(p - M o) / (s width).
    world.clear();
    mInstancePlaneFirst.assign(mScene->instances.size(), 0);
    for (size_t i = 0; i < mScene->instances.size(); ++i) {
        const Instance& inst = mScene->instances[i];
        mInstancePlaneFirst[i] = uint32_t(world.size());
        const glm::mat3 m(inst.model);
        const float scale = glm::length(m[0]);
        for (uint32_t j = 0; j < mMeshCount[inst.mesh]; ++j) {
            const GpuPlane& p = mPlanes[mMeshFirst[inst.mesh] + j];
            GpuPlane w;
            w.origin = glm::vec4(glm::vec3(inst.model * glm::vec4(glm::vec3(p.origin), 1.0f)), p.origin.w);
            w.normal = glm::vec4(glm::normalize(m * glm::vec3(p.normal)), 0.0f);
            w.right = glm::vec4(m * glm::vec3(p.right) / (scale * scale), 0.0f);
            w.up = glm::vec4(m * glm::vec3(p.up) / (scale * scale), 0.0f);
            world.push_back(w);
        }
    }
    // Candidates as (first world plane, plane count) pairs after the per-instance ranges.
    table = mCandidateRange;
    for (uint32_t c : mCandidates)
        table.emplace_back(mInstancePlaneFirst[c], mMeshCount[mScene->instances[c].mesh]);
}

std::vector<OccluderPlan::Texels> OccluderPlan::layers(const Scene& scene, const PropertySet& properties,
                                                       const Baker& bake, const Loader& load) {
    const int resolution = int(properties.getInt(Occluder::kResolution));
    OccluderBakeOptions options;
    options.resolution = resolution;
    options.dilate = int(properties.getInt(Occluder::kDilate));
    // One layer per texture owner: a plane with its own texture, or the plane another names in
    // texture_of (the thesis's two tail fins share one), whether or not the owner itself is used.
    std::map<std::pair<int, int>, int> layerOf;
    std::vector<Texels> layers;
    for (size_t e = 0; e < mPlanes.size(); ++e) {
        const auto [m, k] = std::pair<int, int>(mPlaneSource[e].x, mPlaneSource[e].y);
        const Mesh& mesh = scene.meshes[size_t(m)];
        const std::vector<ShadowPlane>& planes = mMeshPlanes[size_t(m)];
        const ShadowPlane& plane = planes[size_t(k)];
        if (plane.solid) continue; // layer -1: no texture
        int owner = k;
        if (!plane.textureOf.empty()) {
            auto it = std::find_if(planes.begin(), planes.end(),
                                   [&](const ShadowPlane& p) { return p.name == plane.textureOf; });
            if (it == planes.end())
                throw Error("occluder: mesh '" + mesh.name + "': plane '" + plane.name +
                            "' takes the texture of '" + plane.textureOf + "', which the mesh does not have");
            owner = int(it - planes.begin());
        }
        auto [it, added] = layerOf.emplace(std::make_pair(m, owner), int(layers.size()));
        if (added) {
            const ShadowPlane& source = planes[size_t(owner)];
            OccluderBakeOptions planeOptions = options;
            planeOptions.silhouette = !source.sectionOnly;
            layers.push_back(source.texture == "auto" ? bake(mesh, source, planeOptions)
                                                      : load(source.texture, resolution));
            // SB_DUMP_OCCLUDERS=DIR writes every texture as DIR/<mesh>_<plane>.png (to inspect bakes).
            if (const char* dir = std::getenv("SB_DUMP_OCCLUDERS"))
                OccluderTexels::write(std::string(dir) + "/" + mesh.name + "_" + source.name + ".png",
                                      *layers.back(), resolution, resolution);
        }
        mPlanes[e].origin.w = float(it->second);
    }
    return layers;
}

bool OccluderPlan::sceneChanged(const Scene& scene, uint32_t changes) {
    if (changes & kCastersMoved)
        for (size_t i = 0; i < scene.instances.size(); ++i)
            mInverseModel[i] = glm::inverse(scene.instances[i].model);
    if (mReceiveAll && (changes & (kCastersMoved | kLightsMoved))) {
        collectCandidates(scene);
        return true;
    }
    return false;
}

void OccluderPlan::checkVertexComponents(int available, const std::string& renderer) const {
    const int needed = vertexComponents();
    if (needed > available)
        throw Error("occluder: " + std::to_string(mLights) + " lights x " + std::to_string(mPlaneSlots) +
                        " planes need " + std::to_string(needed) + " vertex output components, '" + renderer +
                        "' has " + std::to_string(available) +
                        "; use fewer planes (-t occluder:planes=N) or lights",
                    ExitCode::Unsupported);
}

Defines OccluderPlan::defines(Defines d) const {
    if (!mSectionTable.empty()) d["RECEIVER_SECTIONS"] = "";
    d["LIGHT_COUNT"] = std::to_string(mLights);
    d["PLANE_COUNT"] = std::to_string(mPlaneSlots);
    if (mPerInstance) d["LIGHT_PER_INSTANCE"] = "";
    if (mTextureMatrix) d["TEXTURE_MATRIX"] = "";
    if (mReceiveAll) {
        d["RECEIVE_OTHERS"] = "";
        d["INSTANCE_COUNT"] = std::to_string(std::max<size_t>(1, mScene->instances.size()));
    }
    return d;
}

void OccluderPlan::updateLightSpace() {
    const size_t stride = 1 + size_t(mLights);
    {
        // The thesis's proposed optimisation: the light in each instance's model space, once per
        // instance and frame on the CPU, instead of once per vertex in the shader.
        for (size_t i = 0; i < mScene->instances.size(); ++i)
            for (int l = 0; l < mLights && l < int(mScene->lights.size()); ++l) {
                const Light& light = mScene->lights[size_t(l)];
                if (!light.castsShadows) continue; // never read (occluder/scene.vert)
                glm::vec4& out = mInstanceData[i * stride + 1 + size_t(l)];
                if (light.type == LightType::Directional)
                    out = glm::vec4(
                        glm::normalize(glm::vec3(mInverseModel[i] * glm::vec4(-light.direction, 0.0f))),
                        0.0f);
                else
                    out = glm::vec4(glm::vec3(mInverseModel[i] * glm::vec4(light.position, 1.0f)), 1.0f);
            }
    }
}

void OccluderPlan::updateMatrices() {
    // Per instance, light and used plane: equations 6 and 8 as one affine map (ShadowPlane::
    // textureMatrix), from the light in the instance's model space. The CPU work the vertex stage saves.
    const size_t slots = size_t(mPlaneSlots);
    for (size_t i = 0; i < mScene->instances.size(); ++i) {
        const uint32_t mesh = mScene->instances[i].mesh;
        for (int l = 0; l < mLights && l < int(mScene->lights.size()); ++l) {
            if (!mScene->lights[size_t(l)].castsShadows) continue; // never read (occluder/scene.vert)
            const glm::vec3 toward = glm::normalize(
                glm::vec3(mInverseModel[i] * glm::vec4(-mScene->lights[size_t(l)].direction, 0.0f)));
            for (uint32_t j = 0; j < mMeshCount[mesh]; ++j) {
                const glm::ivec2 src = mPlaneSource[mMeshFirst[mesh] + j];
                const auto rows = mMeshPlanes[size_t(src.x)][size_t(src.y)].textureMatrix(toward);
                const size_t base = ((i * size_t(mLights) + size_t(l)) * slots + j) * 3;
                std::copy(rows.begin(), rows.end(), mMatrices.begin() + std::ptrdiff_t(base));
            }
        }
    }
}

Counters OccluderPlan::counters(const Scene& scene, const SubmitStats& s, int resolution, int layers) const {
    double planeInstances = 0;
    for (const Instance& inst : scene.instances) planeInstances += mMeshCount[inst.mesh];
    return {{"draw_calls", double(s.drawCalls)},
            {"triangles", double(s.triangles)},
            {"shadow_planes", planeInstances},
            {"occluder_texels", double(resolution) * resolution * double(layers)},
            {"receiver_candidates", double(mCandidates.size())},
            {"no_useful_planes", double(mNoUsefulPlanes)},
            {"lights_unshadowed", double(ShadowWork::unshadowedLights(scene, size_t(mLights)))}};
}

} // namespace sb
