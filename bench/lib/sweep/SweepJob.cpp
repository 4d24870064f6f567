#include "bench/lib/sweep/SweepJob.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/Error.h"

namespace sb {

namespace {
constexpr const char* kPrefix = "@sb ";

nlohmann::json toJson(const KeyValues& kv) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& [k, v] : kv) out.push_back({k, v});
    return out;
}

KeyValues keyValues(const nlohmann::json& j) {
    KeyValues out;
    for (const auto& pair : j) out.emplace_back(pair.at(0).get<std::string>(), pair.at(1).get<std::string>());
    return out;
}
} // namespace

void SweepJob::save(const std::string& path) const {
    nlohmann::json j;
    j["mode"] = SweepPlan::modeName(mode);
    j["args"] = args;
    j["csv"] = csvPath;
    j["tags"] = toJson(tags);
    j["baseline"] = baseline;
    if (timer)
        j["timer"] = {{"checked", timer->checked}, {"trusted", timer->trusted}, {"reason", timer->reason}};
    for (const auto& [round, wall] : baselineWalls) j["baseline_walls"].push_back({round, wall});
    j["replaces_failed"] = replacesFailed;
    for (const PlannedRow& r : rows)
        j["rows"].push_back({{"index", r.index}, {"technique", r.technique}, {"round", r.round}});
    std::ofstream out(path);
    out << j.dump(1);
    if (!out.flush()) throw Error("cannot write sweep job file '" + path + "'", ExitCode::Failure);
}

SweepJob SweepJob::load(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("sweep-worker: cannot read job file '" + path + "'");
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        SweepJob job;
        job.mode = j.at("mode") == "accuracy" ? SweepPlan::Mode::Accuracy : SweepPlan::Mode::Measure;
        job.args = j.at("args").get<std::vector<std::string>>();
        job.csvPath = j.at("csv").get<std::string>();
        job.tags = keyValues(j.at("tags"));
        job.baseline = j.at("baseline").get<std::string>();
        if (j.contains("timer")) {
            TimerVerdict v;
            v.checked = j["timer"].at("checked").get<bool>();
            v.trusted = j["timer"].at("trusted").get<bool>();
            v.reason = j["timer"].at("reason").get<std::string>();
            job.timer = v;
        }
        if (j.contains("baseline_walls"))
            for (const auto& bw : j["baseline_walls"])
                job.baselineWalls[bw.at(0).get<int>()] = bw.at(1).get<double>();
        if (j.contains("replaces_failed")) job.replacesFailed = j["replaces_failed"].get<std::set<size_t>>();
        for (const auto& r : j.at("rows"))
            job.rows.push_back({r.at("index").get<size_t>(), r.at("technique").get<std::string>(),
                                r.at("round").get<int>()});
        return job;
    } catch (const nlohmann::json::exception& e) {
        throw Error("sweep-worker: job file '" + path + "' is malformed: " + e.what());
    }
}

std::string WorkerMessage::begin(size_t index) {
    return std::string(kPrefix) + "begin " + std::to_string(index);
}

std::string WorkerMessage::done(size_t index, double wallMs) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", wallMs);
    return std::string(kPrefix) + "done " + std::to_string(index) + " " + buf;
}

std::string WorkerMessage::failed(size_t index, int exitCode, const std::string& message) {
    std::string oneLine = message;
    for (char& c : oneLine)
        if (c == '\n' || c == '\r') c = ' ';
    return std::string(kPrefix) + "failed " + std::to_string(index) + " " + std::to_string(exitCode) + " " +
           oneLine;
}

std::optional<WorkerMessage> WorkerMessage::parse(const std::string& line) {
    if (line.rfind(kPrefix, 0) != 0) return std::nullopt;
    std::istringstream in(line.substr(4));
    std::string kind;
    WorkerMessage m{};
    if (!(in >> kind >> m.index)) return std::nullopt;
    if (kind == "begin") {
        m.kind = Kind::Begin;
    } else if (kind == "done") {
        m.kind = Kind::Done;
        in >> m.wallMs;
    } else if (kind == "failed") {
        m.kind = Kind::Failed;
        in >> m.exitCode;
        std::getline(in >> std::ws, m.message);
    } else {
        return std::nullopt;
    }
    return m;
}

} // namespace sb
