#include "bench/lib/measure/Measurement.h"

#include "bench/lib/output/CsvNumber.h"
#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/rows/ResultRow.h"

namespace sb {

Measurement Measurement::take(MeasuredHarness& harness, Technique& technique, AccuracyEvaluator* evaluator,
                              const AccuracyOptions& options, Environment& env) {
    Measurement m;
    m.run = harness.measure(technique);
    if (evaluator && evaluator->rendersWith(harness)) {
        m.accuracy = evaluator->evaluate(technique, options);
    } else if (evaluator) {
        AccuracyOptions visibilityOnly = options;
        visibilityOnly.stability = false;
        if (harness.moving()) { // the frame evaluate() judges on GL: the first of the path
            harness.seekPath(0);
            harness.renderFrame(technique);
        }
        m.accuracy = evaluator->evaluateVisibility(harness.readVisibility(), visibilityOnly);
    }
    env.timestamp = Environment::nowIso8601();
    m.row = ResultRow::build(harness, m.run, env);
    if (m.accuracy) m.accuracy->appendColumns(m.row);
    return m;
}

void Measurement::addRound(int round, const std::string& baseline, std::optional<double> baselineWallMs) {
    row.emplace_back(col::kRepeat, std::to_string(round));
    row.emplace_back(col::kBaseline, baseline);
    const bool ratio = baselineWallMs && *baselineWallMs > 0.0;
    row.emplace_back(col::kWallRatioVsBaseline, ratio ? csvNumber(run.wall.median / *baselineWallMs) : "");
}

} // namespace sb
