#include "techniques/gl/LitPrograms.h"

#include "techniques/ReceiverSplit.h"

namespace sb {

std::string LitPrograms::compile(const CompileContext& ctx, const ShaderSources& sources,
                                 const Defines& lit) {
    mNonReceivers = nullptr;
    if (!ReceiverSplit::drawsApart(ctx.scene, ctx.submitter.mode())) {
        mReceivers = &ctx.programs.get(sources, lit);
        return mReceivers->key();
    }
    mReceivers = &ctx.programs.get(sources, ReceiverSplit::defines(lit, true));
    mNonReceivers = &ctx.programs.get(sources, ReceiverSplit::defines(lit, false));
    return mReceivers->key() + "|" + mNonReceivers->key();
}

void LitPrograms::draw(Submitter& submitter, const CullView& view) const {
    if (!mNonReceivers) {
        submitter.drawCulled(DrawSet::All, view);
        return;
    }
    submitter.drawCulled(DrawSet::Receivers, view);
    mNonReceivers->use();
    submitter.drawCulled(DrawSet::NonReceivers, view);
}

} // namespace sb
