#pragma once
// What decides the code llvmpipe generates and the instructions it retires, recorded next to every
// instruction count (layer B) and wall time (layer C): numbers are compared only between runs with the
// same fingerprint. Layer A's exact work counters (draw calls, triangles) do not depend on the machine,
// so they compare across fingerprints.
//
// Why each field: the renderer string names the LLVM version and llvmpipe's vector width (128/256 bits,
// from the CPU features llvmpipe sees: under valgrind that is valgrind's synthetic CPUID, which has AVX2
// but no AVX-512); Mesa's version is its code; the CPU model names the CPU LLVM tunes for (its host
// CPU name decides instruction selection and scheduling); the CPU flags are the features llvmpipe
// checks; the driver's name and full version (the driver table's row columns, on both APIs) tell a
// self-built Mesa from the release of the same number; valgrind's version decides how instructions are
// counted; glibc's and the compiler's versions
// change the harness's and libc's own instructions; the pinned environment (LP_NUM_THREADS, the shader
// cache) changes what code runs.
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace sb {

/// The three layers of the performance gate.
enum class FingerprintUse { ExactCounters, Instructions, WallTime };

struct Fingerprint {
    std::string renderer;  ///< GL_RENDERER, "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string glVersion; ///< GL_VERSION, "4.5 (Compatibility Profile) Mesa 22.3.6"
    /// "22.3.6" from glVersion, or on Vulkan (no GL version) from the row's gl_vendor ("llvmpipe Mesa
    /// 25.0.7-2~bpo12+1 (LLVM 15.0.6)"); "" when neither names Mesa
    std::string mesaVersion;
    /// The row's `driver` ("system", "mesa-25.0.7", a prefix) and `driver_version`: "" in rows and records
    /// older than the driver table, and then not compared (mesaVersion still is)
    std::string driver, driverVersion;
    std::string llvmVersion; ///< "15.0.6" from the renderer, "" when it names no LLVM
    std::string vectorBits;  ///< "256" from the renderer, ""
    std::string backend;     ///< the bench's context backend ("egl-surfaceless")
    std::string cpuModel;    ///< /proc/cpuinfo "model name"
    std::string cpuFlags;    ///< the relevant flags present, space separated in kRelevantCpuFlags order
    std::string valgrind;    ///< "valgrind-3.19.0", "" for a run outside valgrind
    std::string glibc;       ///< gnu_get_libc_version()
    std::string compiler;    ///< the compiler that built this code (and the bench beside it)
    std::map<std::string, std::string> environment; ///< the pinned variables the child ran with

    /// The CPU flags llvmpipe and LLVM choose code paths by.
    static const std::vector<std::string>& relevantCpuFlags();

    /// From a bench row (its "renderer", "gl_version", "backend" columns), the machine (/proc/cpuinfo,
    /// glibc), `valgrindVersion` ("" outside valgrind) and the child's pinned `environment`.
    static Fingerprint capture(const nlohmann::json& row, const std::string& valgrindVersion,
                               const std::map<std::string, std::string>& environment);
    /// The relevant flags in /proc/cpuinfo's "flags" text.
    static std::string relevantFlags(const std::string& cpuinfoFlags);

    nlohmann::json toJson() const;
    /// The inverse of toJson; a missing field reads as "" (an older record); a non-string is BadInput.
    static Fingerprint fromJson(const nlohmann::json& j, const std::string& source);

    /// The fields (JSON names) whose values differ, "environment.LP_NUM_THREADS" for one variable;
    /// driver and driver_version only where both sides have them.
    std::vector<std::string> differences(const Fingerprint& other) const;
    /// differences(other) without those a driver A/B changes on purpose: the driver's own fields
    /// (renderer, gl_version, mesa_version, llvm_version, vector_bits, driver, driver_version) and the
    /// variables either side set (`tested`, e.g. LD_LIBRARY_PATH, LP_NUM_THREADS). What is left (the
    /// backend, the CPU, valgrind, glibc, the compiler, other variables) must match for the A/B to compare
    /// one driver's code against the other's.
    std::vector<std::string> differencesBesidesDriver(const Fingerprint& other,
                                                      const std::set<std::string>& tested) const;
    /// Throws Error (BadInput) naming every differing field when `layer` is Instructions or WallTime
    /// and the fingerprints differ; ExactCounters compare across machines.
    static void requireComparable(const Fingerprint& base, const Fingerprint& current, FingerprintUse layer);
};

} // namespace sb
