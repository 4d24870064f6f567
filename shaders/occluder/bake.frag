// Occluder-texture bake: occluders are black. The cross-section's marking pass masks colour writes off
// and counts in the stencil only.
layout(location = 0) out vec4 oColor;

void main() { oColor = vec4(0.0, 0.0, 0.0, 1.0); }
