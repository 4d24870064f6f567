#include "techniques/GaussianKernel.h"

#include <algorithm>
#include <cmath>

namespace sb {

namespace {
/// The Gaussian's integral from 0 to x, for sigma (the erf form of its CDF, minus one half).
double gaussianIntegral(double x, double sigma) {
    return 0.5 * std::erf(x / (sigma * std::sqrt(2.0)));
}
} // namespace

std::vector<float> GaussianKernel::texelIntegral(int width) {
    if (width < 2) return {1.0f};
    const int radius = width / 2;
    const double half = 0.5 * width, sigma = 0.25 * width;
    std::vector<double> w(size_t(radius) + 1);
    double total = 0.0;
    for (int k = 0; k <= radius; ++k) {
        const double a = std::max(k - 0.5, -half), b = std::min(k + 0.5, half);
        w[size_t(k)] = gaussianIntegral(b, sigma) - gaussianIntegral(a, sigma);
        total += k == 0 ? w[0] : 2.0 * w[size_t(k)];
    }
    std::vector<float> out;
    for (double v : w) out.push_back(float(v / total));
    return out;
}

} // namespace sb
