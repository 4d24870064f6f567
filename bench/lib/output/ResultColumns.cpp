#include "bench/lib/output/ResultColumns.h"

#include <algorithm>

namespace sb {

namespace {

// The measured row's columns in ResultRow's order (tests/CsvColumnsCliTest.cpp holds a real run to it),
// then what accuracy, sweeps, bottleneck studies, bench ci, -t auto and failed rows add. Meanings are
// docs/CSV.md's.
const std::vector<ColumnInfo> kColumns = {
    {col::kTimestamp, "", ColumnType::Text, kEveryRun, "ISO 8601 UTC time the row was measured"},
    {col::kGitCommit, "", ColumnType::Text, kEveryRun, "`git describe --always --dirty` of the source tree"},
    {col::kStatus, "", ColumnType::Text, kEveryRun,
     "`ok`; a configuration without numbers (a run's refused technique, a sweep's failed worker) "
     "`failed` (see `error`) or `unsupported` (the context lacks what it needs, e.g. "
     "`volume:depth_bounds=true` on llvmpipe: skipped, not a failure)"},
    {col::kApi, "", ColumnType::Text, kEveryRun, "`gl` or `vulkan` (`--api`)"},
    {col::kApiVersion, "", ColumnType::Text, kEveryRun,
     "`GL_VERSION`, or the Vulkan device's API version (`1.3.230`)"},
    {col::kRenderer, "", ColumnType::Text, kEveryRun, "`GL_RENDERER`, or the Vulkan device name"},
    {col::kGlVersion, "", ColumnType::Text, kEveryRun, "`GL_VERSION` (empty on Vulkan)"},
    {col::kGlVendor, "", ColumnType::Text, kEveryRun, "`GL_VENDOR`, or the Vulkan driver's name and info"},
    {col::kDriver, "", ColumnType::Text, kEveryRun,
     "the driver build the run loaded (`--driver`): `system`, `mesa-25.0.7`, a Mesa prefix's path, or "
     "`environment` when its variables were set by hand"},
    {col::kDriverVersion, "", ColumnType::Text, kEveryRun,
     "the version the driver reports: from `Mesa` on in `GL_VERSION` (`Mesa 25.0.7-2~bpo12+1`), the Vulkan "
     "driver's info (`Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)`); the whole `GL_VERSION` of a driver that is "
     "not Mesa"},
    {col::kBackend, "", ColumnType::Text, kEveryRun,
     "context backend: egl-surfaceless, egl-device, osmesa, glfw; `vulkan` on Vulkan"},
    {col::kDevice, "", ColumnType::Text, kEveryRun,
     "EGL device name (egl-device), the Vulkan device's index and name, else empty"},
    {col::kCpuModel, "", ColumnType::Text, kEveryRun, "`/proc/cpuinfo` model name"},
    {col::kHwThreads, "count", ColumnType::Integer, kEveryRun,
     "CPUs the process was given: its affinity mask (`taskset`, a Slurm task's CPUs), not the node's"},
    {col::kLpNumThreads, "", ColumnType::Text, kEveryRun,
     "`LP_NUM_THREADS` if set (llvmpipe rasteriser threads)"},
    {col::kHost, "", ColumnType::Text, kEveryRun, "host name of the machine that ran it (`gethostname`)"},
    {col::kSlurmJobId, "", ColumnType::Text, kEveryRun,
     "the Slurm job it ran in: `SLURM_ARRAY_JOB_ID` in a job array, else `SLURM_JOB_ID`; empty outside "
     "Slurm"},
    {col::kSlurmArrayTaskId, "", ColumnType::Text, kEveryRun,
     "`SLURM_ARRAY_TASK_ID`: the job array's task that ran it; empty outside a job array"},
    {col::kScene, "", ColumnType::Text, kEveryRun, "scene name"},
    {col::kSceneHash, "", ColumnType::Text, kEveryRun,
     "hash of geometry, instances, lights, cameras and motion (a scene in motion: at rest)"},
    {col::kSceneTriangles, "count", ColumnType::Integer, kEveryRun, "triangles over all instances"},
    {col::kTechnique, "", ColumnType::Text, kEveryRun, "technique name"},
    {col::kProperties, "", ColumnType::Text, kEveryRun,
     "every property, canonical `k=v:k=v` (re-run with `-t technique:<this>`)"},
    {col::kPermutation, "", ColumnType::Text, kEveryRun,
     "shader permutation keys (sorted defines, a long value as #hash) of the programs used"},
    {col::kEffectsRequested, "", ColumnType::Text, kEveryRun,
     "the scene's `effects`, `+`-joined (`hard_shadows+self_shadowing`; `none` for an empty list)"},
    {col::kEffectsDelivered, "", ColumnType::Text, kEveryRun,
     "the requested effects the technique can produce"},
    {col::kEffectsMissing, "", ColumnType::Text, kEveryRun,
     "the requested effects it cannot produce (`none` when it covers the request; README, *Effects a scene "
     "asks "
     "for*)"},
    {col::kPassesSkipped, "", ColumnType::Text, kEveryRun,
     "declared passes the technique left out of the frame, with its reason (`depth: no light casts shadows; "
     "blur: blur below 2 texels: a one-tap kernel`); empty when every pass ran"},
    {col::kInstances, "count", ColumnType::Integer, kEveryRun, "layout instances"},
    {col::kScale, "ratio", ColumnType::Number, kEveryRun, "`--scale`"},
    {col::kTessellation, "", ColumnType::Text, kEveryRun, "`--tess`, or `default`"},
    {col::kTessFactor, "ratio", ColumnType::Number, kEveryRun,
     "`--tess-factor`: multiplies every generated mesh's tessellation (1 = as the scene says)"},
    {col::kSeed, "", ColumnType::Text, kEveryRun, "`--seed`, or `default`"},
    {col::kModel, "", ColumnType::Text, kEveryRun, "`--model` path, or empty"},
    {col::kSubmit, "", ColumnType::Text, kEveryRun, "submission mode"},
    {col::kBackFaces, "", ColumnType::Text, kEveryRun,
     "`--back-faces`: `cull` (back faces of closed meshes culled where the image cannot change) or `draw`"},
    {col::kLighting, "", ColumnType::Text, kEveryRun,
     "where the lit passes evaluate the lights: `fragment` or `vertex` (Gouraud), the scene's "
     "\"lighting\" or `--lighting`"},
    {col::kCamera, "", ColumnType::Text, kEveryRun, "camera preset"},
    {col::kWidth, "px", ColumnType::Integer, kEveryRun, "render target width"},
    {col::kHeight, "px", ColumnType::Integer, kEveryRun, "render target height"},
    {col::kLights, "", ColumnType::Text, kEveryRun,
     "light types, `+`-joined; a light with `\"casts_shadows\": false` is marked `:unshadowed` "
     "(`directional+point:unshadowed`)"},
    {col::kMotion, "", ColumnType::Text, kEveryRun,
     "what moves in a scene in motion, `+`-joined (`sun+casters`, `orbit+camera`); empty for a static scene"},
    {col::kPathFrames, "count", ColumnType::Integer, kEveryRun,
     "a scene in motion: frames per pass along its path (`--path-frames`, else the scene's)"},
    {col::kPathTime, "", ColumnType::Text, kEveryRun,
     "a scene in motion: `moving` (frame f at path time (f mod path_frames) / path_frames), or the time "
     "`--time` froze it at"},
    {col::kFrames, "count", ColumnType::Integer, kEveryRun, "measured frames (n)"},
    {col::kWarmup, "count", ColumnType::Integer, kEveryRun, "discarded warm-up frames"},
    {col::kSetupMs, "ms", ColumnType::Number, kEveryRun, "setScene + compile time (untimed for the frames)"},
    {col::kWallMsMedian, "ms", ColumnType::Number, kEveryRun,
     "wall time per frame (submit + glFinish), median"},
    {col::kWallMsP5, "ms", ColumnType::Number, kEveryRun, "5th percentile"},
    {col::kWallMsP95, "ms", ColumnType::Number, kEveryRun, "95th percentile"},
    {col::kWallMsP99, "ms", ColumnType::Number, kEveryRun, "99th percentile"},
    {col::kWallMsMean, "ms", ColumnType::Number, kEveryRun, "mean"},
    {col::kWallMsStddev, "ms", ColumnType::Number, kEveryRun, "sample standard deviation"},
    {col::kWallMsMad, "ms", ColumnType::Number, kEveryRun, "median absolute deviation"},
    {col::kCpuSubmitMsMedian, "ms", ColumnType::Number, kEveryRun, "CPU submit time per frame, median"},
    {col::kCpuSubmitMsP5, "ms", ColumnType::Number, kEveryRun, "5th percentile"},
    {col::kCpuSubmitMsP95, "ms", ColumnType::Number, kEveryRun, "95th percentile"},
    {col::kCpuSubmitMsP99, "ms", ColumnType::Number, kEveryRun, "99th percentile"},
    {col::kCpuSubmitMsMean, "ms", ColumnType::Number, kEveryRun, "mean"},
    {col::kCpuSubmitMsStddev, "ms", ColumnType::Number, kEveryRun, "sample standard deviation"},
    {col::kCpuSubmitMsMad, "ms", ColumnType::Number, kEveryRun, "median absolute deviation"},
    {col::kCpuPassMsMedian, "ms", ColumnType::Number, kEveryRun,
     "CPU submit time of each declared pass, median: from the pass's begin to the next pass's begin (the "
     "last pass: to the end of submission)"},
    {col::kMotionMsMedian, "ms", ColumnType::Number, kEveryRun,
     "a moving scene: CPU time per frame spent moving the scene and updating the technique for it (light "
     "fits, projectors, silhouettes, bounds; part of the CPU submit time), median; empty for a static or "
     "frozen scene"},
    {col::kMotionMsP95, "ms", ColumnType::Number, kEveryRun, "the same, 95th percentile"},
    {col::kFpsMedian, "1/s", ColumnType::Number, kEveryRun, "1000 / wall median"},
    {col::kTimerVerdict, "", ColumnType::Text, kEveryRun, "`trusted`, `untrusted` or `unchecked`"},
    {col::kTimerReason, "", ColumnType::Text, kEveryRun,
     "the calibration's evidence: timer growth, wall growth and timer/wall per round, the bands, what "
     "failed, and the re-check after the run"},
    {col::kGpuMsMedian, "ms", ColumnType::Number, kEveryRun,
     "GPU time per frame, median (empty unless trusted)"},
    {col::kGpuPassMsMedian, "ms", ColumnType::Number, kEveryRun,
     "GPU time of each declared pass, median (empty unless trusted)"},
    {col::kCounter, "", ColumnType::Number, kEveryRun,
     "technique counters of the last frame: `triangles`, `draw_calls`, `shadow_map_texels`, `rays` ...; "
     "`no_useful_planes` (occluder): casting meshes without given planes whose automatic shadow-plane choice "
     "found no "
     "useful plane (drawn unshadowed); application work (the perf gate holds them equal across drivers)"},
    {col::kLoadGlCalls, "count", ColumnType::Integer, kEveryRun,
     "GL calls the submitter issued in one untimed census frame after the measured ones (immediate mode: one "
     "per vertex attribute); application work"},
    {col::kLoadVertices, "count", ColumnType::Integer, kEveryRun,
     "vertex shader invocations in the census frame (`GL_ARB_pipeline_statistics_query`; empty where the "
     "context cannot count); driver work"},
    {col::kLoadPrimitives, "count", ColumnType::Integer, kEveryRun,
     "primitives submitted in the census frame (assembled from the draws); application work"},
    {col::kLoadClippedPrimitives, "count", ColumnType::Integer, kEveryRun,
     "primitives out of the clipper in the census frame; driver work"},
    {col::kLoadFragments, "count", ColumnType::Integer, kEveryRun,
     "fragment shader invocations in the census frame; driver work"},
    {col::kWorkGlCalls, "count", ColumnType::Integer, kEveryRun,
     "the census frame pass by pass (`frame` for work before a technique's first pass, when there is any): "
     "GL calls the submitter issued in the pass; application work"},
    {col::kWorkDraws, "count", ColumnType::Integer, kEveryRun, "draw calls of the pass; application work"},
    {col::kWorkTriangles, "count", ColumnType::Integer, kEveryRun,
     "triangles the submitter issued in the pass; application work"},
    {col::kWorkVertices, "count", ColumnType::Integer, kEveryRun,
     "vertex shader invocations of the pass (empty where the context cannot count); driver work"},
    {col::kWorkPrimitives, "count", ColumnType::Integer, kEveryRun,
     "primitives submitted in the pass; application work"},
    {col::kWorkClippedPrimitives, "count", ColumnType::Integer, kEveryRun,
     "primitives out of the clipper in the pass; driver work"},
    {col::kWorkFragments, "count", ColumnType::Integer, kEveryRun,
     "fragment shader invocations of the pass; driver work"},
    {col::kInjected, "", ColumnType::Text, kInjected,
     "the deliberate regressions switched on for the row (`SHADOWBENCH_INJECT`, the gate's proof); absent "
     "otherwise"},
    {col::kAccLight, "", ColumnType::Integer, kAccuracy, "`bench accuracy`: the judged light"},
    {col::kAccReference, "", ColumnType::Text, kAccuracy,
     "`hard` (point-shaped light: one ray per sample) or `soft` (area light: N samples)"},
    {col::kAccEvaluated, "count", ColumnType::Number, kAccuracy,
     "samples judged (covered, geometric n.L > 0.05, within a point or spot light's range)"},
    {col::kAccFalseShadowPct, "%", ColumnType::Number, kAccuracy,
     "technique shadowed (visibility < 0.5) where the reference is lit, % of judged"},
    {col::kAccFalseLightPct, "%", ColumnType::Number, kAccuracy,
     "technique lit where the reference is shadowed, %"},
    {col::kAccWrongPct, "%", ColumnType::Number, kAccuracy, "their sum"},
    {col::kAccFalseShadowNoEdgePct, "%", ColumnType::Number, kAccuracy,
     "the same with samples within 1 px of a reference shadow edge left out"},
    {col::kAccFalseLightNoEdgePct, "%", ColumnType::Number, kAccuracy, "the same, false light"},
    {col::kAccWrongNoEdgePct, "%", ColumnType::Number, kAccuracy,
     "the same, sum (gross errors rather than edge aliasing)"},
    {col::kAccRmse, "", ColumnType::Number, kAccuracy, "visibility RMSE over judged samples (soft shadows)"},
    {col::kAccMeanAbs, "", ColumnType::Number, kAccuracy, "mean absolute visibility error"},
    {col::kAccMaxAbs, "", ColumnType::Number, kAccuracy, "max absolute visibility error"},
    {col::kAccNan, "count", ColumnType::Number, kAccuracy,
     "NaN values in the whole visibility read-back (must be 0)"},
    {col::kAccInf, "count", ColumnType::Number, kAccuracy, "Inf values (must be 0)"},
    {col::kAccOutOfRange, "count", ColumnType::Number, kAccuracy, "finite values outside [0, 1] (must be 0)"},
    {col::kAccGainCamera, "ratio", ColumnType::Number, kAccuracy, "perturbation gain, 0.25 px camera shift"},
    {col::kAccGainLight, "ratio", ColumnType::Number, kAccuracy, "perturbation gain, 0.01 degree light turn"},
    {col::kAccFlicker, "ratio", ColumnType::Number, kAccuracy,
     "changes over a 6-step camera drift / max(1, reference changes)"},
    {col::kAccPathPoints, "count", ColumnType::Integer, kAccuracy,
     "a moving scene (the `acc_*` columns above are then its first frame, and the three stability columns "
     "are empty): points along the path judged (4, spread evenly)"},
    {col::kAccPathWrongMeanPct, "%", ColumnType::Number, kAccuracy,
     "`acc_wrong_pct` averaged over the path's points"},
    {col::kAccPathWrongMaxPct, "%", ColumnType::Number, kAccuracy, "the worst point's `acc_wrong_pct`"},
    {col::kAccPathChangesTechnique, "count", ColumnType::Integer, kAccuracy,
     "judged samples whose lit/shadowed state changes from each point's frame to the next frame, technique"},
    {col::kAccPathChangesReference, "count", ColumnType::Integer, kAccuracy,
     "the same, reference (the motion's own changes)"},
    {col::kAccPathFalseChanges, "count", ColumnType::Integer, kAccuracy,
     "of those, samples that change in the technique but not in the reference: flicker the motion does not "
     "explain"},
    {col::kAccPathFlicker, "ratio", ColumnType::Number, kAccuracy,
     "temporal flicker: `acc_path_false_changes` / max(1, `acc_path_changes_reference`); 0 is none, 1 as "
     "many false changes as the motion's own"},
    {col::kAccTexelsPerPixelP50, "ratio", ColumnType::Number, kAccuracy,
     "shadow-map texels per screen pixel, median over the judged samples the technique's lighting pass looks "
     "up in a map (of the judged light, `acc_light`; receivers only; outside the map's area or depth range "
     "left out): t = sqrt(abs(det J)), J the Jacobian from screen pixels to map texels through the "
     "receiver's "
     "tangent plane, from the G-buffer and the technique's light-space mapping on the CPU "
     "(bench/lib/measure/TexelDensity.h); 1 / t is the aliasing error m of Lloyd et al., \"Warping and "
     "Partitioning for Low Error Shadow Maps\" (EGSR 2006) and \"Logarithmic Perspective Shadow Maps\" "
     "(ACM TOG 2008), the sections defining m: below 1 a texel covers more than a pixel (undersampling); "
     "empty for a technique without a shadow map (volume, planar, raytraced ...) or when no judged sample "
     "is looked up in one"},
    {col::kAccTexelsPerPixelP5, "ratio", ColumnType::Number, kAccuracy,
     "the same, 5th percentile: the undersampled end (m's 95th percentile)"},
    {col::kAccTexelsPerPixelMin, "ratio", ColumnType::Number, kAccuracy,
     "the same, minimum: the worst-sampled judged sample (m's maximum)"},
    {col::kRefSamples, "count", ColumnType::Number, kAccuracy, "reference samples per pixel"},
    {col::kRefNoiseBound, "", ColumnType::Number, kAccuracy,
     "95% half-width of a soft reference pixel at its worst (0 for hard)"},
    {col::kRefRays, "count", ColumnType::Number, kAccuracy, "rays the reference cast for the judged frame"},
    {col::kRefRaysPerSPerThread, "1/s", ColumnType::Number, kAccuracy, "the reference's throughput"},
    {col::kRefThreads, "count", ColumnType::Number, kAccuracy, "tracing threads"},
    {col::kRepeat, "", ColumnType::Integer, kEveryRun,
     "round of interleaved measurement (`--repeat K`: the techniques measured in turn K times), 1-based"},
    {col::kBaseline, "", ColumnType::Text, kEveryRun,
     "the first technique of the run (spec as given): the one ratios are taken against"},
    {col::kWallRatioVsBaseline, "ratio", ColumnType::Number, kEveryRun,
     "this row's wall median over the baseline's in the same round (runs next to each other)"},
    {col::kAutoChoice, "", ColumnType::Text, kAuto,
     "rows of `-t auto` only: the technique chosen and why (`planar: the cheapest of 9 candidate(s) "
     "delivering hard_shadows within 10% wrong (...)`)"},
    {col::kAutoCandidates, "", ColumnType::Text, kAuto,
     "rows of `-t auto` only: every candidate with its calibrated cost, error and verdict (`lacks "
     "self_shadowing`, `13.8% wrong > bound 10%`, `refused: ...`)"},
    {col::kScreenshotFile, "", ColumnType::Text, kImages,
     "the `--screenshot` PNG of this row's configuration, relative to the CSV's folder (bench/lib/images/"
     "RunImageNames.h: how each configuration of a run gets its own)"},
    {col::kVisibilityFile, "", ColumnType::Text, kImages,
     "the `--visibility` PNG of this row's configuration (light 0; light L's adds `_lightL` before `.png`), "
     "relative to the CSV's folder"},
    {col::kError, "", ColumnType::Text, kFailed,
     "why a configuration failed or was skipped (`status` = `failed` or `unsupported`): the worker's "
     "one-line error, or how it died (\"killed by signal 11\")"},
    {col::kTechniqueSpec, "", ColumnType::Text, kSweep,
     "sweeps: the technique as given to `-t` (the row's configuration; `technique` + `properties` are what "
     "ran)"},
    {col::kConfigIndex, "", ColumnType::Integer, kSweep,
     "sweeps: this configuration's place in the complete sweep, 0-based (what `--resume`, `--shard` and "
     "`bench merge` key on)"},
    {col::kConfigGroup, "", ColumnType::Integer, kSweep,
     "sweeps: the combination of axes (one worker process) the row belongs to"},
    {col::kSweepId, "", ColumnType::Text, kSweep,
     "sweeps: hash of the sweep definition (axes, options, techniques, rounds); rows of one sweep share it"},
    {col::kSweepName, "", ColumnType::Text, kSweep,
     "sweeps: the definition's name (file stem, `--name`, `bottleneck`, a figure's name)"},
    {col::kSweepConfigs, "count", ColumnType::Integer, kSweep,
     "sweeps: configurations in the complete sweep (rows of all shards together)"},
    {col::kShard, "", ColumnType::Text, kSweep, "sweeps: `i/N` of `--shard` (`1/1` unsharded)"},
    {col::kPerturbation, "", ColumnType::Text, kBottleneck,
     "`bench bottleneck`: which perturbation of the base setting the row measures (`baseline`, "
     "`submit_immediate` ...)"},
    {col::kStudyBase, "", ColumnType::Text, kBottleneck,
     "`bench bottleneck`: the base setting the perturbation applies to"},
    {col::kCiConfig, "", ColumnType::Text, kCi, "`bench ci`: the suite configuration's name"},
    {col::kCiSide, "", ColumnType::Text, kCi, "`bench ci`: `head` or `base`"},
    {col::kCiRound, "", ColumnType::Integer, kCi, "`bench ci` layer C: the round, 0-based"},
    {col::kCiRole, "", ColumnType::Text, kCi,
     "`bench ci` layer C: `base`, `head`, or `control_a`/`control_b` (the A/A control)"},
};

/// The writers' names in docs/CSV.md, in flag order.
constexpr std::pair<unsigned, const char*> kWriterNames[] = {{kEveryRun, "every run"},
                                                             {kAccuracy, "bench accuracy"},
                                                             {kSweep, "sweeps"},
                                                             {kBottleneck, "bench bottleneck"},
                                                             {kCi, "bench ci"},
                                                             {kAuto, "-t auto"},
                                                             {kFailed, "failed rows"},
                                                             {kInjected, "SHADOWBENCH_INJECT"},
                                                             {kImages, "--screenshot or --visibility"}};

} // namespace

const std::vector<ColumnInfo>& ResultColumns::all() {
    return kColumns;
}

bool ResultColumns::matches(const ColumnInfo& info, std::string_view column) {
    const size_t lt = info.name.find('<');
    if (lt == std::string_view::npos) return column == info.name;
    const std::string_view prefix = info.name.substr(0, lt),
                           suffix = info.name.substr(info.name.find('>') + 1);
    return column.size() > prefix.size() + suffix.size() && column.substr(0, prefix.size()) == prefix &&
           column.substr(column.size() - suffix.size()) == suffix;
}

const ColumnInfo* ResultColumns::find(std::string_view column) {
    // Fixed names first: `work_<pass>_primitives` would also claim a pass named "x_clipped".
    for (const ColumnInfo& c : kColumns)
        if (!c.isFamily() && c.name == column) return &c;
    const ColumnInfo* best = nullptr;
    for (const ColumnInfo& c : kColumns)
        if (c.isFamily() && matches(c, column) && (!best || c.name.size() > best->name.size())) best = &c;
    return best;
}

std::vector<ColumnInfo> ResultColumns::writtenBy(unsigned writers) {
    std::vector<ColumnInfo> out;
    std::copy_if(kColumns.begin(), kColumns.end(), std::back_inserter(out),
                 [&](const ColumnInfo& c) { return (c.writers & writers) != 0; });
    return out;
}

std::string ResultColumns::writersText(unsigned writers) {
    std::string out;
    for (const auto& [flag, name] : kWriterNames)
        if (writers & flag) out += (out.empty() ? "" : ", ") + std::string(name);
    return out;
}

std::string_view ResultColumns::typeName(ColumnType type) {
    switch (type) {
    case ColumnType::Text:
        return "text";
    case ColumnType::Integer:
        return "integer";
    case ColumnType::Number:
        return "number";
    }
    return "text";
}

std::string col::member(std::string_view family, std::string_view value) {
    const size_t lt = family.find('<'), gt = family.find('>');
    return std::string(family.substr(0, lt)) + std::string(value) + std::string(family.substr(gt + 1));
}

} // namespace sb
