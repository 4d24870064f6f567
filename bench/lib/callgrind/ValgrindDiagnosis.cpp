#include "bench/lib/callgrind/ValgrindDiagnosis.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string_view>
#include <sys/wait.h>
#include <vector>

namespace sb {

namespace {

/// The text after `marker` on the first line that holds it, trimmed; "" when no line does.
std::string after(const std::string& log, std::string_view marker) {
    const size_t at = log.find(marker);
    if (at == std::string::npos) return "";
    const size_t start = at + marker.size();
    std::string rest = log.substr(start, log.find('\n', start) - start);
    rest.erase(0, rest.find_first_not_of(" \t"));
    rest.erase(rest.find_last_not_of(" \t\r") + 1);
    return rest;
}

/// Valgrind's own lines start with "==PID=="; the program's lines do not.
bool isValgrindLine(const std::string& line) {
    if (line.size() < 5 || line.compare(0, 2, "==") != 0) return false;
    const size_t close = line.find("==", 2);
    return close != std::string::npos && close > 2 && line.find_first_not_of("0123456789", 2) == close;
}

/// The program's last non-empty line of its own (not valgrind's, not VEX's).
std::string lastProgramLine(const std::string& log) {
    std::istringstream in(log);
    std::string last;
    for (std::string line; std::getline(in, line);) {
        if (line.find_first_not_of(" \t\r") == std::string::npos || isValgrindLine(line) ||
            line.rfind("vex ", 0) == 0)
            continue;
        last = line;
    }
    last.erase(last.find_last_not_of(" \t\r") + 1);
    return last.size() > 200 ? last.substr(0, 200) + "..." : last;
}

/// "0xF 0x1 0xF9 0x48" -> {0x0F, 0x01, 0xF9, 0x48}.
std::vector<int> parseBytes(const std::string& text) {
    std::vector<int> bytes;
    std::istringstream in(text);
    for (std::string word; in >> word;) {
        if (word.rfind("0x", 0) != 0) break;
        bytes.push_back(int(std::strtol(word.c_str() + 2, nullptr, 16)));
    }
    return bytes;
}

std::string hexBytes(const std::vector<int>& bytes, size_t count) {
    std::string out;
    char b[4];
    for (size_t i = 0; i < bytes.size() && i < count; ++i) {
        std::snprintf(b, sizeof b, "%02X", unsigned(bytes[i]));
        out += (out.empty() ? "" : " ") + std::string(b);
    }
    return out;
}

/// "at 0x2251D522: hwy::platform::TimerResolution() (in /usr/lib/.../libhwy.so.1.0.3)" ->
/// "hwy::platform::TimerResolution() (libhwy.so.1.0.3)"; "" when the log has no frame.
std::string firstFrame(const std::string& log) {
    std::string frame = after(log, "   at 0x");
    const size_t colon = frame.find(": ");
    if (colon == std::string::npos) return "";
    frame = frame.substr(colon + 2);
    const size_t in = frame.rfind("(in ");
    if (in != std::string::npos) {
        std::string object = frame.substr(in + 4);
        if (!object.empty() && object.back() == ')') object.pop_back();
        object = object.substr(object.rfind('/') + 1);
        frame = frame.substr(0, in) + "(" + object + ")";
    }
    return frame;
}

std::string signalName(int signal) {
    switch (signal) {
    case SIGILL:
        return "SIGILL";
    case SIGSEGV:
        return "SIGSEGV";
    case SIGBUS:
        return "SIGBUS";
    case SIGABRT:
        return "SIGABRT";
    case SIGFPE:
        return "SIGFPE";
    case SIGKILL:
        return "SIGKILL";
    case SIGTERM:
        return "SIGTERM";
    default:
        return "signal " + std::to_string(signal);
    }
}

} // namespace

std::string ValgrindDiagnosis::instructionName(const std::string& text) {
    const std::vector<int> b = parseBytes(text);
    size_t i = 0;
    while (i < b.size() && (b[i] == 0x66 || b[i] == 0xF2 || b[i] == 0xF3)) ++i; // legacy prefixes
    if (i < b.size() && (b[i] & 0xF0) == 0x40) ++i;                             // REX
    if (i >= b.size()) return "";
    if (b[i] == 0x62) return "an AVX-512 (EVEX-encoded) instruction";
    if (i + 2 < b.size() && b[i] == 0x0F && b[i + 1] == 0x01 && b[i + 2] == 0xF9) return "RDTSCP";
    if (i + 2 < b.size() && b[i] == 0x0F && b[i + 1] == 0xC7 && ((b[i + 2] >> 3) & 7) == 7)
        return i > 0 && b[i - 1] == 0xF3 ? "RDPID" : "RDSEED";
    if (i + 2 < b.size() && b[i] == 0x0F && b[i + 1] == 0xC7 && ((b[i + 2] >> 3) & 7) == 6) return "RDRAND";
    return "";
}

ValgrindDiagnosis ValgrindDiagnosis::of(int status, const std::string& log) {
    ValgrindDiagnosis d;
    const std::string unhandled = after(log, "unhandled instruction bytes:");
    if (!unhandled.empty()) {
        // VEX met an instruction it cannot translate; valgrind then raises SIGILL in the program.
        d.unsupported = true;
        const std::vector<int> bytes = parseBytes(unhandled);
        const std::string name = instructionName(unhandled);
        const std::string address = after(log, "Unrecognised instruction at address");
        const std::string frame = firstFrame(log);
        d.reason = "killed by SIGILL: valgrind cannot execute the instruction";
        if (!address.empty()) d.reason += " at " + address.substr(0, address.find_last_not_of('.') + 1);
        d.reason += " (bytes " + hexBytes(bytes, 3) + (name.empty() ? "" : ", " + name) + ")";
        if (!frame.empty()) d.reason += " in " + frame;
        if (log.find("_dl_init") != std::string::npos)
            d.reason += ", while a shared library was being loaded (before main)";
        return d;
    }
    if (WIFSIGNALED(status)) {
        d.reason = "killed by " + signalName(WTERMSIG(status));
        const std::string frame = firstFrame(log);
        if (!frame.empty()) d.reason += " in " + frame;
        return d;
    }
    if (WIFEXITED(status)) {
        const int code = WEXITSTATUS(status);
        // The program's own exit 3 is its own "this machine lacks it" (a GL capability, a device).
        d.unsupported = code == 3;
        d.reason = "exit " + std::to_string(code);
        const std::string line = lastProgramLine(log);
        if (!line.empty()) d.reason += ": " + line;
        return d;
    }
    d.reason = "did not start (wait status " + std::to_string(status) + ")";
    return d;
}

} // namespace sb
