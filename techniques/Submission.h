#pragma once
// The submission axis (docs/ARCHITECTURE.md, "Submission"), named once for both APIs: the modes an
// application of each era fed geometry with, and what a submitter counts. GL has all four modes
// (techniques/gl/Submitter.h); Vulkan has retained and instanced (techniques/vulkan/VulkanSubmitter.h)
// and refuses the other two with exit 3.
#include <cstdint>
#include <optional>
#include <string>

#include "core/NameTable.h"
#include "scenes/DrawSet.h"

namespace sb {

enum class SubmitMode { Immediate, DisplayList, Retained, Instanced };
constexpr SubmitMode kAllSubmitModes[] = {SubmitMode::Immediate, SubmitMode::DisplayList,
                                          SubmitMode::Retained, SubmitMode::Instanced};

/// The submission modes in the order --help lists them (--submit, the CSV's `submit` column).
const NameTable<Named<SubmitMode>>& submitModes();
const char* submitModeName(SubmitMode m); ///< "immediate", "displaylist", "retained", "instanced"
std::optional<SubmitMode> parseSubmitMode(const std::string& name);

/// What a submitter sent since the last reset (counters of the CSV row, per frame and per pass).
struct SubmitStats {
    uint64_t drawCalls = 0;
    uint64_t triangles = 0;
    uint64_t instances = 0;
    /// API calls the application issued to draw (uniforms, binds, draws, and in immediate mode one call
    /// per vertex attribute; on Vulkan the commands recorded): the CPU-side load of the bottleneck study.
    /// Counted per draw from the mesh sizes, not per call, so counting costs nothing inside the
    /// immediate-mode loop.
    uint64_t glCalls = 0;

    SubmitStats& operator+=(const SubmitStats& o) {
        drawCalls += o.drawCalls;
        triangles += o.triangles;
        instances += o.instances;
        glCalls += o.glCalls;
        return *this;
    }
    friend SubmitStats operator+(SubmitStats a, const SubmitStats& b) { return a += b; }
    friend SubmitStats operator-(SubmitStats a, const SubmitStats& b) {
        return {a.drawCalls - b.drawCalls, a.triangles - b.triangles, a.instances - b.instances,
                a.glCalls - b.glCalls};
    }
};

} // namespace sb
