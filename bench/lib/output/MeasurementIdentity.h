#pragma once
// Whether rows are one measurement: the columns that must agree before the rows of a sweep's shards are
// merged into the one sweep the merge claims to produce (the machine's CPU, the build, the renderer and
// the driver), the mixtures found, and how many hosts the rows came from (many nodes of one kind are
// how a cluster runs a sweep: never refused, only counted).
//
// The columns, and why each is in:
// - git_commit: another commit is other code (a "-dirty" tree counts as a commit of its own);
// - cpu_model: on llvmpipe and lavapipe the CPU draws the frames; on a GPU it still times submission;
// - driver (the build --driver loaded), and per api renderer (GL_RENDERER, the Vulkan device name) and
//   driver_version: the software that drew the frame. renderer and driver_version are compared within one
//   `api` only: a sweep's api axis puts GL rows ("Mesa 25.0.7") and Vulkan rows ("Mesa 25.0.7 (LLVM
//   15.0.6)") of one driver side by side.
// And why its neighbours are out: gl_version, gl_vendor and api_version say what driver_version and
// renderer say (driver_version is read from GL_VERSION or the Vulkan driver's info); `device` holds the
// device's index, which differs between nodes of one kind; hw_threads and lp_num_threads are the
// allocation's size, which rows record and a study may vary.
//
// An empty cell (a failed row, never measured) and a file without the column (an older CSV) give no value.
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bench/lib/output/CsvWriter.h"

namespace sb {

/// One value of a column and where it was first seen.
struct SeenValue {
    std::string value;
    size_t rows = 0;   ///< rows carrying it
    std::string where; ///< "<file>:<line>" of the first of them
};

/// A column whose rows carry more than one value.
struct Mixture {
    std::string column;
    std::string api; ///< the `api` the values were compared within; empty for columns compared across all
    std::vector<SeenValue> values; ///< in first-seen order

    /// "cpu_model", or "renderer (api gl)" for a column compared within one api.
    std::string label() const;
};

class MeasurementIdentity {
public:
    /// Tallies the identity columns and the host of `table`'s rows; row r starts on line `lines[r]` of
    /// `path` (for messages).
    void add(const CsvTable& table, const std::string& path, const std::vector<size_t>& lines);

    /// Every column with more than one value, in the order of the columns above, each api in first-seen
    /// order.
    std::vector<Mixture> mixtures() const;
    /// Distinct non-empty `host` cells; nullopt when no input has the column (CSVs written before rows
    /// said where they ran).
    std::optional<size_t> hosts() const;

    /// The one-line refusal naming every mixture, each value with the first file and line holding it:
    /// "rows of different measurements mixed: cpu_model 'A' in 'a.csv:2' but 'B' in 'b.csv:2'; ...".
    static std::string refusal(const std::vector<Mixture>& mixtures);
    /// "cpu_model: 'A' 3 rows (first in 'a.csv:2'), 'B' 1 row (first in 'b.csv:2')", for the report of a
    /// merge told to mix.
    static std::string describe(const Mixture& mixture);

private:
    struct Tally {
        std::string column, api;
        std::vector<SeenValue> values;
    };
    void count(const std::string& column, const std::string& api, const std::string& value,
               const std::string& path, size_t line);

    std::vector<Tally> mTallies;
    std::set<std::string> mHosts;
    bool mHostColumn = false;
};

} // namespace sb
