#pragma once
// The accuracy bound of every matrix cell, derived from the Embree answer of that cell and from what the
// technique can achieve, never from the technique's own result. One rule per technique:
//   exact        (volume, reference, raytraced): visibility is exact up to rasterisation, so off the 1-px
//   band
//                around reference shadow edges only a sliver may differ;
//   map          (shadowmap and its family: cubemap, paraboloid, cascaded, pcss, vsm, esm): exact up to
//                the map's texels, bias and filter width, a little more off the edge band;
//   no_shadow    (none): draws no shadow, so its error must be exactly the reference's shadowed fraction;
//   approximate  (occluder, planar, projective, hybrid): an approximation may miss shadows, but a shadow that
//   is
//                worse than drawing no shadow at all is broken: the bound is the error of no shadow in
//                that cell (judged samples the reference shadows);
//   soft_approximate (proxy, blob): their visibility is continuous by design (ShadowProxies' "infinitely
//                soft" halo, the blob's faded ellipse), so a 0.5 threshold misjudges them: the metric is
//                the RMSE against the reference, bounded by the RMSE of no shadow;
//   not_judged   (synthetic): not a shadow technique (the bottleneck study's workloads).
// Under an area light (soft reference) the hard-shadow techniques are all approximations: the metric is
// the RMSE, bounded by the RMSE of no shadow. A cell whose technique is known not to reach its rule's
// bound carries an exception with the reason (kExceptions in AccuracyBounds.cpp), shown in the matrix.
// A technique's matrix variant (raytraced:mode=soft, raytraced:mode=guided: techniques/MatrixVariant.h)
// is held to the rule it declares, and its reason closes the bound's; its bounds are keyed by
// MatrixVariants::key ("raytraced.mode=soft/<scene>/light<i>").
#include <map>
#include <string>
#include <vector>

#include "bench/golden/GoldenMatrix.h"

namespace sb {

struct AccuracyBound {
    std::string cell;   ///< "technique/scene/light<i>", the technique as MatrixVariants::key writes it
    std::string metric; ///< "wrong_pct", "wrong_no_edge_pct", "rmse", "" (not judged)
    double max = 0.0;
    double min = 0.0; ///< the no_shadow rule pins both ends
    std::string rule; ///< the rule's name, or "exception"
    std::string why;
    /// The 'measured' value bounds.json holds for the cell (AccuracyBounds::read), so that an update of
    /// some scenes or techniques writes the other cells back as they were, not as 0.
    double recorded = 0.0;
    bool judged() const { return !metric.empty(); }
    /// The value of `metric` in `accuracy`.
    double measured(const CellAccuracy& accuracy) const;
};

class AccuracyBounds {
public:
    /// The bound of light `light` of `cell` (any mode: the mode never changes the image).
    static AccuracyBound derive(const MatrixCell& cell, size_t light);
    /// results/goldens/bounds.json as written by `bench golden --update`: every bound with its rule,
    /// reason and the value measured when it was written, for review.
    static std::string toJson(const std::vector<AccuracyBound>& bounds, const std::vector<double>& measured);
    /// Reads bounds.json, keyed by cell "technique/scene/light<i>" (MatrixVariants::key's technique;
    /// throws sb::Error naming the file).
    static std::map<std::string, AccuracyBound> read(const std::string& path);
};

} // namespace sb
