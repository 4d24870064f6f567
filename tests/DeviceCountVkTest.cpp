// shaders/raytraced/count64.glsl's 64-bit count in two 32-bit words, on lavapipe, against sums computed on
// the CPU in 64-bit integers: each case starts the count at a chosen value, lets every invocation of a
// compute fixture (tests/shaders/vk/count64.comp) add its n, and reads the words back with
// techniques/raytraced/DeviceCount.h. Exact: integer sums, no tolerance. The cases wrap the low word
// once, many times (every add nearly 2^32), from just below a wrap, and not at all, so a lost or doubled
// carry changes the answer.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "VkComputeKernel.h"
#include "VkTestSupport.h"
#include "techniques/raytraced/DeviceCount.h"
#include "vk/VulkanBuffer.h"

namespace sb {
namespace {

using test::VulkanTest;

struct Push {
    uint32_t invocations = 0, offset = 0, mask = 0, base = 0;
};
constexpr uint32_t kLocalSize = 64; ///< count64.comp's local_size_x

struct Case {
    const char* what;
    uint64_t start;
    Push push;
};

/// The fixture's n for invocation i, as the shader computes it (mod 2^32).
uint32_t addOf(uint32_t i, const Push& p) {
    return p.base + ((i * 2654435761u + p.offset) & p.mask);
}

class DeviceCountVkTest : public VulkanTest {};

TEST_F(DeviceCountVkTest, SumsAcrossTheLowWordsWrapAreExact) {
    test::ComputeKernel kernel(context(), "tests/shaders/vk/count64.comp", {}, 1, sizeof(Push),
                               "count64 test");
    VulkanBuffer count(context(), kDeviceCountBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    const Case cases[] = {
        // Sums under 2^32: the high word must stay 0.
        {"no wrap: 4096 adds below 2^20", 0, {4096, 12345u, 0xFFFFFu, 0u}},
        // About 2^32 in all from 2^32 - 2^30: one wrap.
        {"one wrap: 4096 adds of about 2^20 from 2^32 - 2^30", 0xC0000000ull, {4096, 7u, 0xFFFFFu, 0x80000u}},
        // Every add wraps or nearly: 65535 carries or so, out of order across invocations.
        {"many wraps: 65536 adds of 2^32 - 256 to 2^32 - 1", 0, {65536, 3u, 0xFFu, 0xFFFFFF00u}},
        // 1000 adds of 1 from 100 below a wrap, the high word already 5: the 100th add carries.
        {"from just below a wrap, high word set", (5ull << 32) | 0xFFFFFF9Cull, {1000, 0u, 0u, 1u}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        const uint32_t words[2] = {uint32_t(c.start), uint32_t(c.start >> 32)};
        std::memcpy(count.map(), words, sizeof words);
        kernel.dispatch({&count}, &c.push, (c.push.invocations + kLocalSize - 1) / kLocalSize);
        uint64_t expected = c.start;
        for (uint32_t i = 0; i < c.push.invocations; ++i) expected += addOf(i, c.push);
        EXPECT_EQ(readDeviceCount(count.map()), expected);
        // The table's cases wrap as they say: the carry is what is tested.
        const bool wraps = (expected >> 32) != (c.start >> 32);
        EXPECT_EQ(wraps, c.start != 0 || expected > 0xFFFFFFFFull) << "expected " << expected;
    }
    zeroDeviceCount(count.map());
    EXPECT_EQ(readDeviceCount(count.map()), 0u);
}

} // namespace
} // namespace sb
