#pragma once
// Runs a hybrid's part (techniques/hybrid/HybridPart.h) with its router on the frame's pass timer and
// restores the frame's router and view scope after it, also when the part throws. `Timer` is the API's
// pass timer (PassTimer, VulkanPassTimer), `S` its submitter: both forms of the hybrid use it.
#include "techniques/PassRouter.h"

namespace sb {

template <class Timer, class S>
class HybridRouterScope {
public:
    HybridRouterScope(Timer& passes, S& submitter, PassRouter* router)
        : mPasses(passes), mSubmitter(submitter), mOuter(passes.router()) {
        mPasses.setRouter(router);
    }
    ~HybridRouterScope() {
        mSubmitter.setViewScope({});
        mPasses.setRouter(mOuter);
    }
    HybridRouterScope(const HybridRouterScope&) = delete;
    HybridRouterScope& operator=(const HybridRouterScope&) = delete;

private:
    Timer& mPasses;
    S& mSubmitter;
    PassRouter* mOuter;
};

} // namespace sb
