// `volume` marking pass: colour writes are masked off, only stencil counts change.
void main() {}
