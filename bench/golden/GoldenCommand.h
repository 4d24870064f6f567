#pragma once
// `bench golden --check|--update`: renders the technique x submission x scene matrix (GoldenMatrix)
// and judges it (MatrixCheck), or rewrites the goldens and bounds from it, printing for every golden
// what changed and by how much. The test suite runs the same check (tests/MatrixGLTest.cpp).
namespace sb {

class GoldenCommand {
public:
    /// argv from "golden" on. Exit 0 when every cell passes (or the update is written), 1 when a cell
    /// fails, 2 for bad options.
    static int main(int argc, char** argv);
};

} // namespace sb
