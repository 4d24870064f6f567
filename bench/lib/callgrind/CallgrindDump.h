#pragma once
// One callgrind output file (one dump) read into the numbers the instruction-count gate compares: the
// dump's trigger (the technique's name, from CALLGRIND_DUMP_STATS_AT in bench/lib/harness/Harness.cpp), its
// total instructions and the self instructions of every function.
//
// The format (valgrind manual, "Callgrind Format Specification"): a header of `key: value` lines
// (`events:`, `positions:`, `desc: Trigger: ...`, `summary:`/`totals:`), then cost lines
// `<subpositions> <event counts>` attributed to the current `ob=` (object), `fn=` (function). Names may be
// compressed: `fn=(12) name` defines id 12, a later `fn=(12)` refers to it; `ob=`/`cob=`, `fn=`/`cfn=`
// and `fl=`/`fi=`/`fe=`/`cfi=`/`cfl=` each share one table. The cost line after a `calls=` line is the
// call's inclusive cost, already counted in the callee, so it is not the caller's self cost. The dump's
// `totals:` (or `summary:`) is the sum of the self costs, which the parser checks.
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace sb {

/// Self instructions of one function in one object file.
struct FunctionIr {
    std::string object;   ///< `ob=` path, "???" for code in no object file (JIT code)
    std::string function; ///< `fn=` name, "0x..." where callgrind found no symbol
    uint64_t ir = 0;
};

struct CallgrindDump {
    int part = 0;         ///< `part:` (1, 2, ... per dump of one process)
    std::string trigger;  ///< `desc: Trigger:` text, e.g. "Client Request: shadowmap"
    std::string dumpName; ///< the name after "Client Request: ", "" for another trigger (program end)
    std::string command;  ///< `cmd:`
    uint64_t totalIr = 0; ///< `totals:` (or `summary:` when no totals line)
    std::vector<FunctionIr> functions; ///< one entry per (object, function), by Ir descending

    /// Parses one file; `source` names it in errors. Throws Error (Failure) on a malformed file, an
    /// `events:` line without Ir, or self costs that do not add up to the totals.
    static CallgrindDump parse(std::istream& in, const std::string& source);
    static CallgrindDump read(const std::string& path);
};

} // namespace sb
