#include "bench/lib/bisect/Bisection.h"

#include <chrono>
#include <csignal>
#include <filesystem>
#include <memory>

#include "bench/lib/output/ProgressBar.h"
#include "core/Error.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string shortHash(const std::string& commit) {
    return commit.substr(0, 12);
}

/// The progress line of one finished step.
std::string stepLine(const BisectStep& s) {
    std::string line = shortHash(s.commit) + " " + s.subject.substr(0, 60) + ": " + s.verdict + " (build " +
                       ProgressBar::formatDuration(s.buildSeconds) + ", run " +
                       ProgressBar::formatDuration(s.runSeconds) + ")";
    if (!s.reason.empty()) line += ": " + s.reason.substr(0, 200);
    return line;
}

void checkInterrupt(const volatile std::sig_atomic_t& interrupted) {
    if (interrupted) throw Error("bisect: interrupted", ExitCode::Failure);
}

} // namespace

const BisectStep* BisectResult::step(const std::string& commit) const {
    for (const BisectStep& s : steps)
        if (s.commit == commit) return &s;
    return nullptr;
}

nlohmann::json BisectResult::toJson(const std::string& signal,
                                    const std::vector<std::string>& benchArgs) const {
    nlohmann::json j;
    j["good"] = good;
    j["bad"] = bad;
    j["signal"] = signal;
    j["bench_args"] = benchArgs;
    j["commits"] = commits.size();
    j["result"] = outcome.kind == BisectOutcome::Kind::Found      ? "found"
                  : outcome.kind == BisectOutcome::Kind::NotFound ? "not_found"
                                                                  : "undecided";
    if (outcome.kind == BisectOutcome::Kind::Found) {
        const BisectStep* s = step(commits[outcome.firstBad]);
        j["first_changed"] = {{"commit", s->commit},           {"subject", s->subject},
                              {"index", outcome.firstBad + 1}, {"changes", s->changes},
                              {"before", steps.front().value}, {"after", s->value}};
    }
    for (size_t i : outcome.candidates) j["candidates"].push_back(commits[i]);
    if (outcome.kind == BisectOutcome::Kind::Undecided) j["may_be_none"] = outcome.mayBeNone;
    j["builds"] = steps.size();
    j["max_builds_without_skips"] = BisectSearch::maxEvaluations(commits.size()) + 1;
    j["steps"] = nlohmann::json::array();
    for (const BisectStep& s : steps) {
        nlohmann::json step = {{"commit", s.commit},
                               {"subject", s.subject},
                               {"verdict", s.verdict},
                               {"build_s", s.buildSeconds},
                               {"run_s", s.runSeconds}};
        if (!s.reason.empty()) step["reason"] = s.reason;
        if (!s.changes.empty()) step["changes"] = s.changes;
        j["steps"].push_back(step);
    }
    j["total_s"] = totalSeconds;
    j["build_folder"] = buildFolder;
    return j;
}

Bisection::Bisection(const GitRepo& repo, BisectWorkspace& workspace, const BisectSignal& signal, int jobs)
    : mRepo(repo), mWorkspace(workspace), mSignal(signal), mJobs(jobs) {}

BisectStep Bisection::measure(const std::string& commit, const volatile std::sig_atomic_t& interrupted) {
    BisectStep s{commit, mRepo.subject(commit), "", 0, 0, "", {}, {}};
    try {
        mWorkspace.checkout(commit);
        s.buildSeconds = mWorkspace.build(mJobs);
        checkInterrupt(interrupted);
        const auto start = std::chrono::steady_clock::now();
        s.value = mSignal.measure(mWorkspace.benchPath(),
                                  (fs::path(mWorkspace.folder()) / "runs" / shortHash(commit)).string());
        s.runSeconds = secondsSince(start);
    } catch (const Error& e) {
        checkInterrupt(interrupted); // an interrupted child fails too: that is not a skip
        s.verdict = "skipped";
        s.reason = e.what();
    }
    return s;
}

BisectResult Bisection::run(const std::string& good, const std::string& bad,
                            const volatile std::sig_atomic_t& interrupted) {
    const auto start = std::chrono::steady_clock::now();
    BisectResult r;
    r.good = good;
    r.bad = bad;
    r.commits = mRepo.firstParentRange(good, bad);
    r.buildFolder = mWorkspace.buildFolder();
    const BisectSearch search(r.commits.size());
    const size_t most = BisectSearch::maxEvaluations(r.commits.size()) + 1; // GOOD and the probes
    std::fprintf(stderr,
                 "bisect: %zu commits after GOOD; at most %zu builds (GOOD and ceil(log2(%zu + 1)) probes) "
                 "unless some are skipped; building in %s%s\n",
                 r.commits.size(), most, r.commits.size(), r.buildFolder.c_str(),
                 mWorkspace.usesCcache() ? " with ccache" : "");
    ProgressBar bar(stderr, most, 0);
    auto report = [&](const BisectStep& s) {
        // Skips can take the search past the bar's total: those steps print a plain line.
        if (r.steps.size() <= most)
            bar.finished(stepLine(s), s.verdict != "skipped");
        else
            std::fprintf(stderr, "%s %s\n", s.verdict == "skipped" ? "FAILED" : "ok    ",
                         stepLine(s).c_str());
    };
    bar.setCurrent("GOOD " + shortHash(good) + ": building");
    r.steps.push_back(measure(good, interrupted));
    if (r.steps.back().verdict == "skipped") {
        bar.close();
        throw Error("bisect: GOOD " + shortHash(good) + " gives no reference: " + r.steps.back().reason,
                    ExitCode::Failure);
    }
    r.steps.back().verdict = "reference";
    report(r.steps.back());
    const SignalValue reference = r.steps.front().value;
    r.outcome = search.run([&](size_t i) {
        bar.setCurrent(shortHash(r.commits[i]) + ": building and running");
        BisectStep s = measure(r.commits[i], interrupted);
        BisectVerdict v = BisectVerdict::Skip;
        if (s.verdict != "skipped") {
            s.changes = mSignal.differences(reference, s.value);
            s.verdict = s.changes.empty() ? "same" : "changed";
            v = s.changes.empty() ? BisectVerdict::Good : BisectVerdict::Bad;
        }
        r.steps.push_back(s);
        report(s);
        return v;
    });
    bar.close();
    r.totalSeconds = secondsSince(start);
    return r;
}

} // namespace sb
