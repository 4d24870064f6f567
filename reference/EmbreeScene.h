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
    /// Builds the BVH (RTC_BUILD_QUALITY_HIGH; the build is untimed precompute). Throws sb::Error
    /// naming the instance and the Embree error when a device or geometry cannot be created, or when
    /// the scene has a non-finite vertex ("scene 'x': instance 12 (mesh 'f35') has a non-finite vertex").
    explicit EmbreeScene(const Scene& scene);
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
    RTCDevice mDevice = nullptr;
    RTCScene mScene = nullptr;
    size_t mTriangles = 0;
    /// Per instance: its world-space vertices and the mesh's indices (kept for normals).
    std::vector<std::vector<glm::vec3>> mWorldVertices;
    std::vector<const std::vector<uint32_t>*> mIndices;
};

} // namespace sb
