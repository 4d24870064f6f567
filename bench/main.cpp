// bench: the shadowbench command line (see BenchApp.h, README.md).
#include "bench/BenchApp.h"

int main(int argc, char** argv) {
    return sb::BenchApp::main(argc, argv);
}
