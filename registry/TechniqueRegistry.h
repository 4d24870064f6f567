#pragma once
// The registry: one explicit table of every technique (docs/ARCHITECTURE.md, "The technique contract"),
// one row each: its name, its GL form and its Vulkan form, where it has them (a technique without a GL
// form, `raytraced`, says why in its row). Adding a technique is one row in TechniqueRegistry.cpp; so is
// adding a technique's Vulkan form. It stands above techniques/ and
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
        std::function<std::unique_ptr<GlTechnique>()> gl;         ///< empty: no GL form (glRefusal says why)
        std::function<std::unique_ptr<VulkanTechnique>()> vulkan; ///< empty: no Vulkan form yet
        /// Why a technique without a GL form has none, in one line (the refusal of `-t NAME` on GL).
        const char* glRefusal = nullptr;
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
    /// The GL form (callers that draw with GL only: the viewer, explain, the matrix's judge, tests). A
    /// technique without one is sb::Error(Unsupported) with its entry's glRefusal.
    static std::unique_ptr<GlTechnique> create(const std::string& name);
    static std::unique_ptr<GlTechnique> create(const TechniqueSpec& spec);
    /// A form of the technique for what its declaration says (name, properties, passes, effects) where
    /// the run's API has none: the GL form, else the Vulkan form, with the spec's properties. Nothing
    /// of an API is touched (no context or device is needed). The errors of a bad spec as create's.
    static std::unique_ptr<Technique> describe(const TechniqueSpec& spec);
    /// The Vulkan form with the spec's properties; the errors as create(spec, Api::Vulkan).
    static std::unique_ptr<VulkanTechnique> createVulkan(const TechniqueSpec& spec);
    static bool hasVulkan(const std::string& name) { return has(name, Api::Vulkan); }
};

} // namespace sb
