#include "techniques/synthetic/SyntheticGL.h"

namespace sb {

namespace {
constexpr GLint kVertexIterationsLocation = 9;   // synthetic/scene.vert
constexpr GLint kFragmentIterationsLocation = 0; // synthetic/fill.frag

} // namespace

SyntheticGL::SyntheticGL() : GlTechnique(Synthetic::declaration()) {}

SyntheticGL::~SyntheticGL() {
    if (mEmptyVao) glDeleteVertexArrays(1, &mEmptyVao);
}

void SyntheticGL::setScene(const Scene&) {
    if (!mEmptyVao) glCreateVertexArrays(1, &mEmptyVao);
}

void SyntheticGL::compile(const CompileContext& ctx) {
    std::string key;
    mScene = mFill = nullptr;
    if (properties().getBool(Synthetic::kDrawScene)) {
        mScene =
            &ctx.programs.get({"synthetic/scene.vert", "synthetic/scene.frag", ""}, ctx.submitter.defines());
        key = mScene->key();
    }
    if (properties().getInt(Synthetic::kFragmentIterations) > 0) {
        mFill = &ctx.programs.get({"common/fullscreen.vert", "synthetic/fill.frag", ""}, {});
        key += (key.empty() ? "" : "|") + mFill->key();
    }
    setPermutationKey(key);
}

void SyntheticGL::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("scene");
    if (mScene) {
        mScene->use();
        glUniform1i(kVertexIterationsLocation, int(properties().getInt(Synthetic::kVertexIterations)));
        ctx.submitter.drawCulled(DrawSet::All, cameraCullView(ctx));
    }
    ctx.passes.begin("fill");
    if (mFill) {
        // Over everything, every pixel exactly once: no depth test, no depth writes.
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        mFill->use();
        glUniform1i(kFragmentIterationsLocation, int(properties().getInt(Synthetic::kFragmentIterations)));
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
