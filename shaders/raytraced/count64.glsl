// A 64-bit event counter that fragments add to, kept in two 32-bit words of a storage buffer (the low
// word, then the high one), so that no device feature beyond 32-bit atomics is needed
// (shaderBufferInt64Atomics is optional in Vulkan). One 32-bit word overflows within a frame the suite
// can ask for: `raytraced:mode=soft,rays=256` at 4096x4096 traces up to 4096^2 x 256 = 2^32 rays per
// light.
//
// COUNT64_ADD(low, high, n) adds the uint n. atomicAdd returns the low word before this add; the add
// wrapped the low word past 2^32 exactly when that value exceeds 2^32 - 1 - n, and then this invocation,
// and only this one, carries 1 into the high word. Every wrap is carried once, in any order of the adds,
// so after the frame high * 2^32 + low is the exact sum (the host reads it with
// techniques/raytraced/DeviceCount.h; tests/DeviceCountVkTest.cpp holds it to closed-form sums across
// the wrap).
#define COUNT64_ADD(low, high, n)                                                                          \
    {                                                                                                      \
        const uint count64Added_ = (n);                                                                    \
        if (atomicAdd(low, count64Added_) > 0xFFFFFFFFu - count64Added_) atomicAdd(high, 1u);              \
    }
