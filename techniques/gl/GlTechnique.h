#pragma once
// The technique contract on GL (docs/ARCHITECTURE.md, "The technique contract"): a technique's GL form
// takes its declaration from the technique's API-neutral file and adds what GL needs: a capability check
// against the context, compile (programs for the current properties, the scene's effects and the
// submission mode, through the ProgramCache) and execute once per frame into the bound targets. Every
// technique writes, besides colour, the visibility target (FrameTargets attachment 1: channel i = light
// i, 1 lit, 0 shadowed).
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "gl/Context.h"
#include "gl/FrameTargets.h"
#include "gl/ProgramCache.h"
#include "scenes/Scene.h"
#include "techniques/Technique.h"
#include "techniques/gl/FrameUniforms.h"
#include "techniques/gl/PassTimer.h"
#include "techniques/gl/Submitter.h"

namespace sb {

struct CompileContext {
    ProgramCache& programs;
    const Scene& scene;
    const Submitter& submitter; ///< its defines() go into every scene-drawing program
    const Context& context;

    /// What every scene-drawing program is compiled with: the submitter's defines and the scene's
    /// shadow exceptions and light kinds (addSceneDefines).
    Defines defines() const;
};

struct FrameContext {
    const Scene& scene;
    glm::mat4 view{1.0f}, proj{1.0f};
    glm::vec3 eye{0.0f};
    FrameTargets& targets; ///< bound and cleared by the harness before execute()
    Submitter& submitter;
    PassTimer& passes;
    uint64_t frameIndex = 0;
    /// The harness's frame block (binding 0). A technique that binds a block of its own there (volume's
    /// infinite projection) leaves it bound; a hybrid binds this one again before its next part.
    const FrameUniforms* frameBlock = nullptr;
};

/// The camera's view for back-face culling (Submitter::setCullView, scenes/BackFaceCulling.h): what
/// every pass that draws the visible scene with the harness's camera passes.
inline CullView cameraCullView(const FrameContext& ctx) {
    return {ctx.proj * ctx.view, false};
}

class GlTechnique : public Technique {
public:
    using Technique::Technique;
    Api api() const override { return Api::GL; }

    /// "" when every GL capability is present, else "shadowmap needs GL_ARB_x (not exposed by <renderer>)".
    std::string checkCapabilities(const Context& context) const;
    /// Builds the programs for the current properties, scene effects and submission mode.
    virtual void compile(const CompileContext& ctx) = 0;
    /// Renders one frame into ctx.targets, calling ctx.passes.begin() at each declared pass.
    virtual void execute(FrameContext& ctx) = 0;
};

} // namespace sb
