#include "registry/MemoryBudget.h"

#include <algorithm>

#include "core/Error.h"
#include "core/Strings.h"
#include "registry/TechniqueRegistry.h"

namespace sb {

namespace {

uint64_t plus(uint64_t a, uint64_t b) {
    return b > UINT64_MAX - a ? UINT64_MAX : a + b;
}

} // namespace

uint64_t MemoryBudget::targetBytes(int width, int height) {
    return uint64_t(std::max(0, width)) * uint64_t(std::max(0, height)) * kTargetBytesPerPixel;
}

ResourceEstimate MemoryBudget::techniqueBytes(const TechniqueSpec& spec, const ResourceInputs& in) {
    if (!TechniqueRegistry::has(spec.name, Api::GL) && !TechniqueRegistry::hasVulkan(spec.name)) return {};
    // A form is only constructed (no context, no device): its declaration and the spec's checked
    // properties (the GL form, else the Vulkan form of a technique that has no other: raytraced).
    const std::unique_ptr<Technique> technique = TechniqueRegistry::describe(spec);
    const ResourceDeclaration& declared = technique->info().resources;
    return declared ? declared(technique->properties(), in) : ResourceEstimate{};
}

void MemoryBudget::check(const std::vector<TechniqueSpec>& specs, const ResourceInputs& in,
                         uint64_t sceneBytes, uint64_t limitBytes, const std::string& where) {
    const uint64_t targets = targetBytes(in.width, in.height);
    for (const TechniqueSpec& spec : specs) {
        const ResourceEstimate technique = techniqueBytes(spec, in);
        const uint64_t total = plus(plus(sceneBytes, targets), technique.bytes);
        if (total <= limitBytes) continue;
        const std::string how = technique.how.empty() ? "" : " (" + technique.how + ")";
        throw Error(where + "-t " + spec.toString() + ": estimated memory " + byteSize(total) +
                    " (technique " + byteSize(technique.bytes) + how + ", scene " + byteSize(sceneBytes) +
                    ", frame targets " + byteSize(targets) + " at " + std::to_string(in.width) + "x" +
                    std::to_string(in.height) + ") exceeds the limit of " + byteSize(limitBytes) +
                    " (--max-memory-gib)");
    }
}

} // namespace sb
