#pragma once
// A form of a technique at some of its properties that the golden matrix (bench/golden/GoldenMatrix.h)
// judges in cells of its own, beside the technique's default form: `raytraced`'s mode=soft and
// mode=guided. A technique declares its variants with its other properties (TechniqueInfo::
// matrixVariants), each with the accuracy rule its cells are held to and why that rule holds for it; the
// matrix names their cells by the spec ("raytraced:mode=soft") and keys their goldens, bounds and rows by
// bench/golden/MatrixVariants.h. A variant is one configuration worth its own golden (a mode that traces
// other rays), not a sweep of knobs: `bench accuracy --sweep` walks those.
#include <string>

namespace sb {

/// The accuracy rules of the matrix, what bench/golden/AccuracyBounds.h bounds each by: the default form
/// of every technique has one there (by its name), a variant declares its own.
enum class AccuracyRule { Exact, Map, NoShadow, Approximate, SoftApproximate, NotJudged };

/// "exact", "map", "no_shadow", "approximate", "soft_approximate", "not_judged": bounds.json's `rule`.
const char* accuracyRuleName(AccuracyRule rule);

struct MatrixVariant {
    /// The spec's properties, as `-t name:<properties>` writes them: "mode=soft" (TechniqueSpec's form,
    /// "k=v:k=v", in the order toString() writes them back).
    std::string properties;
    AccuracyRule rule = AccuracyRule::Approximate;
    /// Why the rule holds for this form, in a sentence: it closes the reason of each of its bounds
    /// (results/goldens/bounds.json, MATRIX.md).
    std::string why;
    /// Non-empty: the variant has no GL form (it needs what only Vulkan offers), in a sentence. Its GL
    /// cells are then cells of no form with this reason, and its Vulkan retained cell holds its golden
    /// and bound, as for a technique with no GL form (bench/golden/GoldenMatrix.h).
    std::string glRefusal;
};

} // namespace sb
