#pragma once
// Splitting the gate's family-wise false-alarm rate over the configurations of one run. A run that gates
// m configurations, each tested at alpha, raises a false alarm with probability up to m * alpha, so each
// configuration gets a share. The family-wise alpha itself is a budget of false alarms: f alarms a week
// over g gated runs a week is alpha = f / g per run (1 / 20 = 0.05 for one a week at 20 runs; the
// gate's default 0.005 is one in ten weeks), split here over the configurations.
//   - Bonferroni: every configuration at alpha / m. Simple, and a configuration's verdict does not
//     depend on the others' p-values.
//   - Holm (step-down): sort p ascending; the k-th smallest (k = 1..m) is tested at alpha / (m - k + 1)
//     while all before it were rejected, and nothing after the first acceptance is rejected. The same
//     family-wise guarantee under any dependence, and never fewer rejections than Bonferroni.
#include <cstddef>
#include <vector>

namespace sb::ci {

/// familyAlpha / configurations. familyAlpha outside (0, 1) or no configurations: sb::Error.
double bonferroniAlpha(double familyAlpha, size_t configurations);

/// Per-configuration alphas (in the order of pValues) such that pValues[i] < alpha[i] exactly when Holm
/// rejects configuration i: the k-th smallest gets familyAlpha / (m - k + 1) up to the first one that is
/// not rejected, and that one's alpha is given to every larger p (which cannot be below it). So a
/// configuration's alpha can be handed to WallTimeVerdict::decide. Ties in p keep their input order.
std::vector<double> holmAlphas(const std::vector<double>& pValues, double familyAlpha);

/// Whether Holm rejects each hypothesis (pValues[i] < holmAlphas(pValues, familyAlpha)[i]).
std::vector<bool> holmRejects(const std::vector<double>& pValues, double familyAlpha);

} // namespace sb::ci
