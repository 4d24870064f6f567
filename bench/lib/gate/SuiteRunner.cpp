#include "bench/lib/gate/SuiteRunner.h"

#include <algorithm>

#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/sweep/ChildProcess.h"
#include "core/Error.h"

namespace sb {

namespace {
/// The child's stderr tail on one line (messages are one line).
std::string oneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    std::string out;
    for (char c : text) out += c == '\n' ? std::string(" | ") : std::string(1, c);
    return out;
}
} // namespace

std::string CiSide::describe() const {
    std::string out = label;
    for (const auto& [k, v] : env) out += (out == label ? " (" : ", ") + k + "=" + v;
    return out == label ? out : out + ")";
}

std::vector<std::string> SuiteRunner::benchArgs(const CiSuite& suite, const CiConfig& config, int frames,
                                                int warmup) {
    std::vector<std::string> out;
    // A configuration's own option replaces the suite's (bench refuses an option given twice).
    const auto& own = config.args;
    for (size_t i = 0; i < suite.args.size(); ++i) {
        const std::string& a = suite.args[i];
        const bool hasValue = i + 1 < suite.args.size() && suite.args[i + 1].rfind("-", 0) != 0;
        if (a.rfind("-", 0) == 0 && std::find(own.begin(), own.end(), a) != own.end()) {
            i += hasValue ? 1 : 0;
            continue;
        }
        out.push_back(a);
    }
    out.insert(out.end(), own.begin(), own.end());
    for (const std::string& a : {std::string("--frames"), std::to_string(frames), std::string("--warmup"),
                                 std::to_string(warmup), std::string("--no-timer-check")})
        out.push_back(a);
    return out;
}

std::vector<std::string> SuiteRunner::argv(const CiSuite& suite, const CiConfig& config, const CiSide& side,
                                           const CiRunRequest& request) {
    std::vector<std::string> out = request.wrapper;
    out.push_back(side.bench);
    const auto args = benchArgs(suite, config, request.frames, request.warmup);
    out.insert(out.end(), args.begin(), args.end());
    for (const char* a : {"--format", "csv", "-q"}) out.push_back(a);
    return out;
}

CsvRow SuiteRunner::run(const CiSuite& suite, const CiConfig& config, const CiSide& side,
                        const CiRunRequest& request) {
    std::string text;
    auto env = side.env;
    env.insert(env.end(), request.env.begin(), request.env.end());
    const ChildExit exit = ChildProcess::run(argv(suite, config, side, request), env,
                                             [&](const std::string& line) { text += line + "\n"; });
    const std::string where = "ci config '" + config.name + "' (" + side.describe() + ")";
    if (!exit.ok())
        throw Error(where + ": bench ended with " + exit.describe() + ": " + oneLine(exit.stderrTail),
                    ExitCode::Failure);
    const CsvTable table = CsvWriter::parse(text, where);
    if (table.rows.size() != 1)
        throw Error(where + ": expected one row, got " + std::to_string(table.rows.size()),
                    ExitCode::Failure);
    CsvRow row{{col::kCiConfig, config.name}, {col::kCiSide, side.label}};
    for (size_t c = 0; c < table.header.size(); ++c) row.emplace_back(table.header[c], table.rows[0][c]);
    return row;
}

} // namespace sb
