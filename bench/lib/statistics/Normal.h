#pragma once
// The standard normal distribution, for the large-sample approximations of the rank tests and the
// minimum detectable effect. Written out here because the standard library has std::erfc but no
// quantile function.
namespace sb::ci {

/// P(Z <= z) for a standard normal Z, through std::erfc (accurate in both tails).
double normalCdf(double z);

/// The z with normalCdf(z) = p, for p in (0, 1): Acklam's rational approximation (relative error
/// 1.15e-9) polished by one Halley step on normalCdf, which brings it to about 1e-15. p outside
/// (0, 1) is a programming error (sb::Error).
double normalQuantile(double p);

} // namespace sb::ci
