#pragma once
// Where the tests find the source tree and the bench binary. The values live in one generated file of
// the build tree (tests/CMakeLists.txt), not in a define on every test, so test objects do not depend
// on where the checkout is.
namespace sb::test {
const char* sourceDir();   ///< the source tree's root
const char* benchBinary(); ///< the bench executable of this build ($SHADOWBENCH_TEST_BENCH when set)
const char* handshadowBinary(); ///< the hand-written shadow map (bench/handwritten/handshadow/) of this build
                                ///< ($SHADOWBENCH_TEST_HANDSHADOW when set)
} // namespace sb::test

#define SB_SOURCE_DIR ::sb::test::sourceDir()
#define SB_BENCH_BINARY ::sb::test::benchBinary()
#define SB_HANDSHADOW_BINARY ::sb::test::handshadowBinary()
