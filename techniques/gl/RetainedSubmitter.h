#pragma once
#include <vector>

#include "techniques/gl/MeshBuffers.h"
#include "techniques/gl/Submitter.h"

namespace sb {

/// VBO/IBO per mesh, one glDrawElements per instance with per-instance uniforms. Instances are drawn
/// grouped by mesh (order fixed at upload) so the VAO changes once per mesh, not per instance.
class RetainedSubmitter final : public Submitter {
public:
    SubmitMode mode() const override { return SubmitMode::Retained; }
    void uploadMode(const Scene& scene) override;

private:
    void drawKept(DrawSet set, InstanceMask keep) override;
    const Scene* mScene = nullptr;
    MeshBuffers mBuffers;
    std::vector<uint32_t> mOrder; ///< instance indices sorted by mesh (instancesByMesh)
};

} // namespace sb
