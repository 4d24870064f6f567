#include "bench/lib/rows/SamplesFile.h"

#include "bench/lib/output/CsvNumber.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

namespace sb {

void SamplesFile::append(const std::string& path, const MeasuredHarness& harness, const RunResult& r) {
    const TimerVerdict& v = harness.timerVerdict();
    std::string prefix = v.checked && v.trusted ? "gpu_" : "timer_query_";
    std::vector<CsvRow> rows;
    rows.reserve(r.samples.size());
    for (size_t i = 0; i < r.samples.size(); ++i) {
        const FrameSample& s = r.samples[i];
        CsvRow row{{col::kTechnique, r.technique},
                   {col::kProperties, r.properties},
                   {col::kSubmit, submitModeName(harness.config().submit)},
                   {"frame", std::to_string(i)},
                   {"cpu_submit_ms", csvNumber(s.cpuSubmitMs)},
                   {"wall_ms", csvNumber(s.wallMs)},
                   {col::kTimerVerdict, v.label()},
                   {prefix + "total_ms", s.gpuTotalMs >= 0 ? csvNumber(s.gpuTotalMs) : ""}};
        for (const auto& [pass, ms] : s.gpuPassMs) row.emplace_back(prefix + pass + "_ms", csvNumber(ms));
        rows.push_back(std::move(row));
    }
    CsvWriter::appendRows(path, rows);
}

} // namespace sb
