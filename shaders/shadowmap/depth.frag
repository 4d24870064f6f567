// Depth only: colour writes are masked off; the empty body lets the rasteriser skip shading work.
void main() {}
