#pragma once
// The registry: one explicit table of every technique (docs/ARCHITECTURE.md, "The technique contract"),
// one row each: its name, its GL form and, where it has one, its Vulkan form. Adding a technique is one
// row in TechniqueRegistry.cpp; so is adding a technique's Vulkan form. It stands above techniques/ and
// reference/ (the reference is a technique too): the one place that names them all.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "techniques/Technique.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

class TechniqueRegistry {
public:
    struct Entry {
        const char* name;
        std::function<std::unique_ptr<GlTechnique>()> gl;
        std::function<std::unique_ptr<VulkanTechnique>()> vulkan; ///< empty: no Vulkan form yet
    };
    static const std::vector<Entry>& entries();
    static std::vector<std::string> names();
    /// Whether `name` has a form on `api`.
    static bool has(const std::string& name, Api api);
    /// The names with a form on `api`, in table order.
    static std::vector<std::string> namesOn(Api api);

    /// The form on `api` with the spec's properties applied (and propertiesApplied() called). An unknown
    /// name is sb::Error(BadInput) listing the known ones; a known technique without a form on `api` is
    /// sb::Error(Unsupported) naming those that have one.
    static std::unique_ptr<Technique> create(const TechniqueSpec& spec, Api api);
    /// The GL form (callers that draw with GL only: the viewer, explain, the matrix's judge, tests).
    static std::unique_ptr<GlTechnique> create(const std::string& name);
    static std::unique_ptr<GlTechnique> create(const TechniqueSpec& spec);
    /// The Vulkan form with the spec's properties; the errors as create(spec, Api::Vulkan).
    static std::unique_ptr<VulkanTechnique> createVulkan(const TechniqueSpec& spec);
    static bool hasVulkan(const std::string& name) { return has(name, Api::Vulkan); }
};

} // namespace sb
