#pragma once
// What the --back-faces tests keep of one frame on either API (tests/BackFacesGLTest.cpp,
// tests/BackFacesVkTest.cpp): the colour and visibility targets and the fragment-shader invocations of
// the census frame, whole and per pass, so that "culled equals drawn" and "culled shades fewer" are
// judged the same way on both.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sb::test {

struct BackFacesFrame {
    std::vector<unsigned char> color;
    std::vector<float> visibility;
    uint64_t fragments = 0; ///< fragment-shader invocations of the whole census frame
    std::vector<std::pair<std::string, uint64_t>> passFragments;
};

/// One census frame (pipeline statistics per pass) and one rendered frame of `technique`, prepared on
/// `harness` (Harness or VulkanHarness: both have measureLoads, renderFrame and targets()).
template <class HarnessT, class TechniqueT>
BackFacesFrame captureBackFacesFrame(HarnessT& harness, TechniqueT& technique) {
    BackFacesFrame f;
    const auto loads = harness.measureLoads(technique);
    for (const auto& [pass, work] : loads.passes)
        if (work.pipeline) f.passFragments.emplace_back(pass, work.pipeline->fragmentShaderInvocations);
    if (loads.pipeline) f.fragments = loads.pipeline->fragmentShaderInvocations;
    harness.renderFrame(technique);
    f.color = harness.targets().readColorRGBA8();
    f.visibility = harness.targets().readVisibilityRGBA32F();
    return f;
}

} // namespace sb::test
