// `planar` stencil marking: no colour (the colour masks are off); the stencil op does the work.
void main() {}
