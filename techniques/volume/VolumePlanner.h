#pragma once
// The API-independent half of `volume` (techniques/volume/VolumeGL.h), shared by the GL technique
// and its Vulkan form (VolumeVulkan.h): the properties and what they mean, where the casters stand,
// where each light's passes run (scissor rectangle, depth bounds), and per light the draw list of the
// marking pass with the frame's statistics: range culling, z-fail or z-pass per caster (occlusion
// pyramid), cap and side culling, CPU silhouettes streamed into one index array, or the vertex-shader
// extrusion mesh's caps and sides. Offsets and counts are plain indices (elements into the stream or the
// extrusion mesh's index buffer), for glDrawElements and vkCmdDrawIndexed alike.
#include <array>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Scene.h"
#include "techniques/PropertySet.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/volume/GpuVolumeFlags.h"
#include "techniques/volume/ShadowVolumeMesh.h"
#include "techniques/volume/VolumeGeometry.h"

namespace sb {

class VolumePlanner {
public:
    enum class Mode { ZFail, ZPass, Auto };
    enum class Far { Infinite, DepthClamp, Finite };
    /// Where silhouettes are found: on the CPU per caster (the chapter), in the vertex shader
    /// (McGuire-Hughes), or per face on the GPU in a geometry shader (triangles with adjacency), a
    /// compute shader (copies of the doubled buffer's vertices, drawn indirectly) or a mesh shader (Vulkan).
    enum class Extrusion { Cpu, Vertex, Geometry, Compute, Mesh };
    struct Settings {
        Mode mode = Mode::Auto;
        Far far = Far::Infinite;
        Extrusion extrusion = Extrusion::Cpu;
        /// The GPU per-face paths (geometry, compute, mesh): the same volume as the CPU's, built on the
        /// device, its triangles counted there.
        bool gpuSilhouettes() const {
            return extrusion == Extrusion::Geometry || extrusion == Extrusion::Compute ||
                   extrusion == Extrusion::Mesh;
        }
        bool vertexExtrusion = false, directional = true, rangeCull = true, frustumCull = true,
             scissor = true, finiteVolumes = false, boundedVolumes = true, depthBounds = false;
        OpenEdgePolicy policy = OpenEdgePolicy::Multiplicity;
    };
    struct Caster {
        uint32_t instance = 0, mesh = 0;
        glm::mat4 model{1.0f}, inverseModel{1.0f};
        Aabb bounds; ///< world space
        float scale = 1.0f;
    };
    /// One caster's draw for the current light.
    struct Draw {
        const Caster* caster = nullptr;
        glm::vec4 lightObject{0.0f};
        uint32_t first = 0;     ///< CPU path: first index in stream()
        uint32_t count = 0;     ///< CPU path: all of its volume
        uint32_t capCount = 0;  ///< vertex path: caps drawn (0 or all), from index 0 of the mesh
        uint32_t sideCount = 0; ///< vertex path: sides, after the mesh's caps
        float extrusion = 0;    ///< world-space extrusion length of a finite volume (range or bounded)
        bool zfail = true;
        /// GPU silhouette paths: what the device builds (VolumeRequest's caps, cap culling, sides and
        /// directional form, as GpuVolumeFlags bits); the device counts the triangles.
        uint32_t gpuFlags = 0;
    };
    struct FrameStats {
        double silhouetteEdges = 0, volumeTriangles = 0, rangeCulled = 0, capsCulled = 0, zpass = 0,
               zfail = 0, unshadowedLights = 0;
    };
    struct View {
        glm::mat4 viewProj{1.0f};
        std::array<Plane, 5> frustum{};
        std::array<glm::vec3, 4> nearRect{};
        int width = 0, height = 0;
    };
    /// Where light i's pass runs this frame: its scissor rectangle {x0, y0, x1, y1} in pixels, GL's
    /// window coordinates (y from the bottom; the viewport without scissoring, empty when the range is
    /// off screen) and its depth bounds.
    struct LightRegion {
        glm::ivec4 rect{0};
        bool depthBounds = false;
        glm::vec2 depth{0.0f, 1.0f};
        bool empty() const { return rect.z <= rect.x || rect.w <= rect.y; }
    };
    /// What the planner needs of a mesh's volume form: the welded mesh (null for a mesh no caster
    /// uses) and, for the vertex path, the extrusion mesh's index counts (caps first, then sides).
    struct MeshInfo {
        const ShadowVolumeMesh* mesh = nullptr;
        uint32_t capIndices = 0, sideIndices = 0;
    };

    /// The knobs (techniques/Property.h): what --list shows and -t volume:k=v sets.
    static std::vector<PropertyDesc> declareProperties();
    static Settings readSettings(const PropertySet& p);
    /// VolumeGL::infiniteFrom.
    static glm::mat4 infiniteFrom(const glm::mat4& proj);
    /// The chapter's L: the position for point and spot lights, the vector towards a directional one.
    static glm::vec4 worldLight(const Light& light);

    void setSettings(const Settings& s) { mSettings = s; }
    const Settings& settings() const { return mSettings; }

    /// The meshes' volume forms, by scene mesh index (set before checkClosed and collectDraws).
    void setMeshes(std::vector<MeshInfo> meshes) { mMeshes = std::move(meshes); }
    /// open_edges=refuse and an open caster mesh: sb::Error(BadInput) naming it.
    void checkClosed(const Scene& scene) const;
    /// A GPU silhouette path and an open caster mesh: sb::Error(Unsupported) naming it (those paths build
    /// the chapter's closed-mesh volume only; the CPU and vertex paths handle open meshes). Unsupported,
    /// not bad input: the form cannot draw this scene, as vsm cannot light a point light
    /// (techniques/PointLightRefusal.h), and the golden matrix lists such a cell with this reason.
    void checkGpuSilhouettes(const Scene& scene) const;
    /// Mesh bounds, whether the scene has non-receivers, and the casters (placeCasters).
    void setScene(const Scene& scene);
    /// The casters and the scene's bounds from where the scene's instances stand.
    void placeCasters(const Scene& scene);
    bool hasNonReceivers() const { return mHasNonReceivers; }

    /// The policy buildVolume() gets for `mesh`: Closed for closed meshes, else the property's.
    OpenEdgePolicy policyFor(const ShadowVolumeMesh& mesh) const;
    /// bounded_volumes applies to this light (directional, scene not empty).
    bool boundedFor(const Light& light) const;
    /// The light's volumes are finite (bounded, or finite_volumes with a range): the FINITE program.
    bool finiteFor(const Light& light) const;
    /// The projection every pass uses: the camera's with its far plane at infinity, or as it is.
    glm::mat4 projection(const glm::mat4& cameraProj) const;
    /// The frame's view of `proj` * `cameraView` on a `width` x `height` target.
    static View viewOf(const glm::mat4& proj, const glm::mat4& cameraView, int width, int height);
    /// Light `light`'s region; depth bounds only when asked for and `depthBoundsAvailable`.
    LightRegion regionOf(const Light& light, const glm::mat4& cameraView, const View& view,
                         const glm::mat4& proj, bool depthBoundsAvailable) const;
    /// Builds the draws of `light` (CPU silhouettes into stream()), z-fail first, and counts them (the
    /// GPU silhouette paths' volume triangles are counted on the device, not here).
    void collectDraws(const Light& light, const View& view, FrameStats& stats);
    const std::vector<Draw>& draws() const { return mDraws; }
    const std::vector<uint32_t>& stream() const { return mStream; }

    /// The technique's counters in GL's order; stencil_samples_passed only where `stencilSamples` is
    /// given, silhouette_edges only for the CPU path (the vertex path has no count to report). The GPU
    /// silhouette paths' volume_triangles is 0 here: the technique replaces it with the device's count.
    Counters counters(const FrameStats& stats, const SubmitStats& submitted,
                      std::optional<double> stencilSamples) const;
    /// `counters` with volume_triangles replaced by `triangles`, the device's count (GPU silhouettes).
    static Counters withDeviceTriangles(Counters counters, double triangles);

private:
    Settings mSettings;
    std::vector<MeshInfo> mMeshes;
    std::vector<Aabb> mMeshBounds; ///< per mesh, object space
    std::vector<Caster> mCasters;
    Aabb mSceneBounds; ///< world space, every instance: the receivers a bounded volume must reach past
    bool mHasNonReceivers = false;
    // Per-frame scratch, kept to avoid allocation in the measured frames.
    std::vector<Draw> mDraws;
    std::vector<uint32_t> mStream;
    VolumeIndices mVolume;
};

} // namespace sb
