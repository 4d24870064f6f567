// Receiver marking (techniques/gl/ReceiverStencil, for `planar` and `blob`): no colour (the colour
// masks are off); the stencil op does the work.
void main() {}
