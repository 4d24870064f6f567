#include "techniques/synthetic/SyntheticTechnique.h"

namespace sb {

namespace {
constexpr const char* kFragmentIterations = "fragment_iterations";
constexpr const char* kVertexIterations = "vertex_iterations";
constexpr const char* kDrawScene = "draw_scene";
constexpr GLint kVertexIterationsLocation = 9;   // synthetic/scene.vert
constexpr GLint kFragmentIterationsLocation = 0; // synthetic/fill.frag

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        integer(kFragmentIterations, "0", 0, 100000,
                "arithmetic steps per pixel of a full-screen pass (0: no pass)"),
        integer(kVertexIterations, "0", 0, 100000, "extra arithmetic steps per vertex of the scene pass"),
        flag(kDrawScene, "true", "draw the scene's triangles"),
    };
}
} // namespace

SyntheticTechnique::SyntheticTechnique()
    : Technique({.name = "synthetic",
                 .description =
                     "calibration workload of known bottleneck (no shadows): full-screen fill loop, "
                     "vertex loop, or the scene's draws",
                 .effects = 0,
                 .capabilities = {{"GL 4.5", 4, 5, ""}},
                 .passes = {"scene", "fill"},
                 .properties = declareProperties()}) {}

SyntheticTechnique::~SyntheticTechnique() {
    if (mEmptyVao) glDeleteVertexArrays(1, &mEmptyVao);
}

void SyntheticTechnique::setScene(const Scene&) {
    if (!mEmptyVao) glCreateVertexArrays(1, &mEmptyVao);
}

void SyntheticTechnique::compile(const CompileContext& ctx) {
    std::string key;
    mScene = mFill = nullptr;
    if (properties().getBool(kDrawScene)) {
        mScene =
            &ctx.programs.get({"synthetic/scene.vert", "synthetic/scene.frag", ""}, ctx.submitter.defines());
        key = mScene->key();
    }
    if (properties().getInt(kFragmentIterations) > 0) {
        mFill = &ctx.programs.get({"common/fullscreen.vert", "synthetic/fill.frag", ""}, {});
        key += (key.empty() ? "" : "|") + mFill->key();
    }
    setPermutationKey(key);
}

void SyntheticTechnique::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("scene");
    if (mScene) {
        mScene->use();
        glUniform1i(kVertexIterationsLocation, int(properties().getInt(kVertexIterations)));
        ctx.submitter.draw(DrawSet::All);
    }
    ctx.passes.begin("fill");
    if (mFill) {
        // Over everything, every pixel exactly once: no depth test, no depth writes.
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        mFill->use();
        glUniform1i(kFragmentIterationsLocation, int(properties().getInt(kFragmentIterations)));
        glBindVertexArray(mEmptyVao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glDepthMask(GL_TRUE);
        glEnable(GL_DEPTH_TEST);
    }
    const SubmitStats& s = ctx.submitter.stats();
    mCounters = {{"draw_calls", double(s.drawCalls) + (mFill ? 1.0 : 0.0)},
                 {"triangles", double(s.triangles)}};
}

} // namespace sb
