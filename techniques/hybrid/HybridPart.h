#pragma once
// One role of a hybrid technique (techniques/hybrid/HybridGL.h), the same on both APIs: the part's
// technique, the instances it shades and the names its passes are recorded under. `T` is the API's
// technique base (GlTechnique, VulkanTechnique), `S` its submitter (Submitter, VulkanSubmitter): both
// offer setViewScope, which the router sets as each of the part's passes begins.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "core/Error.h"
#include "scenes/DrawSet.h"
#include "scenes/Scene.h"
#include "techniques/MapTexels.h"
#include "techniques/PassRouter.h"
#include "techniques/hybrid/Hybrid.h"

namespace sb {

template <class T, class S>
struct HybridPart final : PassRouter {
    std::string role; ///< "self" or "cast"
    std::unique_ptr<T> technique;
    std::vector<uint8_t> scope; ///< per instance: shaded by this part
    size_t scopeCount = 0;      ///< instances in scope
    /// "<role>_<pass>", parallel to the part's passes: interned for the life of the process
    /// (Hybrid::passName), since the timer-query ring reads a pass's name frames after it ran.
    std::vector<const char*> passNames;
    std::vector<bool> viewPass; ///< parallel to the part's passes
    S* submitter = nullptr;     ///< of the frame being drawn

    HybridPart(std::string roleName, std::unique_ptr<T> made)
        : role(std::move(roleName)), technique(std::move(made)) {
        const TechniqueInfo& info = technique->info();
        std::vector<std::string> view = info.viewPasses;
        if (view.empty()) view = {"lighting"};
        for (const std::string& pass : info.passes) {
            passNames.push_back(Hybrid::passName(role, pass));
            viewPass.push_back(std::find(view.begin(), view.end(), pass) != view.end());
        }
    }

    /// The instances of the role on `scene`; prepares the technique when it has any, with its errors
    /// named after the role (Hybrid::partError).
    void setScene(const Scene& scene) {
        scope.assign(scene.instances.size(), 0);
        scopeCount = 0;
        for (size_t i = 0; i < scene.instances.size(); ++i) {
            scope[i] = Hybrid::inRole(role, scene.instances[i]) ? 1 : 0;
            scopeCount += scope[i];
        }
        if (scopeCount == 0) return; // nothing to shade: the part is never prepared
        try {
            technique->setScene(scene);
        } catch (const Error& e) {
            throw Hybrid::partError(role, technique->name(), e);
        }
    }

    const char* enter(const char* pass) override {
        const size_t i = indexOf(pass);
        if (submitter) submitter->setViewScope(viewPass[i] ? InstanceMask(scope) : InstanceMask{});
        return passNames[i];
    }
    const char* nameOf(const char* pass) const override { return passNames[indexOf(pass)]; }

private:
    size_t indexOf(const char* pass) const {
        const std::vector<std::string>& passes = technique->info().passes;
        for (size_t i = 0; i < passes.size(); ++i)
            if (passes[i] == pass) return i;
        throw Error("hybrid: " + technique->name() + " began pass '" + std::string(pass) +
                        "', which it does not declare",
                    ExitCode::Failure);
    }
};

/// A hybrid's map lookups (Technique::mapTexels): an instance's are its role's technique's, none where that
/// technique reads no map. Holds the parts by reference: the hybrid owns both.
template <class Part>
class HybridMapTexels final : public MapTexels {
public:
    explicit HybridMapTexels(const std::vector<Part>& parts) : mParts(parts) {}
    std::optional<MapPoint> texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const override {
        for (const Part& part : mParts) {
            if (at.instance >= part.scope.size() || !part.scope[at.instance]) continue;
            const MapTexels* maps = part.technique->mapTexels();
            return maps ? maps->texel(light, at, q) : std::nullopt;
        }
        return std::nullopt;
    }

private:
    const std::vector<Part>& mParts;
};

/// What a hybrid declares once its parts are made: the combined effects, the parts' capabilities, and
/// their passes under the roles' names (view passes likewise).
template <class Part>
void deriveHybridInfo(TechniqueInfo& info, const std::vector<Part>& parts) {
    info.effects =
        Hybrid::combinedEffects(parts[0].technique->info().effects, parts[1].technique->info().effects);
    info.capabilities.clear();
    info.passes.clear();
    info.viewPasses.clear();
    for (const Part& part : parts) {
        const TechniqueInfo& p = part.technique->info();
        info.capabilities.insert(info.capabilities.end(), p.capabilities.begin(), p.capabilities.end());
        info.passes.insert(info.passes.end(), part.passNames.begin(), part.passNames.end());
        for (size_t i = 0; i < part.passNames.size(); ++i)
            if (part.viewPass[i]) info.viewPasses.push_back(part.passNames[i]);
    }
}

/// The hybrid's permutation key: each prepared part's program keys prefixed with its role.
template <class Part>
std::string hybridPermutationKey(const std::vector<Part>& parts) {
    std::vector<std::string> keys;
    for (const Part& part : parts)
        if (part.scopeCount != 0) Hybrid::appendRoleKeys(part.role, part.technique->permutationKey(), keys);
    return Hybrid::joinKeys(keys);
}

/// The hybrid's counters after a frame: each prepared part's under its role, draw_calls and triangles
/// summed over both first.
template <class Part>
Counters hybridCounters(const std::vector<Part>& parts) {
    std::vector<std::pair<std::string, Counters>> byRole;
    for (const Part& part : parts)
        if (part.scopeCount != 0) byRole.emplace_back(part.role, part.technique->counters());
    return Hybrid::combinedCounters(byRole);
}

} // namespace sb
