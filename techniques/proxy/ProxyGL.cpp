#include "techniques/proxy/ProxyGL.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/Error.h"

namespace sb {

namespace {
// shaders/proxy/lit.frag
constexpr GLuint kProxyBinding = 2, kIndexBinding = 3;
constexpr GLint kShadingLocation = 16, kBleedLocation = 17, kStartLocation = 18, kPenumbraLocation = 19,
                kCellsLocation = 20, kViewportLocation = 21, kCapacityLocation = 22, kCountLocation = 23;

} // namespace

ProxyGL::ProxyGL() : GlTechnique(Proxy::declaration()) {}

ProxyGL::~ProxyGL() {
    release();
}

void ProxyGL::release() {
    if (mProxyBuffer) glDeleteBuffers(1, &mProxyBuffer);
    if (mIndexBuffer) glDeleteBuffers(1, &mIndexBuffer);
    mProxyBuffer = mIndexBuffer = 0;
    mProxyCapacity = mIndexCapacity = 0;
}

void ProxyGL::setScene(const Scene& scene) {
    mPlan.setScene(scene, properties());
}

void ProxyGL::compile(const CompileContext& ctx) {
    mProgram = &ctx.programs.get({"common/scene.vert", "proxy/lit.frag", ""},
                                 mPlan.defines(ctx.defines(), properties()));
    setPermutationKey(mProgram->key());
    if (!mProxyBuffer) glCreateBuffers(1, &mProxyBuffer);
    if (!mIndexBuffer) glCreateBuffers(1, &mIndexBuffer);
}

void ProxyGL::uploadFrame(FrameContext& ctx) {
    mPlan.build(ctx.proj * ctx.view, properties());
    const std::vector<ProxyPlan::GpuProxy>& inView = mPlan.inView();
    // Buffers grow (never shrink) to the largest frame; then only sub-data updates.
    const size_t proxies = std::max<size_t>(1, inView.size());
    if (proxies > mProxyCapacity) {
        glNamedBufferData(mProxyBuffer, GLsizeiptr(proxies * sizeof(ProxyPlan::GpuProxy)), nullptr,
                          GL_DYNAMIC_DRAW);
        mProxyCapacity = proxies;
    }
    if (!inView.empty())
        glNamedBufferSubData(mProxyBuffer, 0, GLsizeiptr(inView.size() * sizeof(ProxyPlan::GpuProxy)),
                             inView.data());
    if (mPlan.useGrid()) {
        const std::vector<uint32_t>& texels = mPlan.grid().texels();
        if (texels.size() > mIndexCapacity) {
            glNamedBufferData(mIndexBuffer, GLsizeiptr(texels.size() * sizeof(uint32_t)), nullptr,
                              GL_DYNAMIC_DRAW);
            mIndexCapacity = texels.size();
        }
        glNamedBufferSubData(mIndexBuffer, 0, GLsizeiptr(texels.size() * sizeof(uint32_t)), texels.data());
    }
}

void ProxyGL::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("index_map");
    uploadFrame(ctx);
    ctx.passes.begin("lighting");
    ctx.targets.bind();
    mProgram->use();
    const ProxyPlan::Uniforms u = mPlan.uniforms(properties(), ctx.targets.width(), ctx.targets.height());
    glUniform4f(kShadingLocation, u.shading.x, u.shading.y, u.shading.z, u.shading.w);
    glUniform1f(kStartLocation, u.start);
    if (mPlan.rays()) glUniform1f(kPenumbraLocation, u.penumbra);
    if (mPlan.bleed()) glUniform1f(kBleedLocation, u.bleed);
    if (mPlan.useGrid()) {
        glUniform2i(kCellsLocation, u.cells.x, u.cells.y);
        glUniform2f(kViewportLocation, u.viewport.x, u.viewport.y);
        glUniform1i(kCapacityLocation, u.capacity);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kIndexBinding, mIndexBuffer);
    } else {
        glUniform1i(kCountLocation, u.count);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kProxyBinding, mProxyBuffer);
    ctx.submitter.drawCulled(DrawSet::All, cameraCullView(ctx));
    mCounters = mPlan.counters(ctx.submitter.stats());
}

} // namespace sb
