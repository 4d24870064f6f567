#include "bench/lib/callgrind/CallgrindDump.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

#include "core/Error.h"

namespace sb {

namespace {

/// One table of compressed names: "(id) name" defines, "(id)" refers, a plain "name" is itself.
class NameTable {
public:
    std::string resolve(const std::string& value, const std::string& where) {
        if (value.empty() || value[0] != '(') return value;
        const size_t close = value.find(')');
        if (close == std::string::npos)
            throw Error(where + ": unterminated compressed name", ExitCode::Failure);
        const std::string id = value.substr(1, close - 1);
        size_t nameStart = close + 1;
        while (nameStart < value.size() && value[nameStart] == ' ') ++nameStart;
        if (nameStart < value.size()) return mNames[id] = value.substr(nameStart);
        auto it = mNames.find(id);
        if (it == mNames.end())
            throw Error(where + ": compressed name (" + id + ") used before it was defined",
                        ExitCode::Failure);
        return it->second;
    }

private:
    std::unordered_map<std::string, std::string> mNames;
};

bool startsWith(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

std::vector<std::string> splitWords(const std::string& s) {
    std::istringstream in(s);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

uint64_t parseCount(const std::string& word, const std::string& where) {
    uint64_t v = 0;
    auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
    if (ec != std::errc() || ptr != word.data() + word.size())
        throw Error(where + ": '" + word + "' is not an event count", ExitCode::Failure);
    return v;
}

} // namespace

CallgrindDump CallgrindDump::parse(std::istream& in, const std::string& source) {
    CallgrindDump dump;
    NameTable objects, files, functions;
    std::string object, function;
    std::map<std::pair<std::string, std::string>, uint64_t> self;
    int positions = 1, irIndex = -1;
    bool haveTotals = false, nextIsCallCost = false;
    uint64_t summary = 0, summed = 0;
    int lineNo = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNo;
        const std::string where = source + ":" + std::to_string(lineNo);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        const char c = line[0];
        const bool costLine = (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '*';
        if (costLine) {
            if (irIndex < 0)
                throw Error(where + ": cost line before an events: line with Ir", ExitCode::Failure);
            const std::vector<std::string> words = splitWords(line);
            // Counts missing at the end of a line are zero (the format omits trailing zeros).
            const size_t at = size_t(positions + irIndex);
            const uint64_t ir = at < words.size() ? parseCount(words[at], where) : 0;
            if (nextIsCallCost) {
                nextIsCallCost = false; // inclusive cost of the call, the callee's self cost holds it
                continue;
            }
            self[{object, function}] += ir;
            summed += ir;
            continue;
        }
        const size_t eq = line.find('=');
        const size_t colon = line.find(':');
        if (eq != std::string::npos && (colon == std::string::npos || eq < colon)) {
            const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
            if (key == "ob")
                object = objects.resolve(value, where);
            else if (key == "cob")
                objects.resolve(value, where);
            else if (key == "fn")
                function = functions.resolve(value, where);
            else if (key == "cfn")
                functions.resolve(value, where);
            else if (key == "fl" || key == "fi" || key == "fe" || key == "cfi" || key == "cfl")
                files.resolve(value, where);
            else if (key == "calls")
                nextIsCallCost = true;
            // jump=/jcnd= (only with --collect-jumps) carry no instruction cost.
            continue;
        }
        if (colon == std::string::npos)
            throw Error(where + ": not a callgrind line: " + line, ExitCode::Failure);
        const std::string key = line.substr(0, colon);
        std::string value = line.substr(colon + 1);
        value.erase(0, value.find_first_not_of(' '));
        if (key == "part")
            dump.part = std::atoi(value.c_str());
        else if (key == "cmd")
            dump.command = value;
        else if (key == "positions")
            positions = int(splitWords(value).size());
        else if (key == "events") {
            const std::vector<std::string> events = splitWords(value);
            auto it = std::find(events.begin(), events.end(), "Ir");
            if (it == events.end())
                throw Error(where + ": events: has no Ir (" + value + ")", ExitCode::Failure);
            irIndex = int(it - events.begin());
        } else if (key == "summary" || key == "totals") {
            const std::vector<std::string> words = splitWords(value);
            const uint64_t ir =
                irIndex >= 0 && size_t(irIndex) < words.size() ? parseCount(words[irIndex], where) : 0;
            if (key == "totals") {
                dump.totalIr = ir;
                haveTotals = true;
            } else {
                summary = ir;
            }
        } else if (key == "desc" && startsWith(value, "Trigger:")) {
            dump.trigger = value.substr(value.find_first_not_of(' ', 8));
            const std::string request = "Client Request: ";
            if (startsWith(dump.trigger, request.c_str()))
                dump.dumpName = dump.trigger.substr(request.size());
        }
    }
    if (irIndex < 0) throw Error(source + ": no events: line (not a callgrind file?)", ExitCode::Failure);
    // callgrind 3.19 writes "summary: 0" at the top of a client-request dump and the real sum in totals:.
    if (!haveTotals) dump.totalIr = summary;
    if (summed != dump.totalIr)
        throw Error(source + ": self costs add up to " + std::to_string(summed) + " Ir, totals say " +
                        std::to_string(dump.totalIr),
                    ExitCode::Failure);
    for (auto& [key, ir] : self)
        if (ir > 0) dump.functions.push_back({key.first, key.second, ir});
    std::stable_sort(dump.functions.begin(), dump.functions.end(),
                     [](const FunctionIr& a, const FunctionIr& b) { return a.ir > b.ir; });
    return dump;
}

CallgrindDump CallgrindDump::read(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot read callgrind output", ExitCode::Failure);
    return parse(in, path);
}

} // namespace sb
