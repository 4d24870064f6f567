#include "techniques/proxy/ProxyIndexGrid.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace sb {

namespace {
/// The 8 corners of the proxy's influence volume bounds: the world box of the unit cube through the
/// frame (which contains the unit sphere and cylinder too), grown by the offset.
std::array<glm::vec4, 8> influenceCorners(const ShadowProxy& p, float offset) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 c(p.frame * glm::vec4((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f,
                                              (i & 4) ? 1.0f : -1.0f, 1.0f));
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
    }
    lo -= glm::vec3(std::max(offset, 0.0f));
    hi += glm::vec3(std::max(offset, 0.0f));
    std::array<glm::vec4, 8> out;
    for (int i = 0; i < 8; ++i)
        out[size_t(i)] = glm::vec4((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z, 1.0f);
    return out;
}
} // namespace

void ProxyIndexGrid::build(const std::vector<ShadowProxy>& proxies, const glm::mat4& viewProj,
                           float proxyOffset, int cellsX, int cellsY, int capacity) {
    mCellsX = std::max(1, cellsX);
    mCellsY = std::max(1, cellsY);
    mCapacity = std::max(1, capacity);
    const size_t cells = size_t(mCellsX) * size_t(mCellsY);
    mIndices.assign(cells * size_t(mCapacity), 0u);
    mCounts.assign(cells, 0u);
    mVisible.clear();
    mOverflow = mEntries = 0;
    mMaxCount = 0;
    for (uint32_t i = 0; i < proxies.size(); ++i) {
        std::array<glm::vec4, 8> clip;
        const std::array<glm::vec4, 8> corners = influenceCorners(proxies[i], proxyOffset);
        for (size_t k = 0; k < 8; ++k) clip[k] = viewProj * corners[k];
        // Clipping (step 2): entirely outside one of the six clip-space planes -> not in view.
        bool outside = false;
        for (int axis = 0; axis < 3 && !outside; ++axis)
            for (float side : {-1.0f, 1.0f}) {
                bool all = true;
                for (const glm::vec4& c : clip) all = all && side * c[axis] > c.w;
                outside = outside || all;
            }
        if (outside) continue;
        // The cell rectangle: NDC bounds of the corners; a corner behind the eye makes it unbounded.
        glm::vec2 lo(1.0f), hi(-1.0f);
        bool behind = false;
        for (const glm::vec4& c : clip) {
            if (c.w <= 1e-6f) {
                behind = true;
                break;
            }
            const glm::vec2 ndc = glm::vec2(c) / c.w;
            lo = glm::min(lo, ndc);
            hi = glm::max(hi, ndc);
        }
        if (behind) lo = glm::vec2(-1.0f), hi = glm::vec2(1.0f);
        auto cellOf = [](float ndc, int n) {
            return std::clamp(int(std::floor((ndc * 0.5f + 0.5f) * float(n))), 0, n - 1);
        };
        const int x0 = cellOf(lo.x, mCellsX), x1 = cellOf(hi.x, mCellsX);
        const int y0 = cellOf(lo.y, mCellsY), y1 = cellOf(hi.y, mCellsY);
        const uint32_t index = uint32_t(mVisible.size());
        mVisible.push_back(i);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const size_t c = size_t(y) * size_t(mCellsX) + size_t(x);
                if (mCounts[c] == uint32_t(mCapacity)) {
                    ++mOverflow; // counted, reported, never silently lost
                    continue;
                }
                mIndices[c * size_t(mCapacity) + mCounts[c]++] = index + 1;
                ++mEntries;
                mMaxCount = std::max(mMaxCount, mCounts[c]);
            }
    }
}

} // namespace sb
