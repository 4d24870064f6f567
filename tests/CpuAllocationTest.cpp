// The CPUs a process was given (core/CpuAllocation.h) and the reference tracer's default thread count
// that uses them: a kernel CPU list counted by hand, and the count under a narrowed affinity mask held to
// sched_getaffinity()'s own CPU_COUNT, the independent answer, while std::thread::hardware_concurrency()
// still reports the whole machine (what rows and the tracer used before).
#include <optional>
#include <sched.h>
#include <thread>

#include <gtest/gtest.h>

#include "core/CpuAllocation.h"
#include "reference/ReferenceTracer.h"

using namespace sb;

namespace {

struct ListCase {
    const char* list;
    std::optional<int> count; ///< counted by hand; nullopt: not a CPU list
};

const ListCase kLists[] = {
    {"0", 1},
    {"0-1", 2},
    {"0-3,8,10-11", 7},
    {"5", 1},
    {" 2-3\n", 2},
    {"", std::nullopt},
    {"a", std::nullopt},
    {"3-1", std::nullopt},
    {"1,,2", std::nullopt},
    {"-1", std::nullopt},
    {"0-", std::nullopt},
    {"+1", std::nullopt},
};

/// The calling thread's mask narrowed to its first allowed CPU, and put back on destruction.
class OneCpu {
public:
    OneCpu() {
        CPU_ZERO(&mOld);
        mOk = ::sched_getaffinity(0, sizeof mOld, &mOld) == 0;
        for (int cpu = 0; mOk && cpu < CPU_SETSIZE; ++cpu)
            if (CPU_ISSET(cpu, &mOld)) {
                cpu_set_t one;
                CPU_ZERO(&one);
                CPU_SET(cpu, &one);
                mOk = ::sched_setaffinity(0, sizeof one, &one) == 0;
                return;
            }
    }
    ~OneCpu() {
        if (mOk) ::sched_setaffinity(0, sizeof mOld, &mOld);
    }
    bool ok() const { return mOk; }

private:
    cpu_set_t mOld;
    bool mOk = false;
};

int affinityCount() {
    cpu_set_t set;
    CPU_ZERO(&set);
    return ::sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : -1;
}

} // namespace

TEST(CpuAllocation, CountsKernelCpuLists) {
    for (const ListCase& c : kLists) EXPECT_EQ(countCpuList(c.list), c.count) << "'" << c.list << "'";
}

TEST(CpuAllocation, TheProcessMaskIsWhatSchedGetaffinityCounts) {
    EXPECT_EQ(allocatedCpuCount(), affinityCount());
}

// `taskset -c 0` in process: one CPU of a machine with more. The count and the tracer's default follow
// the mask; an explicit thread count is kept as given.
TEST(CpuAllocation, UnderAOneCpuMaskTheCountAndTheTracersDefaultAreOne) {
    if (affinityCount() < 2) GTEST_SKIP() << "needs a process allowed at least 2 CPUs to narrow to 1";
    OneCpu one;
    ASSERT_TRUE(one.ok()) << "sched_setaffinity refused";
    ASSERT_EQ(affinityCount(), 1);
    EXPECT_GE(std::thread::hardware_concurrency(), 2u) << "the machine's count, which the mask must override";
    EXPECT_EQ(allocatedCpuCount(), 1);
    EXPECT_EQ(ReferenceTracer::threadCount(0), 1);
    EXPECT_EQ(ReferenceTracer::threadCount(3), 3);
}
