#include "techniques/hybrid/HybridGL.h"

#include "core/Error.h"
#include "techniques/gl/FrameState.h"
#include "techniques/hybrid/HybridRouterScope.h"

namespace sb {

namespace {

constexpr const char* kSelf = Hybrid::kSelf;
constexpr const char* kCast = Hybrid::kCast;

} // namespace

HybridGL::HybridGL(Factory create, std::vector<std::string> choices)
    : GlTechnique(Hybrid::declaration(choices)), mCreate(std::move(create)) {
    propertiesApplied();
}

HybridGL::~HybridGL() = default;

HybridGL::Part HybridGL::makePart(const std::string& role, const std::string& name) const {
    return Part(role, mCreate(name));
}

void HybridGL::propertiesApplied() {
    mParts.clear();
    mParts.push_back(makePart(kSelf, properties().getEnum(kSelf)));
    mParts.push_back(makePart(kCast, properties().getEnum(kCast)));
    deriveHybridInfo(mutableInfo(), mParts);
    mScene = nullptr;
}

void HybridGL::setScene(const Scene& scene) {
    mScene = &scene;
    for (Part& part : mParts) part.setScene(scene);
}

void HybridGL::sceneChanged(const Scene& scene, uint32_t changes) {
    for (Part& part : mParts)
        if (part.scopeCount != 0) part.technique->sceneChanged(scene, changes);
}

void HybridGL::compile(const CompileContext& ctx) {
    for (Part& part : mParts)
        if (part.scopeCount != 0) part.technique->compile(ctx);
    setPermutationKey(hybridPermutationKey(mParts));
}

void HybridGL::runPart(Part& part, FrameContext& ctx) {
    part.submitter = &ctx.submitter;
    HybridRouterScope<PassTimer, Submitter> scope(ctx.passes, ctx.submitter, &part);
    if (part.scopeCount == 0) {
        for (const std::string& pass : part.technique->info().passes) // renamed by the router
            ctx.passes.skip(pass.c_str(), Hybrid::emptyRoleReason(part.role));
        return;
    }
    part.technique->execute(ctx);
}

void HybridGL::execute(FrameContext& ctx) {
    bool first = true;
    for (Part& part : mParts) {
        if (!first && part.scopeCount != 0) {
            // The state the harness sets before a frame, which the next part may assume as well
            // (techniques/gl/FrameState.h): the first part may have left another framebuffer or frame
            // block bound.
            resetFrameState();
            ctx.targets.bind();
            if (ctx.frameBlock) ctx.frameBlock->bind();
        }
        runPart(part, ctx);
        first = first && part.scopeCount == 0;
    }
    mCounters = hybridCounters(mParts);
}

Counters HybridGL::counters() const {
    return mCounters;
}

} // namespace sb
