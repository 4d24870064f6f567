#pragma once
// The one table of the result CSV's columns (docs/CSV.md; docs/ARCHITECTURE.md, "Results"): each column's
// name, unit, type, which runs write it and what it means. Code names a column by its constant in
// `sb::col` (col::kWallMsMedian), never by a string literal, so that a renamed or misspelt column fails to
// compile rather than silently reading empty cells; tests/CsvDocTest.cpp holds docs/CSV.md to this table
// and tests/CsvColumnsCliTest.cpp a real run's header.
//
// Families: a column whose name holds a placeholder (`gpu_<pass>_ms_median`, `counter_<name>`,
// `work_<pass>_draws` ...) stands for one column per pass or counter of the technique; col::member()
// spells a member. The table lists the measured row's columns in the order
// ResultRow writes them, then the columns other runs add.
#include <string>
#include <string_view>
#include <vector>

namespace sb {

/// Which runs write a column, as bit flags (a column may have several).
enum ColumnWriter : unsigned {
    kEveryRun = 1u << 0,   ///< every measured row: plain `bench` and every mode built on it
    kAccuracy = 1u << 1,   ///< `bench accuracy` (and sweeps in accuracy mode)
    kSweep = 1u << 2,      ///< `bench sweep`, figures and bottleneck studies (they run sweeps)
    kBottleneck = 1u << 3, ///< `bench bottleneck`
    kCi = 1u << 4,         ///< `bench ci`
    kAuto = 1u << 5,       ///< rows of `-t auto`
    kFailed = 1u << 6,     ///< rows of a configuration that failed or was unsupported
    kInjected = 1u << 7,   ///< rows measured with SHADOWBENCH_INJECT set
    kImages = 1u << 8,     ///< rows of a run with --screenshot or --visibility
};

/// How a cell is written: free text, a whole number, or a csvNumber (fixed 4 decimals).
enum class ColumnType { Text, Integer, Number };

struct ColumnInfo {
    std::string_view name; ///< the header cell; a family holds a `<placeholder>`
    std::string_view unit; ///< "ms", "%", "px", "count", "1/s", "ratio", or "" for none
    ColumnType type;
    unsigned writers;         ///< ColumnWriter flags
    std::string_view meaning; ///< one line

    bool isFamily() const { return name.find('<') != std::string_view::npos; }
};

class ResultColumns {
public:
    /// Every column, measured-row columns first in ResultRow's order.
    static const std::vector<ColumnInfo>& all();
    /// The entry that `column` (a header cell) is, or a member of; nullptr for an unknown column.
    static const ColumnInfo* find(std::string_view column);
    /// Whether `column` is `info`'s name or, for a family, a member of it (non-empty placeholder).
    static bool matches(const ColumnInfo& info, std::string_view column);
    /// The entries with any of `writers`' flags, in table order.
    static std::vector<ColumnInfo> writtenBy(unsigned writers);
    /// docs/CSV.md's "written by" cell: the writers' names joined by ", " ("every run", "bench accuracy").
    static std::string writersText(unsigned writers);
    /// "text", "integer" or "number".
    static std::string_view typeName(ColumnType type);
};

/// The column names. Grouped as in the table; a family has a function that spells its members.
namespace col {
inline constexpr const char* kTimestamp = "timestamp";
inline constexpr const char* kGitCommit = "git_commit";
inline constexpr const char* kStatus = "status";
inline constexpr const char* kApi = "api";
inline constexpr const char* kApiVersion = "api_version";
inline constexpr const char* kRenderer = "renderer";
inline constexpr const char* kGlVersion = "gl_version";
inline constexpr const char* kGlVendor = "gl_vendor";
inline constexpr const char* kDriver = "driver";
inline constexpr const char* kDriverVersion = "driver_version";
inline constexpr const char* kBackend = "backend";
inline constexpr const char* kDevice = "device";
inline constexpr const char* kCpuModel = "cpu_model";
inline constexpr const char* kHwThreads = "hw_threads";
inline constexpr const char* kLpNumThreads = "lp_num_threads";
inline constexpr const char* kHost = "host";
inline constexpr const char* kSlurmJobId = "slurm_job_id";
inline constexpr const char* kSlurmArrayTaskId = "slurm_array_task_id";
inline constexpr const char* kScene = "scene";
inline constexpr const char* kSceneHash = "scene_hash";
inline constexpr const char* kSceneTriangles = "scene_triangles";
inline constexpr const char* kTechnique = "technique";
inline constexpr const char* kProperties = "properties";
inline constexpr const char* kPermutation = "permutation";
inline constexpr const char* kEffectsRequested = "effects_requested";
inline constexpr const char* kEffectsDelivered = "effects_delivered";
inline constexpr const char* kEffectsMissing = "effects_missing";
inline constexpr const char* kPassesSkipped = "passes_skipped";
inline constexpr const char* kInstances = "instances";
inline constexpr const char* kScale = "scale";
inline constexpr const char* kTessellation = "tessellation";
inline constexpr const char* kTessFactor = "tess_factor";
inline constexpr const char* kSeed = "seed";
inline constexpr const char* kModel = "model";
inline constexpr const char* kSubmit = "submit";
inline constexpr const char* kBackFaces = "back_faces";
inline constexpr const char* kLighting = "lighting";
inline constexpr const char* kCamera = "camera";
inline constexpr const char* kWidth = "width";
inline constexpr const char* kHeight = "height";
inline constexpr const char* kLights = "lights";
inline constexpr const char* kMotion = "motion";
inline constexpr const char* kPathFrames = "path_frames";
inline constexpr const char* kPathTime = "path_time";
inline constexpr const char* kFrames = "frames";
inline constexpr const char* kWarmup = "warmup";
inline constexpr const char* kSetupMs = "setup_ms";
inline constexpr const char* kWallMsMedian = "wall_ms_median";
inline constexpr const char* kWallMsP5 = "wall_ms_p5";
inline constexpr const char* kWallMsP95 = "wall_ms_p95";
inline constexpr const char* kWallMsP99 = "wall_ms_p99";
inline constexpr const char* kWallMsMean = "wall_ms_mean";
inline constexpr const char* kWallMsStddev = "wall_ms_stddev";
inline constexpr const char* kWallMsMad = "wall_ms_mad";
inline constexpr const char* kCpuSubmitMsMedian = "cpu_submit_ms_median";
inline constexpr const char* kCpuSubmitMsP5 = "cpu_submit_ms_p5";
inline constexpr const char* kCpuSubmitMsP95 = "cpu_submit_ms_p95";
inline constexpr const char* kCpuSubmitMsP99 = "cpu_submit_ms_p99";
inline constexpr const char* kCpuSubmitMsMean = "cpu_submit_ms_mean";
inline constexpr const char* kCpuSubmitMsStddev = "cpu_submit_ms_stddev";
inline constexpr const char* kCpuSubmitMsMad = "cpu_submit_ms_mad";
inline constexpr const char* kCpuPassMsMedian = "cpu_<pass>_ms_median";
inline constexpr const char* kMotionMsMedian = "motion_ms_median";
inline constexpr const char* kMotionMsP95 = "motion_ms_p95";
inline constexpr const char* kFpsMedian = "fps_median";
inline constexpr const char* kTimerVerdict = "timer_verdict";
inline constexpr const char* kTimerReason = "timer_reason";
inline constexpr const char* kGpuMsMedian = "gpu_ms_median";
inline constexpr const char* kGpuPassMsMedian = "gpu_<pass>_ms_median";
inline constexpr const char* kCounter = "counter_<name>";
inline constexpr const char* kLoadGlCalls = "load_gl_calls";
inline constexpr const char* kLoadVertices = "load_vertices";
inline constexpr const char* kLoadPrimitives = "load_primitives";
inline constexpr const char* kLoadClippedPrimitives = "load_clipped_primitives";
inline constexpr const char* kLoadFragments = "load_fragments";
inline constexpr const char* kWorkGlCalls = "work_<pass>_gl_calls";
inline constexpr const char* kWorkDraws = "work_<pass>_draws";
inline constexpr const char* kWorkTriangles = "work_<pass>_triangles";
inline constexpr const char* kWorkVertices = "work_<pass>_vertices";
inline constexpr const char* kWorkPrimitives = "work_<pass>_primitives";
inline constexpr const char* kWorkClippedPrimitives = "work_<pass>_clipped_primitives";
inline constexpr const char* kWorkFragments = "work_<pass>_fragments";
inline constexpr const char* kInjected = "injected";
inline constexpr const char* kAccLight = "acc_light";
inline constexpr const char* kAccReference = "acc_reference";
inline constexpr const char* kAccEvaluated = "acc_evaluated";
inline constexpr const char* kAccFalseShadowPct = "acc_false_shadow_pct";
inline constexpr const char* kAccFalseLightPct = "acc_false_light_pct";
inline constexpr const char* kAccWrongPct = "acc_wrong_pct";
inline constexpr const char* kAccFalseShadowNoEdgePct = "acc_false_shadow_no_edge_pct";
inline constexpr const char* kAccFalseLightNoEdgePct = "acc_false_light_no_edge_pct";
inline constexpr const char* kAccWrongNoEdgePct = "acc_wrong_no_edge_pct";
inline constexpr const char* kAccRmse = "acc_rmse";
inline constexpr const char* kAccMeanAbs = "acc_mean_abs";
inline constexpr const char* kAccMaxAbs = "acc_max_abs";
inline constexpr const char* kAccNan = "acc_nan";
inline constexpr const char* kAccInf = "acc_inf";
inline constexpr const char* kAccOutOfRange = "acc_out_of_range";
inline constexpr const char* kAccGainCamera = "acc_gain_camera";
inline constexpr const char* kAccGainLight = "acc_gain_light";
inline constexpr const char* kAccFlicker = "acc_flicker";
inline constexpr const char* kAccPathPoints = "acc_path_points";
inline constexpr const char* kAccPathWrongMeanPct = "acc_path_wrong_mean_pct";
inline constexpr const char* kAccPathWrongMaxPct = "acc_path_wrong_max_pct";
inline constexpr const char* kAccPathChangesTechnique = "acc_path_changes_technique";
inline constexpr const char* kAccPathChangesReference = "acc_path_changes_reference";
inline constexpr const char* kAccPathFalseChanges = "acc_path_false_changes";
inline constexpr const char* kAccPathFlicker = "acc_path_flicker";
inline constexpr const char* kAccTexelsPerPixelP50 = "acc_texels_per_pixel_p50";
inline constexpr const char* kAccTexelsPerPixelP5 = "acc_texels_per_pixel_p5";
inline constexpr const char* kAccTexelsPerPixelMin = "acc_texels_per_pixel_min";
inline constexpr const char* kRefSamples = "ref_samples";
inline constexpr const char* kRefNoiseBound = "ref_noise_bound";
inline constexpr const char* kRefRays = "ref_rays";
inline constexpr const char* kRefRaysPerSPerThread = "ref_rays_per_s_per_thread";
inline constexpr const char* kRefThreads = "ref_threads";
inline constexpr const char* kRepeat = "repeat";
inline constexpr const char* kBaseline = "baseline";
inline constexpr const char* kWallRatioVsBaseline = "wall_ratio_vs_baseline";
inline constexpr const char* kAutoChoice = "auto_choice";
inline constexpr const char* kAutoCandidates = "auto_candidates";
inline constexpr const char* kScreenshotFile = "screenshot_file";
inline constexpr const char* kVisibilityFile = "visibility_file";
inline constexpr const char* kError = "error";
inline constexpr const char* kTechniqueSpec = "technique_spec";
inline constexpr const char* kConfigIndex = "config_index";
inline constexpr const char* kConfigGroup = "config_group";
inline constexpr const char* kSweepId = "sweep_id";
inline constexpr const char* kSweepName = "sweep_name";
inline constexpr const char* kSweepConfigs = "sweep_configs";
inline constexpr const char* kShard = "shard";
inline constexpr const char* kPerturbation = "perturbation";
inline constexpr const char* kStudyBase = "study_base";
inline constexpr const char* kCiConfig = "ci_config";
inline constexpr const char* kCiSide = "ci_side";
inline constexpr const char* kCiRound = "ci_round";
inline constexpr const char* kCiRole = "ci_role";

/// The values of `status`: a measured row is ok; a sweep's or a run's row without numbers says why not.
inline constexpr const char* kStatusOk = "ok";
inline constexpr const char* kStatusFailed = "failed";
inline constexpr const char* kStatusUnsupported = "unsupported";

/// The member of `family` (a name with one `<placeholder>`) for `value`:
/// member(kGpuPassMsMedian, "depth") is "gpu_depth_ms_median", member(kCounter, "rays") "counter_rays".
std::string member(std::string_view family, std::string_view value);
} // namespace col

} // namespace sb
