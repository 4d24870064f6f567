#pragma once
// A lit pass's programs on GL: one for the whole scene, or, where techniques/ReceiverSplit.h allows it,
// one for the receivers and one without the shadow lookup for the instances that receive no shadow.
// Every technique whose lit pass looks a shadow up per fragment draws its lit pass through it.
#include <string>

#include "gl/ProgramCache.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/Submitter.h"

namespace sb {

class LitPrograms {
public:
    /// Gets the programs of `sources` for `lit` (the lit pass's defines) from `ctx`'s cache; returns
    /// the permutation key of what was compiled: the one program's key, or the receivers' and the
    /// non-receivers' keys joined by '|'.
    std::string compile(const CompileContext& ctx, const ShaderSources& sources, const Defines& lit);

    /// The program the technique sets its uniforms on and draws the receivers with (or everything).
    const Program& program() const { return *mReceivers; }
    /// Whether the non-receivers are drawn apart with a second program.
    bool split() const { return mNonReceivers != nullptr; }

    /// Draws the visible scene under `view` with program() in use: DrawSet::All, or the receivers, then
    /// the non-receivers with their program, which reads none of the technique's uniforms and textures
    /// (nothing to set). Leaves the last program used in use.
    void draw(Submitter& submitter, const CullView& view) const;

private:
    const Program* mReceivers = nullptr;
    const Program* mNonReceivers = nullptr;
};

} // namespace sb
