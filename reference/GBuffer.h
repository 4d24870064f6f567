#pragma once
// The sample positions every accuracy judgement is made at: rendered by the harness
// (GBufferRenderer) with the same camera and submitter as the technique, so reference and technique
// are compared at exactly the same points. Rows are bottom-up, as GL reads them.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace sb {

struct GBuffer {
    int width = 0, height = 0;
    /// xyz: world position of the visible surface; w: object id (Instance::objectId, 1-based; 0 = no
    /// geometry). Float ids are exact up to 2^24 instances.
    std::vector<glm::vec4> position;
    /// Triangle index within the instance's mesh (gl_PrimitiveID of the draw; restarts per instance
    /// in every submission mode). Meaningless where position.w == 0.
    std::vector<uint32_t> primitive;

    size_t size() const { return size_t(width) * size_t(height); }
    bool covered(size_t i) const { return position[i].w > 0.0f; }
    /// 0-based index into Scene::instances for a covered pixel.
    uint32_t instance(size_t i) const { return uint32_t(position[i].w) - 1u; }
};

} // namespace sb
