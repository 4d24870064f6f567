// Receiver marking (techniques/gl/ReceiverStencil, for `planar` and `blob`): a receiver plane's
// rectangle (world space), pulled towards the eye by glPolygonOffset so it wins the depth test against
// the receiver it lies on.
#include "common/frame.glsl"

layout(location = 0) in vec3 aPosition;

void main() { gl_Position = uViewProj * vec4(aPosition, 1.0); }
