#pragma once
// What the GL and Vulkan forms of `occluder` share, API-neutral (techniques/occluder/OccluderGL.h says
// what the technique does): the shadow planes of every drawn mesh (given, or chosen for the scene's
// lights), their GPU records, which texture layer each plane reads and where its texels come from
// (a bake or an image file: layers()), the receiver sections' hash tables, the per-instance records,
// the light in each instance's space (per_instance) or the texture matrices (texture_matrix) per frame,
// receivers=all's caster candidates and world-space planes, the permutation and the counters. A form
// bakes the layers with its API, uploads what this holds and draws.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Scene.h"
#include "scenes/ShadowPlane.h"
#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/occluder/OccluderTexels.h"

namespace sb {

class OccluderPlan {
public:
    /// std430 mirror of OccluderPlane in shaders/occluder/scene.vert.
    struct GpuPlane {
        glm::vec4 origin; ///< w: texture layer, -1 for a solid occluder
        glm::vec4 normal;
        glm::vec4 right; ///< right / width
        glm::vec4 up;    ///< up / height
    };
    using Texels = std::shared_ptr<const std::vector<uint8_t>>;
    /// A form's bake of one automatic texture: texels at options.resolution, row 0 = v near 0.
    using Baker = std::function<Texels(const Mesh&, const ShadowPlane&, const OccluderBakeOptions&)>;
    /// A form's load of a texture file, resampled to `resolution`.
    using Loader = std::function<Texels(const std::string& path, int resolution)>;

    /// Most planes chosen automatically for a mesh without given ones (the cost is per plane).
    static constexpr int kAutoPlanes = 4;

    /// The planes, records, sections and (receivers=all) candidates; throws what OccluderGL documents.
    /// Returns the effects the row delivers (hard and self shadows left out when no drawn mesh has a
    /// plane, said on stderr).
    EffectMask setScene(const Scene& scene, const PropertySet& properties);
    /// Moving casters change the inverse transforms, and with receivers=all the candidates (which
    /// follow the lights too). True when worldPlanes() changed.
    bool sceneChanged(const Scene& scene, uint32_t changes);
    /// The layers every textured plane reads (one per texture owner: a plane with its own texture, or
    /// the plane another names in texture_of), from `bake` or `load`; sets each record's layer.
    std::vector<Texels> layers(const Scene& scene, const PropertySet& properties, const Baker& bake,
                               const Loader& load);
    /// Vertex output components the lit pass's vertex stage writes (checked against the device).
    int vertexComponents() const { return 4 * (mLights * mPlaneSlots + (mPlaneSlots + 3) / 4 + 3); }
    /// The refusal when `available` components are too few for vertexComponents() on `renderer`.
    void checkVertexComponents(int available, const std::string& renderer) const;
    /// LIGHT_COUNT, PLANE_COUNT and the switches of the permutation, added to `d`.
    Defines defines(Defines d) const;
    /// Per frame: the lights in each instance's space (per_instance) into instanceData().
    void updateLightSpace();
    /// Per frame: the texture matrices (texture_matrix) into matrices(), sized in setScene.
    void updateMatrices();
    /// receivers=all: every instance's planes in world space, and the candidate table (per receiver a
    /// (first, count) range, then per candidate its (first world plane, plane count)).
    void worldPlanes(std::vector<GpuPlane>& world, std::vector<glm::uvec2>& table);
    Counters counters(const Scene& scene, const SubmitStats& s, int resolution, int layers) const;

    bool perInstance() const { return mPerInstance; }
    bool textureMatrix() const { return mTextureMatrix; }
    bool receiveAll() const { return mReceiveAll; }
    const std::vector<GpuPlane>& planes() const { return mPlanes; }
    const std::vector<glm::vec4>& instanceData() const { return mInstanceData; }
    const std::vector<glm::vec4>& matrices() const { return mMatrices; }
    const std::vector<glm::uvec4>& sectionTable() const { return mSectionTable; }

    /// An automatic bake's texels finished: resampled to `resolution`, the outermost ring whitened
    /// (lookups are clamped, so a black border would extend the occluder to infinity).
    static std::vector<uint8_t> finishBake(const std::vector<uint8_t>& texels, int w, int h, int resolution);
    /// Bilinear resample of a single-channel image (loaded textures of another size).
    static std::vector<uint8_t> resample(const std::vector<uint8_t>& src, int w, int h, int size);
    /// Every input of an automatic bake but the mesh, as bytes (OccluderMeshCache's key).
    static std::string bakeKey(const ShadowPlane& plane, const OccluderBakeOptions& options,
                               const std::string& renderer);

private:
    void choosePlanes(const Scene& scene, const std::vector<bool>& drawn);
    bool reportUnshadowed(const Scene& scene, const std::vector<bool>& drawn,
                          const std::vector<std::string>& meshLines) const;
    void collectPlanes(const Scene& scene, const PropertySet& properties);
    void collectCandidates(const Scene& scene);
    void buildReceiverSections(const Scene& scene);

    const Scene* mScene = nullptr;
    int mLights = 1, mPlaneSlots = 1;
    bool mPerInstance = false, mTextureMatrix = false, mReceiveAll = false;
    // receivers=all: per receiver instance (first, count) into mCandidates (caster instances).
    std::vector<glm::uvec2> mCandidateRange;
    std::vector<uint32_t> mCandidates, mInstancePlaneFirst;
    /// Per mesh the planes it is drawn with: its own, or for a mesh without given planes (a --model file)
    /// those ShadowPlaneChooser picked for the scene's lights; mNoUsefulPlanes counts those left without.
    std::vector<std::vector<ShadowPlane>> mMeshPlanes;
    int mNoUsefulPlanes = 0;
    bool mAnyPlane = false;                       ///< some drawn mesh has a plane
    std::vector<GpuPlane> mPlanes;                ///< every mesh's used planes, contiguous per mesh
    std::vector<uint32_t> mMeshFirst, mMeshCount; ///< per mesh: range in mPlanes
    std::vector<glm::ivec2> mPlaneSource;         ///< per entry of mPlanes: mesh, plane index
    std::vector<glm::mat4> mInverseModel;         ///< per instance (the per_instance light space)
    std::vector<glm::vec4> mInstanceData;         ///< per instance: (first, count) then the lights
    std::vector<glm::vec4> mMatrices;             ///< texture_matrix: 3 rows per instance, light, plane
    /// Receiver sections (ReceiverSections.h): every mesh's hash table, contiguous, and per mesh its
    /// (first slot, slot count), count 0 where every part receives every plane.
    std::vector<glm::uvec4> mSectionTable;
    std::vector<glm::uvec2> mMeshSections;
};

} // namespace sb
