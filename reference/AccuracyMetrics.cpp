#include "reference/AccuracyMetrics.h"

#include <algorithm>
#include <cmath>

namespace sb {

namespace {
// A technique sample is "shadowed" below half visibility; the reference is exact 0/1 for hard shadows.
bool shadowed(float v) {
    return v < 0.5f;
}

double percent(uint64_t part, uint64_t whole) {
    return whole ? 100.0 * double(part) / double(whole) : 0.0;
}
} // namespace

std::vector<uint8_t> AccuracyMetrics::edgeMask(const std::vector<float>& reference, int width, int height) {
    std::vector<uint8_t> edge(reference.size(), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            size_t i = size_t(y) * size_t(width) + size_t(x);
            if (reference[i] < 0.0f) continue;
            bool lit = !shadowed(reference[i]);
            for (int dy = -1; dy <= 1 && !edge[i]; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                    float n = reference[size_t(ny) * size_t(width) + size_t(nx)];
                    if (n >= 0.0f && !shadowed(n) != lit) {
                        edge[i] = 1;
                        break;
                    }
                }
        }
    return edge;
}

HardMetrics AccuracyMetrics::hard(const std::vector<float>& technique, const std::vector<float>& reference,
                                  const std::vector<uint8_t>& mask, int width, int height) {
    HardMetrics m;
    std::vector<uint8_t> edge = edgeMask(reference, width, height);
    for (size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        bool refShadow = shadowed(reference[i]);
        // A NaN sample is always wrong: it counts as the opposite of the reference's answer.
        bool techShadow = std::isnan(technique[i]) ? !refShadow : shadowed(technique[i]);
        bool fs = techShadow && !refShadow, fl = !techShadow && refShadow;
        ++m.evaluated;
        m.falseShadow += fs;
        m.falseLight += fl;
        if (edge[i]) continue;
        ++m.evaluatedNoEdge;
        m.falseShadowNoEdge += fs;
        m.falseLightNoEdge += fl;
    }
    m.falseShadowPct = percent(m.falseShadow, m.evaluated);
    m.falseLightPct = percent(m.falseLight, m.evaluated);
    m.wrongPct = m.falseShadowPct + m.falseLightPct;
    m.falseShadowNoEdgePct = percent(m.falseShadowNoEdge, m.evaluatedNoEdge);
    m.falseLightNoEdgePct = percent(m.falseLightNoEdge, m.evaluatedNoEdge);
    m.wrongNoEdgePct = m.falseShadowNoEdgePct + m.falseLightNoEdgePct;
    return m;
}

SoftMetrics AccuracyMetrics::soft(const std::vector<float>& technique, const std::vector<float>& reference,
                                  const std::vector<uint8_t>& mask) {
    SoftMetrics m;
    double sumSq = 0.0, sumAbs = 0.0;
    for (size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        // A non-finite technique value is the largest possible error, not a value to average.
        double e = std::isfinite(technique[i]) ? std::abs(double(technique[i]) - double(reference[i])) : 1.0;
        ++m.evaluated;
        sumSq += e * e;
        sumAbs += e;
        m.maxAbs = std::max(m.maxAbs, e);
    }
    if (m.evaluated) {
        m.rmse = std::sqrt(sumSq / double(m.evaluated));
        m.meanAbs = sumAbs / double(m.evaluated);
    }
    return m;
}

NumericSanity AccuracyMetrics::sanity(const std::vector<float>& values) {
    NumericSanity s;
    for (float v : values) {
        if (std::isnan(v))
            ++s.nan;
        else if (std::isinf(v))
            ++s.inf;
        else if (v < 0.0f || v > 1.0f)
            ++s.outOfRange;
    }
    return s;
}

uint64_t AccuracyMetrics::changedSamples(const std::vector<float>& a, const std::vector<float>& b,
                                         const std::vector<uint8_t>& mask) {
    uint64_t n = 0;
    for (size_t i = 0; i < mask.size(); ++i)
        if (mask[i] && shadowed(a[i]) != shadowed(b[i])) ++n;
    return n;
}

double AccuracyMetrics::perturbationGain(uint64_t techniqueChanges, uint64_t referenceChanges) {
    return double(techniqueChanges) / double(std::max<uint64_t>(1, referenceChanges));
}

std::vector<float> AccuracyMetrics::channel(const std::vector<float>& rgba, int c) {
    std::vector<float> out(rgba.size() / 4);
    for (size_t i = 0; i < out.size(); ++i) out[i] = rgba[i * 4 + size_t(c)];
    return out;
}

} // namespace sb
