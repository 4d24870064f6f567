#pragma once
// The depth range of the camera's view on GL, what `cascaded` fit=sdsm splits (Lauritzen, Salvi and Lefohn
// 2011, Sample Distribution Shadow Maps, I3D: z-partitions fitted to the min and max depth of the frame's
// own samples). It reduces the frame's view depth pre-pass (techniques/gl/ViewDepthGL.h, which the
// technique renders first) with a compute shader (GL 4.3; shaders/shadowmap/depth_range.comp, which the
// Vulkan form compiles too) into a two-uint buffer: the min and max window depth of the covered texels,
// exactly.
//
// Read-back with one frame of latency: frame k's reduction goes into one of two buffers with a fence, and
// frame k fits its cascades to frame k-1's answer, whose fence has long signalled (the harness waits for
// every frame), so reading it stalls nothing; a camera that moved since then is fitted to the depths it
// saw one frame ago (the padding of CascadeSplits::pad absorbs a small move). The first frame after a
// scene change has no earlier answer: it reads its own, waiting for the reduction, once.
#include <array>
#include <cstdint>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gl/ProgramCache.h"
#include "techniques/gl/ViewDepthGL.h"

namespace sb {

class DepthRangeGL {
public:
    DepthRangeGL() = default;
    ~DepthRangeGL() { release(); }
    DepthRangeGL(const DepthRangeGL&) = delete;
    DepthRangeGL& operator=(const DepthRangeGL&) = delete;

    /// The reduction's program.
    void compile(ProgramCache& programs);
    /// Forgets the answers of earlier frames (a new scene): the next frame reads its own.
    void reset() { mFrames = 0; }
    /// Reduces `depth` as this frame rendered it; returns the view-depth interval (x near, y far; x > y
    /// when no texel is covered) to fit this frame's cascades to: the last frame's, or this one's on the
    /// first frame.
    glm::vec2 run(const ViewDepthGL& depth);

    /// The window depths (x min, y max) of the answer run() returned last (x > y: none covered).
    glm::vec2 windowRange() const { return mWindow; }
    /// The window depths the reduction found in the last frame's pre-pass (waits for that reduction):
    /// what the tests compare with the texture read back.
    glm::vec2 latestWindowRange() const;

private:
    void allocate();
    void release();
    void reduce(const ViewDepthGL& depth, size_t buffer);
    /// Buffer `buffer`'s answer in window depths, once its fence has signalled.
    glm::vec2 readWindow(size_t buffer) const;

    const Program* mProgram = nullptr;
    std::array<GLuint, 2> mBuffers{}; ///< the reduction's answer, frame by frame alternately
    std::array<GLsync, 2> mFences{};  ///< signalled when that buffer's reduction has finished
    std::array<glm::mat4, 2> mProj{}; ///< the projection that buffer's depths were rendered with
    uint64_t mFrames = 0;             ///< frames run since the last reset
    glm::vec2 mWindow{1.0f, 0.0f};
};

} // namespace sb
