#pragma once
// What `bench ci --update` writes into a committed baseline (results/ci/baseline/, or a driver's
// baseline/<driver>/) when it ran only some of the configurations that belong there: --configs names a
// few, or --driver-bound counts only what one driver alone can run. The rows and instruction counts of
// the configurations it did not run are kept as they were, in the suite's order, and those it ran
// replaced; an update of every configuration that runs on the driver writes what it measured alone, as
// before (so a column or a configuration that is gone leaves the file). Layer B's counts are kept only
// where they were counted under the same fingerprint as the new ones (InstructionLayer.h compares a
// configuration with its own fingerprint): keeping another machine's counts beside this one's would make
// the record claim what it never measured, so that is refused, naming what differs.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/lib/gate/CiSuite.h"
#include "bench/lib/output/CsvWriter.h"

namespace sb {

class BaselineUpdate {
public:
    /// Layer A's baseline after an update: `fresh` (the rows just measured, in the baseline's columns)
    /// with the rows of `committed` whose configuration is in `belong` (the suite's configurations that
    /// run on this baseline's driver, in order) but not in `fresh`. The header is the committed one with
    /// the fresh columns it lacks appended; the rows follow `belong`'s order. No row kept: `fresh` as is.
    static CsvTable work(const CsvTable& committed, const CsvTable& fresh,
                         const std::vector<const CiConfig*>& belong);
    /// Layer B's record after an update: `fresh` (InstructionLayer's record) with the configurations of
    /// `committed` that are in `belong` and not in `fresh`. Throws Error(BadInput) naming `path` and the
    /// fingerprint's differing fields when a kept configuration was counted under another fingerprint
    /// than the fresh ones.
    static nlohmann::json instructions(const nlohmann::json& committed, const nlohmann::json& fresh,
                                       const std::vector<const CiConfig*>& belong, const std::string& path);
};

} // namespace sb
