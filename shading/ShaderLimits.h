#pragma once
// What every shader and frame target of both APIs is built for: the frame block's light array
// (shaders/common/frame.glsl) and the visibility target's channels (one light per channel of RGBA16F).
namespace sb {

constexpr int kMaxLights = 4;

} // namespace sb
