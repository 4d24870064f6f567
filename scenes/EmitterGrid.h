#pragma once
// The stratified grid over an area light's emitter: sqrt(N) x sqrt(N) equal-measure strata, one sample
// each. The Embree reference's soft shadows (reference/LightSampler) and the ray-traced ones
// (`raytraced:mode=soft`, shaders/raytraced/emitter.glsl) take the same number of samples for the same
// request, so that a count means the same on both sides.
namespace sb {

/// Side of the grid for at least `samples` samples: rounded up to a square, at least 1 (10 -> 4, 16 -> 4).
inline int emitterGridSide(int samples) {
    int side = 1;
    while (side * side < samples) ++side;
    return side;
}

} // namespace sb
