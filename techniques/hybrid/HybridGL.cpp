#include "techniques/hybrid/HybridGL.h"

#include <algorithm>
#include <mutex>
#include <set>

#include "core/Error.h"
#include "core/Strings.h"
#include "techniques/gl/FrameState.h"

namespace sb {

namespace {

constexpr const char* kSelf = Hybrid::kSelf;
constexpr const char* kCast = Hybrid::kCast;

/// A pass name that lives as long as the process (PassTimer keeps names by pointer).
const char* intern(const std::string& name) {
    static std::mutex mutex;
    static std::set<std::string> names;
    const std::lock_guard<std::mutex> lock(mutex);
    return names.insert(name).first->c_str();
}

/// The instances a role shades: the casters for self, the others for cast.
bool inRole(const std::string& role, const Instance& inst) {
    return role == kSelf ? inst.castsShadow : !inst.castsShadow;
}

const char* emptyRoleReason(const std::string& role) {
    return role == kSelf ? "no instance casts a shadow: the self part has nothing to shade"
                         : "every instance casts a shadow: the cast part has nothing to shade";
}

/// Runs a part with its router on the pass timer and restores the frame's router and scope after it,
/// also when the part throws.
class RouterScope {
public:
    RouterScope(PassTimer& passes, Submitter& submitter, PassRouter* router)
        : mPasses(passes), mSubmitter(submitter), mOuter(passes.router()) {
        mPasses.setRouter(router);
    }
    ~RouterScope() {
        mSubmitter.setViewScope({});
        mPasses.setRouter(mOuter);
    }
    RouterScope(const RouterScope&) = delete;
    RouterScope& operator=(const RouterScope&) = delete;

private:
    PassTimer& mPasses;
    Submitter& mSubmitter;
    PassRouter* mOuter;
};

} // namespace

HybridGL::HybridGL(Factory create, std::vector<std::string> choices)
    : GlTechnique(Hybrid::declaration(choices)), mCreate(std::move(create)) {
    propertiesApplied();
}

HybridGL::~HybridGL() = default;

HybridGL::Part HybridGL::makePart(const std::string& role, const std::string& name) const {
    Part part;
    part.role = role;
    part.technique = mCreate(name);
    const TechniqueInfo& info = part.technique->info();
    std::vector<std::string> view = info.viewPasses;
    if (view.empty()) view = {"lighting"};
    for (const std::string& pass : info.passes) {
        part.passNames.push_back(intern(role + "_" + pass));
        part.viewPass.push_back(std::find(view.begin(), view.end(), pass) != view.end());
    }
    return part;
}

void HybridGL::propertiesApplied() {
    mParts.clear();
    mParts.push_back(makePart(kSelf, properties().getEnum(kSelf)));
    mParts.push_back(makePart(kCast, properties().getEnum(kCast)));
    TechniqueInfo& info = mutableInfo();
    info.effects =
        Hybrid::combinedEffects(mParts[0].technique->info().effects, mParts[1].technique->info().effects);
    info.capabilities.clear();
    info.passes.clear();
    info.viewPasses.clear();
    for (const Part& part : mParts) {
        const TechniqueInfo& p = part.technique->info();
        info.capabilities.insert(info.capabilities.end(), p.capabilities.begin(), p.capabilities.end());
        info.passes.insert(info.passes.end(), part.passNames.begin(), part.passNames.end());
        for (size_t i = 0; i < part.passNames.size(); ++i)
            if (part.viewPass[i]) info.viewPasses.push_back(part.passNames[i]);
    }
    mScene = nullptr;
}

void HybridGL::setScene(const Scene& scene) {
    mScene = &scene;
    for (Part& part : mParts) {
        part.scope.assign(scene.instances.size(), 0);
        part.scopeCount = 0;
        for (size_t i = 0; i < scene.instances.size(); ++i) {
            part.scope[i] = inRole(part.role, scene.instances[i]) ? 1 : 0;
            part.scopeCount += part.scope[i];
        }
        if (part.scopeCount == 0) continue; // nothing to shade: the part is never prepared
        try {
            part.technique->setScene(scene);
        } catch (const Error& e) {
            // "shadowmap: light 0 is ..." -> "hybrid: the cast part (shadowmap): light 0 is ..."
            std::string why = e.what();
            const std::string own = part.technique->name() + ": ";
            if (why.rfind(own, 0) == 0) why.erase(0, own.size());
            throw Error("hybrid: the " + part.role + " part (" + part.technique->name() + "): " + why,
                        e.code());
        }
    }
}

void HybridGL::sceneChanged(const Scene& scene, uint32_t changes) {
    for (Part& part : mParts)
        if (part.scopeCount != 0) part.technique->sceneChanged(scene, changes);
}

void HybridGL::compile(const CompileContext& ctx) {
    std::vector<std::string> keys;
    for (Part& part : mParts) {
        if (part.scopeCount == 0) continue;
        part.technique->compile(ctx);
        const std::string& key = part.technique->permutationKey(); // '|'-joined program keys
        for (size_t start = 0; start < key.size();) {
            const size_t end = std::min(key.find('|', start), key.size());
            keys.push_back(part.role + ":" + key.substr(start, end - start));
            start = end + 1;
        }
    }
    setPermutationKey(join(keys, "|"));
}

void HybridGL::runPart(Part& part, FrameContext& ctx) {
    part.submitter = &ctx.submitter;
    RouterScope scope(ctx.passes, ctx.submitter, &part);
    if (part.scopeCount == 0) {
        for (const std::string& pass : part.technique->info().passes) // renamed by the router
            ctx.passes.skip(pass.c_str(), emptyRoleReason(part.role));
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
    mCounters.clear();
    double drawCalls = 0, triangles = 0;
    for (const Part& part : mParts) {
        if (part.scopeCount == 0) continue;
        for (const auto& [name, value] : part.technique->counters()) {
            mCounters.emplace_back(part.role + "_" + name, value);
            if (name == "draw_calls") drawCalls += value;
            if (name == "triangles") triangles += value;
        }
    }
    mCounters.insert(mCounters.begin(), {{"draw_calls", drawCalls}, {"triangles", triangles}});
}

Counters HybridGL::counters() const {
    return mCounters;
}

size_t HybridGL::Part::indexOf(const char* pass) const {
    const std::vector<std::string>& passes = technique->info().passes;
    for (size_t i = 0; i < passes.size(); ++i)
        if (passes[i] == pass) return i;
    throw Error("hybrid: " + technique->name() + " began pass '" + std::string(pass) +
                    "', which it does not declare",
                ExitCode::Failure);
}

const char* HybridGL::Part::enter(const char* pass) {
    const size_t i = indexOf(pass);
    if (submitter) submitter->setViewScope(viewPass[i] ? InstanceMask(scope) : InstanceMask{});
    return passNames[i];
}

const char* HybridGL::Part::nameOf(const char* pass) const {
    return passNames[indexOf(pass)];
}

} // namespace sb
