#pragma once
// What a technique declares before it does anything (docs/ARCHITECTURE.md, "The technique contract"), the
// same on every API: its name, effects, the capabilities each API's form needs, its passes, properties and
// quality knobs. Each technique keeps this declaration in its own API-neutral file
// (techniques/<name>/<Name>.h), which its GL and Vulkan forms both take.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scenes/Scene.h"
#include "techniques/MatrixVariant.h"
#include "techniques/Property.h"
#include "techniques/ResourceEstimate.h"

namespace sb {

/// The APIs a technique may have a form on (--api).
enum class Api { GL, Vulkan };
const char* apiName(Api api); ///< "gl", "vulkan" (the rows' `api` column)
std::optional<Api> parseApi(const std::string& name);

/// A requirement of one API's form: a minimum version and/or an extension. Checked against the context
/// (GL) or device (Vulkan) before a run; a missing one is a clear refusal (ExitCode::Unsupported), never
/// a crash.
struct Capability {
    Api api = Api::GL;
    std::string name; ///< shown to the user: "GL 4.5", "GL_ARB_depth_clamp", "VK_KHR_ray_query"
    int major = 0;    ///< version requirement (0 = none)
    int minor = 0;
    std::string extension; ///< extension requirement ("" = none)
    /// Where it is found when the machine lacks it, added to the refusal ("" = nothing to add): "the
    /// driver entry mesa-25.0.7 has them: --driver mesa-25.0.7".
    std::string hint;
};

/// A quality knob and the values `bench accuracy --sweep` walks (accuracy against time).
struct QualityKnob {
    std::string property;
    std::vector<std::string> values;
};

struct TechniqueInfo {
    std::string name;                     ///< registry name, lower case: "shadowmap"
    std::string description;              ///< one line for --list
    EffectMask effects = 0;               ///< what it can produce
    std::vector<Capability> capabilities; ///< of every API's form (Capability::api says which)
    std::vector<std::string> passes;      ///< stable names: GPU timer scopes and CSV columns
    /// The passes that draw the scene as the camera sees it (shading the visible instances), a subset
    /// of `passes`; the others make shadows (maps, volumes, textures, blurs). A hybrid technique
    /// restricts only these to the instances its part owns. Empty: {"lighting"}.
    std::vector<std::string> viewPasses;
    std::vector<PropertyDesc> properties;
    std::vector<QualityKnob> quality; ///< knobs that trade accuracy for time, with sweep values
    /// What it allocates for one configuration, before it allocates it (techniques/ResourceEstimate.h):
    /// the run refuses a configuration over --max-memory-gib. Empty: nothing that grows with its
    /// properties or the frame (its buffers are the scene's size, which the scene's estimate counts).
    ResourceDeclaration resources;
    /// Forms at other properties that the golden matrix judges in cells of their own, each with its
    /// accuracy rule (techniques/MatrixVariant.h); empty for most: the default form's cells are its only.
    std::vector<MatrixVariant> matrixVariants;

    /// The capabilities of `api`'s form.
    std::vector<Capability> capabilitiesOf(Api api) const;
};

/// Named counters of the last frame ("triangles", "draw_calls", "shadow_map_texels" ...), in a stable
/// order: they become CSV columns "counter_<name>".
using Counters = std::vector<std::pair<std::string, double>>;

} // namespace sb
