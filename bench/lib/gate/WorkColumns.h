#pragma once
// Which exact-work column counts whose work (docs/CSV.md, "Application work and driver work"). The
// census columns (bench/lib/harness/WorkCensus.h, the Vulkan harness's query pool) hold two kinds:
//
// - the application's: what the harness issued. `*_gl_calls`, `*_draws`, `*_triangles` (the submitter's
//   own counts), `*_primitives` (the pipeline-statistics query's primitives submitted: the primitives
//   the draws assembled, fixed by the draws) and the techniques' `counter_*` (draw calls, triangles,
//   shadow-map texels, casters culled ...). Two drivers given the same configuration must agree on them
//   exactly: a difference means the harness did something else.
// - the driver's: what the driver chose to run for that work. `*_vertices` (vertex-shader invocations:
//   a post-transform cache reuses them), `*_clipped_primitives` (the clipper's output) and
//   `*_fragments` (fragment-shader invocations: Mesa 25.0.7 runs none in a depth-only pass, 22.3.6 one
//   per covered pixel). They are exact on one driver and expected to differ between two.
//
// Every user of the perf gate's layer A asks here, so the split is written once.
#include <string>

namespace sb {

enum class WorkClass {
    None,        ///< not an exact-work column (a time, a rate, an identity column)
    Application, ///< what the harness issued: identical on every driver
    Driver,      ///< what the driver ran for it: exact on one driver, differs between two
};

class WorkColumns {
public:
    /// The class of a result column by its name (work_<pass>_<count>, load_<count>, counter_<name>).
    /// A technique counter that is a rate (`..._per_second...`) or a time (`..._ms`, raytraced's build
    /// times) measures time and is None.
    static WorkClass classOf(const std::string& column);
    /// classOf(column) != None.
    static bool isWork(const std::string& column) { return classOf(column) != WorkClass::None; }
    /// "application" or "driver" ("" for None): the words the gate's reports use.
    static const char* name(WorkClass c);
};

} // namespace sb
