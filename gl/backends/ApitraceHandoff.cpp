#include "gl/backends/ApitraceHandoff.h"

#include <link.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

namespace sb {
namespace {

constexpr const char* kGlxTracer = "glxtrace.so";
constexpr const char* kEglTracer = "egltrace.so";

/// The EGL tracer beside the loaded GLX tracer ("" when glxtrace.so is not loaded or has no sibling).
std::string loadedEglTracer() {
    std::string found;
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* data) {
            std::filesystem::path path(info->dlpi_name ? info->dlpi_name : "");
            if (path.filename() != kGlxTracer) return 0;
            std::filesystem::path egl = path.parent_path() / kEglTracer;
            std::error_code error;
            if (std::filesystem::is_regular_file(egl, error)) *static_cast<std::string*>(data) = egl.string();
            return 1;
        },
        &found);
    return found;
}

/// argv of this process from /proc/self/cmdline (NUL separated).
std::vector<std::string> ownArguments() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> args;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\0', start);
        if (end == std::string::npos) end = text.size();
        args.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return args;
}

} // namespace

std::string ApitraceHandoff::eglPreload(const std::string& preload) {
    // LD_PRELOAD is separated by spaces or colons and may hold ld.so's "$LIB" token (apitrace's does:
    // "/usr/bin/../$LIB/apitrace/wrappers/glxtrace.so"), so the entry is rewritten as text.
    std::string out;
    bool replaced = false;
    size_t start = 0;
    while (start <= preload.size()) {
        size_t end = preload.find_first_of(": ", start);
        if (end == std::string::npos) end = preload.size();
        std::string entry = preload.substr(start, end - start);
        size_t slash = entry.rfind('/');
        std::string name = slash == std::string::npos ? entry : entry.substr(slash + 1);
        if (name == kGlxTracer) {
            entry = entry.substr(0, slash == std::string::npos ? 0 : slash + 1) + kEglTracer;
            replaced = true;
        }
        if (!entry.empty()) out += (out.empty() ? "" : ":") + entry;
        start = end + 1;
    }
    return replaced ? out : "";
}

void ApitraceHandoff::toEglTracer() {
    const char* value = std::getenv("LD_PRELOAD");
    if (!value) return;
    const std::string preload = value; // setenv below may free what getenv returned
    std::string egl = eglPreload(preload);
    if (egl.empty() || loadedEglTracer().empty()) return;
    std::vector<std::string> args = ownArguments();
    if (args.empty()) return;
    std::cerr << "bench: apitrace's GLX tracer records no EGL call; restarting under its EGL tracer ("
              << kEglTracer << ", as with `apitrace trace --api egl`)" << std::endl;
    std::cout.flush();
    std::fflush(nullptr);
    setenv("LD_PRELOAD", egl.c_str(), 1);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv("/proc/self/exe", argv.data());
    // Still here: exec failed. Go on with the GLX tracer (an incomplete trace) rather than not at all.
    std::cerr << "bench: cannot restart under " << kEglTracer << " (" << std::strerror(errno) << ")"
              << std::endl;
    setenv("LD_PRELOAD", preload.c_str(), 1);
}

} // namespace sb
