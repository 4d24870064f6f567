#include "bench/lib/bisect/BisectSignal.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "bench/lib/callgrind/InstructionCount.h"
#include "bench/lib/gate/SuiteRunner.h"
#include "bench/lib/gate/WorkGate.h"
#include "core/Error.h"
#include "core/Fnv1a.h"
#include "core/PngFile.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

/// A count cell as a number; an absent or empty cell counts as 0, as in layer A (a pass that appeared).
double number(const SignalValue& v, const std::string& key) {
    const auto it = v.find(key);
    return it == v.end() || it->second.empty() ? 0.0 : std::strtod(it->second.c_str(), nullptr);
}

std::string cellOr0(const SignalValue& v, const std::string& key) {
    const auto it = v.find(key);
    return it == v.end() || it->second.empty() ? "0" : it->second;
}

} // namespace

BisectSignal::Kind BisectSignal::parse(const std::string& name) {
    for (Kind k : {Kind::Work, Kind::Instructions, Kind::Image})
        if (name == BisectSignal::name(k)) return k;
    throw Error("--signal " + name + ": work, instructions or image", ExitCode::BadInput);
}

const char* BisectSignal::name(Kind kind) {
    switch (kind) {
    case Kind::Work:
        return "work";
    case Kind::Instructions:
        return "instructions";
    case Kind::Image:
        return "image";
    }
    return "?";
}

BisectSignal::BisectSignal(Kind kind, CiSuite suite, CiConfig config, double irThreshold)
    : mKind(kind), mSuite(std::move(suite)), mConfig(std::move(config)), mIrThreshold(irThreshold) {}

void BisectSignal::requireTools() const {
    if (mKind == Kind::Instructions && !InstructionCount::valgrindAvailable())
        throw Error("--signal instructions needs valgrind (scripts/install-deps.sh installs it)",
                    ExitCode::Unsupported);
}

std::vector<std::string> BisectSignal::benchArgs() const {
    const CiLayerRuns& runs = mKind == Kind::Instructions ? mSuite.instructions : mSuite.work;
    return SuiteRunner::benchArgs(mSuite, mConfig, runs.frames, runs.warmup);
}

SignalValue BisectSignal::measure(const std::string& bench, const std::string& workDir) const {
    fs::create_directories(workDir);
    switch (mKind) {
    case Kind::Work:
        return measureWork(bench);
    case Kind::Instructions:
        return measureInstructions(bench, workDir);
    case Kind::Image:
        return measureImage(bench, workDir);
    }
    return {};
}

SignalValue BisectSignal::measureWork(const std::string& bench) const {
    const CsvRow row = SuiteRunner::run(mSuite, mConfig, {"commit", bench, {}},
                                        {mSuite.work.frames, mSuite.work.warmup, {}, {}});
    SignalValue out;
    for (const auto& [column, cell] : row)
        if (WorkGate::isWorkColumn(column)) out[column] = cell;
    return out;
}

SignalValue BisectSignal::measureInstructions(const std::string& bench, const std::string& workDir) const {
    InstructionCount::Options o;
    o.bench = bench;
    o.benchArgs = benchArgs();
    o.outDir = workDir;
    const InstructionRun run = InstructionCount(o).run();
    if (run.techniques.size() != 1)
        throw Error("expected one technique under valgrind, got " + std::to_string(run.techniques.size()),
                    ExitCode::Failure);
    char text[64];
    std::snprintf(text, sizeof text, "%.1f", run.techniques[0].irPerFrame);
    return {{"ir_per_frame", text}};
}

SignalValue BisectSignal::measureImage(const std::string& bench, const std::string& workDir) const {
    const std::string png = (fs::path(workDir) / "screenshot.png").string();
    std::error_code ec;
    fs::remove(png, ec); // a run that writes no image must not be judged by the last commit's
    CiConfig withShot = mConfig;
    withShot.args.insert(withShot.args.end(), {"--screenshot", png});
    SuiteRunner::run(mSuite, withShot, {"commit", bench, {}},
                     {mSuite.work.frames, mSuite.work.warmup, {}, {}});
    const PngImage image = PngFile::read8(png);
    Fnv1a hash;
    hash.value(image.width);
    hash.value(image.height);
    hash.value(image.channels);
    hash.vector(image.pixels);
    char text[32];
    std::snprintf(text, sizeof text, "%016llx", (unsigned long long)hash.result());
    return {{"image_fnv1a", text},
            {"image_size", std::to_string(image.width) + "x" + std::to_string(image.height)}};
}

std::vector<std::string> BisectSignal::differences(const SignalValue& base, const SignalValue& head) const {
    std::vector<std::string> out;
    if (mKind == Kind::Instructions) {
        const double b = number(base, "ir_per_frame"), h = number(head, "ir_per_frame");
        const double change = b > 0 ? (h - b) / b : (h > 0 ? 1.0 : 0.0);
        char text[160];
        std::snprintf(text, sizeof text, "ir_per_frame %.1f -> %.1f (%+.3f%%, threshold %.3f%%)", b, h,
                      100.0 * change, 100.0 * mIrThreshold);
        if (std::abs(change) > mIrThreshold) out.push_back(text);
        return out;
    }
    std::map<std::string, bool> keys;
    for (const auto& [k, v] : base) keys[k] = true;
    for (const auto& [k, v] : head) keys[k] = true;
    for (const auto& [k, unused] : keys) {
        const bool same =
            mKind == Kind::Work ? number(base, k) == number(head, k) : cellOr0(base, k) == cellOr0(head, k);
        if (!same) out.push_back(k + " " + cellOr0(base, k) + " -> " + cellOr0(head, k));
    }
    return out;
}

} // namespace sb
