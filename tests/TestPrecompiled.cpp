// The object that owns the test files' precompiled header (tests/TestPrecompiled.h,
// tests/CMakeLists.txt): CMake compiles the header with this file's flags and every test file reuses it.
#include "TestPrecompiled.h"
