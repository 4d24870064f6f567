#pragma once
// The scene's triangles in Intel Embree 3 (Debian libembree-dev), transformed exactly as the GL path
// transforms them (Instance::model applied in float, per vertex), one triangle geometry per instance
// with geomID = instance index and primID = triangle index in its mesh, so a G-buffer sample
// (object id, primitive id) names the same triangle on both sides.
#include <cstdint>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "scenes/Scene.h"

namespace sb {

class EmbreeScene {
public:
    /// What rays can hit: the occluders (instances that cast a shadow; the shadow rays' scene) or
    /// everything (primary rays, which must see a ground that casts nothing).
    enum class Hits { Casters, All };
    /// Builds the BVH for robust traversal (RTC_SCENE_FLAG_ROBUST: no hit lost at large coordinates;
    /// the why in the .cpp; the build is untimed precompute). Throws sb::Error
    /// naming the instance and the Embree error when a device or geometry cannot be created, or when
    /// the scene has a non-finite vertex ("scene 'x': instance 12 (mesh 'f35') has a non-finite vertex").
    /// Every instance keeps its geometry ID and normals either way; with Hits::Casters the others are
    /// disabled (rtcDisableGeometry).
    explicit EmbreeScene(const Scene& scene, Hits hits = Hits::Casters);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    RTCScene handle() const { return mScene; }
    size_t triangleCount() const { return mTriangles; }
    /// Unit geometric normal (counter-clockwise front face) of triangle `primitive` of instance
    /// `instance`, in world space, from the same world-space vertices Embree traces against. Zero
    /// vector for a degenerate (zero-area) triangle.
    glm::vec3 geometricNormal(uint32_t instance, uint32_t primitive) const;

private:
    /// Creates, fills and attaches instance `i`'s triangle geometry with geomID i.
    void addInstance(const Scene& scene, size_t i, Hits hits);
    /// Releases the scene and the device (also on a failed construction).
    void release();
    /// Fills mNormals from the world vertices (after all instances are added).
    void computeNormals();
    /// cross(b - a, c - a) normalised, zero when degenerate.
    static glm::vec3 triangleNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

    RTCDevice mDevice = nullptr;
    RTCScene mScene = nullptr;
    size_t mTriangles = 0;
    /// Per instance: its world-space vertices and the mesh's indices (kept for normals).
    std::vector<std::vector<glm::vec3>> mWorldVertices;
    std::vector<const std::vector<uint32_t>*> mIndices;
    /// Unit geometric normals of all triangles, instance after instance (mNormalBase[i] is instance
    /// i's first): geometricNormal() is on the tracer's per-pixel path, a flat table keeps it to two
    /// loads instead of a pointer chase, three vertex loads and a square root.
    std::vector<glm::vec3> mNormals;
    std::vector<size_t> mNormalBase;
};

} // namespace sb
