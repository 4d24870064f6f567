#include "bench/lib/images/ErrorMap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "reference/AccuracyMetrics.h"

namespace sb {

namespace {
// The same rule as AccuracyMetrics::hard (reference/AccuracyMetrics.cpp): shadowed below 0.5.
bool shadowed(float v) {
    return v < 0.5f;
}
} // namespace

Rgb ErrorMap::dimmed(float reference) {
    const float r = std::isfinite(reference) ? std::clamp(reference, 0.0f, 1.0f) : 0.0f;
    const auto g = uint8_t(40 + std::lround(100.0f * r));
    return {g, g, g};
}

Rgb ErrorMap::colour(ErrorClass c, float reference) {
    switch (c) {
    case ErrorClass::Background:
        return kBackground;
    case ErrorClass::NotJudged:
        return kNotJudged;
    case ErrorClass::Correct:
        return dimmed(reference);
    case ErrorClass::EdgeCorrect:
        return kEdgeBand;
    case ErrorClass::FalseShadow:
        return kFalseShadow;
    case ErrorClass::FalseLight:
        return kFalseLight;
    case ErrorClass::FalseShadowEdge:
        return kFalseShadowEdge;
    case ErrorClass::FalseLightEdge:
        return kFalseLightEdge;
    }
    return kBackground;
}

std::vector<ErrorClass> ErrorMap::classify(const std::vector<float>& technique,
                                           const std::vector<float>& reference,
                                           const std::vector<uint8_t>& mask, int width, int height) {
    const size_t n = size_t(std::max(0, width)) * size_t(std::max(0, height));
    if (technique.size() != n || reference.size() != n || mask.size() != n)
        throw std::invalid_argument("ErrorMap: buffers of " + std::to_string(technique.size()) + ", " +
                                    std::to_string(reference.size()) + " and " + std::to_string(mask.size()) +
                                    " samples for a " + std::to_string(width) + "x" + std::to_string(height) +
                                    " map");
    // The band the judgement's *_no_edge_* figures leave out, computed by the judgement's own function.
    const std::vector<uint8_t> edge = AccuracyMetrics::edgeMask(reference, width, height);
    std::vector<ErrorClass> out(n);
    for (size_t i = 0; i < n; ++i) {
        const float ref = reference[i];
        if (!mask[i]) {
            out[i] = ref >= 0.0f ? ErrorClass::NotJudged : ErrorClass::Background; // NaN: background
            continue;
        }
        const bool refShadow = shadowed(ref);
        const bool techShadow = std::isnan(technique[i]) ? !refShadow : shadowed(technique[i]);
        const bool band = edge[i] != 0;
        if (techShadow && !refShadow)
            out[i] = band ? ErrorClass::FalseShadowEdge : ErrorClass::FalseShadow;
        else if (!techShadow && refShadow)
            out[i] = band ? ErrorClass::FalseLightEdge : ErrorClass::FalseLight;
        else
            out[i] = band ? ErrorClass::EdgeCorrect : ErrorClass::Correct;
    }
    return out;
}

ErrorMap::Counts ErrorMap::count(const std::vector<ErrorClass>& classes) {
    Counts c;
    for (ErrorClass e : classes) {
        if (e == ErrorClass::Background || e == ErrorClass::NotJudged) continue;
        const bool band = e == ErrorClass::EdgeCorrect || e == ErrorClass::FalseShadowEdge ||
                          e == ErrorClass::FalseLightEdge;
        const bool fs = e == ErrorClass::FalseShadow || e == ErrorClass::FalseShadowEdge;
        const bool fl = e == ErrorClass::FalseLight || e == ErrorClass::FalseLightEdge;
        ++c.evaluated;
        c.falseShadow += fs;
        c.falseLight += fl;
        c.edgeBand += band;
        if (band) continue;
        ++c.evaluatedNoEdge;
        c.falseShadowNoEdge += fs;
        c.falseLightNoEdge += fl;
    }
    return c;
}

ErrorMap ErrorMap::build(const std::vector<float>& technique, const std::vector<float>& reference,
                         const std::vector<uint8_t>& mask, int width, int height) {
    const std::vector<ErrorClass> classes = classify(technique, reference, mask, width, height);
    ErrorMap map;
    map.mImage = RgbImage(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            map.mImage.set(x, y, colour(classes[i], reference[i]));
        }
    map.mCounts = count(classes);
    return map;
}

} // namespace sb
