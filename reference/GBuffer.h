#pragma once
// The sample positions every accuracy judgement is made at: rendered by the harness
// (GBufferRenderer) with the same camera and submitter as the technique, so reference and technique
// are compared at exactly the same points. Rows are bottom-up, as GL reads them. A sample is judged
// from the side of its surface the camera sees (seenNormal): every technique shades a back face with its
// normal turned towards the eye (gl_FrontFacing), so the inside of a closed caster, seen from a camera
// within it, is a receiver facing inwards, not the outside of the caster.
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
    /// 1 where the sample is on a back face, as the rasteriser decided it (gl_FrontFacing, the decision
    /// every technique's shading made for that pixel). Empty: not recorded (a hand-built list of
    /// samples); every sample is then seen from the side its geometric normal points to.
    std::vector<uint8_t> backFacing;

    size_t size() const { return size_t(width) * size_t(height); }
    /// Moves shaders/reference/gbuffer.frag's back-face flag (bit 31 of the id it writes: a triangle index
    /// never reaches it) out of `primitive` into `backFacing`; both renderers' read-backs end with it.
    void splitBackFaces() {
        constexpr uint32_t kBackFace = 0x80000000u;
        backFacing.resize(size());
        for (size_t i = 0; i < size(); ++i) {
            backFacing[i] = (primitive[i] & kBackFace) ? 1 : 0;
            primitive[i] &= ~kBackFace;
        }
    }
    bool covered(size_t i) const { return position[i].w > 0.0f; }
    /// 0-based index into Scene::instances for a covered pixel.
    uint32_t instance(size_t i) const { return uint32_t(position[i].w) - 1u; }
    /// `normal` (the sample's geometric normal) turned towards the camera: negated on a back face.
    glm::vec3 seenNormal(size_t i, const glm::vec3& normal) const {
        return !backFacing.empty() && backFacing[i] ? -normal : normal;
    }
};

} // namespace sb
