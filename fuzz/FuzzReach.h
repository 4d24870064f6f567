#pragma once
// The reach check of every fuzz target (scripts/fuzz.sh): a fuzzer that never gets past the parser's
// first "expected an object" would report hours of executions and prove nothing, so the script runs
// each target once on a valid seed and once on a broken input and checks what the parser made of them.
//
// A target reports the outcome of each input with reached(). Normally that does nothing; with the
// environment variable SB_FUZZ_EXPECT set to "parsed" or "rejected" (and the target run on single
// files, libFuzzer's run-inputs mode), it prints the outcome and aborts when it is not the one expected,
// so the run exits non-zero. Any other exception than sb::Error, and any sanitizer report, is a crash
// in either mode: a parser of user input answers bad input with sb::Error (exit 2), nothing else.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace sb::fuzz {

enum class Outcome { Parsed, Rejected };

/// Reports what the parser made of one input; `detail` is the error message (Rejected) or a short
/// description of what was parsed. See the header comment for what it checks.
inline void reached(Outcome outcome, const std::string& detail) {
    static const char* const expected = std::getenv("SB_FUZZ_EXPECT");
    if (!expected || !*expected) return;
    const char* got = outcome == Outcome::Parsed ? "parsed" : "rejected";
    std::fprintf(stderr, "reach: %s: %s\n", got, detail.substr(0, 300).c_str());
    if (std::strcmp(expected, got) != 0) {
        std::fprintf(stderr, "reach: FAILED: expected the input to be %s\n", expected);
        std::abort();
    }
}

/// The bytes of one input as text (the parsers all take std::string).
inline std::string text(const unsigned char* data, size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

/// Aborts with `what` when an invariant the parser promises does not hold (a round trip): libFuzzer
/// then keeps the input as a crash.
inline void require(bool condition, const std::string& what) {
    if (condition) return;
    std::fprintf(stderr, "fuzz invariant broken: %s\n", what.substr(0, 2000).c_str());
    std::abort();
}

} // namespace sb::fuzz
