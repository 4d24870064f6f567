#include "techniques/virtual/VirtualMaps.h"

#include <string>

#include "core/Error.h"
#include "scenes/LightFit.h"
#include "scenes/Motion.h"
#include "shading/ShaderLimits.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/virtual/Virtual.h"

namespace sb {

glm::mat4 PageRun::crop(const PageGeometry& g) const {
    const float n = float(g.pagesPerSide(level));
    const glm::vec2 lo(2.0f * float(first.x) / n - 1.0f, 2.0f * float(first.y) / n - 1.0f);
    const glm::vec2 hi(2.0f * float(first.x + count) / n - 1.0f, 2.0f * float(first.y + 1) / n - 1.0f);
    glm::mat4 m(1.0f);
    m[0][0] = 2.0f / (hi.x - lo.x);
    m[1][1] = 2.0f / (hi.y - lo.y);
    m[3][0] = -(hi.x + lo.x) / (hi.x - lo.x);
    m[3][1] = -(hi.y + lo.y) / (hi.y - lo.y);
    return m;
}

void VirtualMaps::setScene(const Scene& scene, const PropertySet& p) {
    mLight = -1;
    for (size_t i = 0; i < scene.lights.size() && i < size_t(kMaxLights); ++i) {
        const Light& l = scene.lights[i];
        if (!l.castsShadows) continue;
        if (l.type == LightType::Point)
            throw Error(
                "virtual: light " + std::to_string(i) +
                    " is a point light; virtual maps directional and spot lights (a point light's six "
                    "16k faces are not built)",
                ExitCode::Unsupported);
        if (mLight >= 0)
            throw Error("virtual: lights " + std::to_string(mLight) + " and " + std::to_string(i) +
                            " both cast shadows; virtual maps one light (a page table per light, not built)",
                        ExitCode::Unsupported);
        mLight = int(i);
    }
    mLodBias = float(p.getFloat(Virtual::kLodBias));
    mTexels = VirtualMapTexels();
    mCache.emplace(Virtual::geometry(p));
    mMoved.clear();
    fitLight(scene);
}

void VirtualMaps::fitLight(const Scene& scene) {
    if (mLight < 0) return;
    mLightViewProj = fitLightViewProjection(scene, scene.lights[size_t(mLight)], {LightFitBounds::Scene});
    mCasters.reset(scene, mLightViewProj, mCache->geometry(), 1.0f);
    mTexels.setMap(mLight, mLightViewProj, mCache->geometry(), mLodBias);
}

void VirtualMaps::sceneChanged(const Scene& scene, uint32_t changes) {
    if (changes & kLightsMoved)
        fitLight(scene); // a new transform: the cache's next frame drops every page
    else if (changes & kCastersMoved)
        mCasters.moved(scene, mMoved);
}

const std::vector<PageRun>& VirtualMaps::allocate(const uint32_t* requests, bool on,
                                                  std::vector<uint32_t>& table) {
    const PageGeometry& g = mCache->geometry();
    mNeeded.assign(g.pageCount(), 0);
    for (size_t i = 0; i < mNeeded.size(); ++i) mNeeded[i] = requests[i] != 0 ? 1 : 0;
    mCache->beginFrame(mLightViewProj, on);
    mCache->invalidate(mMoved);
    mMoved.clear();
    const std::vector<uint32_t>& pages = mCache->allocate(mNeeded);
    mCache->packTable(table);
    table.resize(size_t(g.pagesPerSide()) * size_t(g.tableRows()), 0u);
    mRuns.clear();
    for (size_t i = 0; i < pages.size();) {
        const PageAddress first = g.address(pages[i]);
        size_t j = i + 1;
        while (j < pages.size() && pages[j] == pages[j - 1] + 1 && g.address(pages[j]).level == first.level &&
               g.address(pages[j]).page.y == first.page.y)
            ++j;
        mRuns.push_back({first.level, first.page, int(j - i)});
        i = j;
    }
    return mRuns;
}

Counters VirtualMaps::counters(const SubmitStats& s) const {
    const PageGeometry& g = mCache->geometry();
    const PageCounts& c = mCache->counts();
    Counters out = DepthLightingFrame::counters(s, double(c.rendered) * g.pageSize() * g.pageSize(), {});
    for (auto& kv : c.toCounters()) out.push_back(kv);
    return out;
}

} // namespace sb
