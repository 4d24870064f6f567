#pragma once
// The registry: one explicit table of every technique (docs/ARCHITECTURE.md, "The technique contract").
// Adding a technique is one line in TechniqueRegistry.cpp.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "techniques/Technique.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

class TechniqueRegistry {
public:
    using Factory = std::function<std::unique_ptr<Technique>()>;
    struct Entry {
        const char* name;
        Factory create;
    };
    static const std::vector<Entry>& entries();
    static std::vector<std::string> names();
    /// Throws sb::Error "unknown technique 'x' (known: none, shadowmap)".
    static std::unique_ptr<Technique> create(const std::string& name);
    /// Creates the technique and applies the spec's properties ("shadowmap:resolution=2048").
    static std::unique_ptr<Technique> create(const TechniqueSpec& spec);

    /// The techniques with a Vulkan form (`--api vulkan`), a subset of entries() in the same order.
    using VulkanFactory = std::function<std::unique_ptr<VulkanTechnique>()>;
    struct VulkanEntry {
        const char* name;
        VulkanFactory create;
    };
    static const std::vector<VulkanEntry>& vulkanEntries();
    static bool hasVulkan(const std::string& name);
    /// The Vulkan form with the spec's properties. A known technique without one is
    /// sb::Error(Unsupported) naming those that have one; an unknown name is create()'s error.
    static std::unique_ptr<VulkanTechnique> createVulkan(const TechniqueSpec& spec);
};

} // namespace sb
