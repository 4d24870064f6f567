#include "techniques/vulkan/VulkanPassTimer.h"

#include "techniques/vulkan/VulkanSubmitter.h"

namespace sb {

void VulkanPassTimer::begin(const char* pass) {
    if (mRouter) pass = mRouter->enter(pass);
    if (mClock) mClock->passBegins(pass); // first: the pass's CPU span includes the timestamp below
    if (mRing) mRing->pass(mCmd, pass);
    if (!mCensus) return;
    closeInterval();
    mOpen = pass;
    mStart = mCensus->lifetimeStats();
    if (!mStatistics || mQueried.size() >= kMaxCensusPasses) return;
    if (mQueryOpen) vkCmdEndQuery(mCmd, mStatistics, uint32_t(mQueried.size() - 1));
    const uint32_t q = uint32_t(mQueried.size());
    vkCmdResetQueryPool(mCmd, mStatistics, q, 1);
    vkCmdBeginQuery(mCmd, mStatistics, q, 0);
    mQueried.emplace_back(pass);
    mQueryOpen = true;
}

void VulkanPassTimer::endCensusFrame() {
    if (mQueryOpen) vkCmdEndQuery(mCmd, mStatistics, uint32_t(mQueried.size() - 1));
    mQueryOpen = false;
}

void VulkanPassTimer::skip(const char* pass, const char* reason) {
    if (mCensus) mSkipped.emplace_back(mRouter ? mRouter->nameOf(pass) : pass, reason);
}

void VulkanPassTimer::startCensus(const VulkanSubmitter& submitter, VkQueryPool statistics) {
    mCensus = &submitter;
    mStatistics = statistics;
    mQueryOpen = false;
    mQueried.clear();
    mOpen.clear();
    mWork.clear();
    mSkipped.clear();
}

void VulkanPassTimer::closeInterval() {
    if (mOpen.empty()) return;
    const SubmitStats work = mCensus->lifetimeStats() - mStart;
    for (auto& [name, sum] : mWork)
        if (name == mOpen) {
            sum += work;
            mOpen.clear();
            return;
        }
    mWork.emplace_back(mOpen, work);
    mOpen.clear();
}

std::vector<std::pair<std::string, SubmitStats>> VulkanPassTimer::finishCensus() {
    if (mCensus) closeInterval();
    mCensus = nullptr;
    return std::exchange(mWork, {});
}

} // namespace sb
