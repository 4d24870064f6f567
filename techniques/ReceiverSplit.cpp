#include "techniques/ReceiverSplit.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace sb::ReceiverSplit {

namespace {

/// Whether no receiver comes after a non-receiver when the instances are visited in `order`.
bool receiversFirst(const Scene& scene, const std::vector<size_t>& order) {
    bool nonReceiverSeen = false;
    for (size_t i : order) {
        if (!scene.instances[i].receivesShadow)
            nonReceiverSeen = true;
        else if (nonReceiverSeen)
            return false;
    }
    return true;
}

} // namespace

bool drawsApart(const Scene& scene, SubmitMode mode) {
    const bool receivers = std::any_of(scene.instances.begin(), scene.instances.end(),
                                       [](const Instance& inst) { return inst.receivesShadow; });
    if (!receivers || !scene.hasNonReceivers()) return false;
    // DrawSet::All's order: the scene's (immediate, display lists, retained), or mesh by mesh and the
    // scene's within a mesh (instanced, techniques/SubmissionPlan.h). Receivers first in it means that
    // Receivers then NonReceivers issue the same draws in the same order.
    std::vector<size_t> order(scene.instances.size());
    std::iota(order.begin(), order.end(), size_t(0));
    if (mode == SubmitMode::Instanced)
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            return scene.instances[a].mesh < scene.instances[b].mesh;
        });
    return receiversFirst(scene, order);
}

Defines defines(Defines lit, bool receivers) {
    // Receivers alone: every fragment receives, the per-fragment test on the id's sign goes.
    lit.erase("SB_NON_RECEIVERS");
    if (!receivers) lit["SB_NON_RECEIVER_DRAWS"] = "";
    return lit;
}

} // namespace sb::ReceiverSplit
