#include "techniques/hybrid/Hybrid.h"

#include <algorithm>
#include <mutex>
#include <set>

#include "core/Strings.h"
#include "techniques/Property.h"

namespace sb {

TechniqueInfo Hybrid::declaration(const std::vector<std::string>& choices) {
    return {
        .name = "hybrid",
        .description = "two techniques in one frame: one shades the casters (self-shadowing), the "
                       "other the ground (cast shadows)",
        .effects = 0,
        .capabilities = {},
        .passes = {},
        .properties =
            {
                choice(kSelf, "occluder", choices,
                       "the technique that shades the instances that cast a shadow (their self-shadowing)"),
                choice(kCast, "shadowmap", choices,
                       "the technique that shades the instances that cast none (where cast shadows fall)"),
            },
        .quality = {}};
}

EffectMask Hybrid::combinedEffects(EffectMask self, EffectMask cast) {
    const EffectMask selfShadowing = uint32_t(Effect::SelfShadowing);
    return (self & cast & ~selfShadowing) | (self & selfShadowing);
}

bool Hybrid::inRole(const std::string& role, const Instance& inst) {
    return role == kSelf ? inst.castsShadow : !inst.castsShadow;
}

const char* Hybrid::emptyRoleReason(const std::string& role) {
    return role == kSelf ? "no instance casts a shadow: the self part has nothing to shade"
                         : "every instance casts a shadow: the cast part has nothing to shade";
}

const char* Hybrid::passName(const std::string& role, const std::string& pass) {
    static std::mutex mutex;
    static std::set<std::string> names;
    const std::lock_guard<std::mutex> lock(mutex);
    return names.insert(role + "_" + pass).first->c_str();
}

Error Hybrid::partError(const std::string& role, const std::string& technique, const Error& e) {
    std::string why = e.what();
    const std::string own = technique + ": ";
    if (why.rfind(own, 0) == 0) why.erase(0, own.size());
    return Error("hybrid: the " + role + " part (" + technique + "): " + why, e.code());
}

void Hybrid::appendRoleKeys(const std::string& role, const std::string& key, std::vector<std::string>& keys) {
    for (size_t start = 0; start < key.size();) {
        const size_t end = std::min(key.find('|', start), key.size());
        keys.push_back(role + ":" + key.substr(start, end - start));
        start = end + 1;
    }
}

std::string Hybrid::joinKeys(const std::vector<std::string>& keys) {
    return join(keys, "|");
}

Counters Hybrid::combinedCounters(const std::vector<std::pair<std::string, Counters>>& byRole) {
    Counters out;
    double drawCalls = 0, triangles = 0;
    for (const auto& [role, counters] : byRole)
        for (const auto& [name, value] : counters) {
            out.emplace_back(role + "_" + name, value);
            if (name == "draw_calls") drawCalls += value;
            if (name == "triangles") triangles += value;
        }
    out.insert(out.begin(), {{"draw_calls", drawCalls}, {"triangles", triangles}});
    return out;
}

} // namespace sb
