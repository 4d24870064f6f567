#include "bench/lib/statistics/MultipleTesting.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "core/Error.h"

namespace sb::ci {

namespace {

void checkFamilyAlpha(double familyAlpha, size_t m, const char* where) {
    if (!(familyAlpha > 0 && familyAlpha < 1) || m == 0)
        throw Error(std::string(where) +
                        ": needs a family alpha in (0, 1) and at least one configuration (got " +
                        std::to_string(familyAlpha) + " over " + std::to_string(m) + ")",
                    ExitCode::BadInput);
}

} // namespace

double bonferroniAlpha(double familyAlpha, size_t configurations) {
    checkFamilyAlpha(familyAlpha, configurations, "bonferroniAlpha");
    return familyAlpha / double(configurations);
}

std::vector<double> holmAlphas(const std::vector<double>& pValues, double familyAlpha) {
    const size_t m = pValues.size();
    checkFamilyAlpha(familyAlpha, m, "holmAlphas");
    std::vector<size_t> order(m);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return pValues[a] < pValues[b]; });
    std::vector<double> alphas(m);
    bool stopped = false;
    double stopAlpha = 0;
    for (size_t k = 0; k < m; ++k) {
        const size_t i = order[k];
        if (!stopped) {
            alphas[i] = familyAlpha / double(m - k);
            if (!(pValues[i] < alphas[i])) {
                stopped = true;
                stopAlpha = alphas[i];
            }
        } else {
            alphas[i] = stopAlpha;
        }
    }
    return alphas;
}

std::vector<bool> holmRejects(const std::vector<double>& pValues, double familyAlpha) {
    const std::vector<double> alphas = holmAlphas(pValues, familyAlpha);
    std::vector<bool> out(pValues.size());
    for (size_t i = 0; i < pValues.size(); ++i) out[i] = pValues[i] < alphas[i];
    return out;
}

} // namespace sb::ci
