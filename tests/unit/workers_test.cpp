// The threads' library (rasterlab/workers.hpp): rl::parallel_for visits each
// index once, and a host's checkpoint runs only on the thread that asked for
// the loop, never on a thread that runs a piece of it for that thread.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "rasterlab/checkpoint.hpp"
#include "rasterlab/workers.hpp"

namespace {

using namespace std::chrono_literals;

TEST(Workers, ParallelForVisitsEachIndexOnce) {
    std::vector<std::atomic<int>> visits(10'000);
    rl::parallel_for(0, 10'000, [&](int i) { ++visits[static_cast<std::size_t>(i)]; });
    for (const std::atomic<int>& v : visits) ASSERT_EQ(v.load(), 1);
    rl::parallel_for(5, 5, [&](int) { ADD_FAILURE() << "an empty range ran its body"; });
}

// Each loop's body names its caller before the checkpoint; the hook counts
// the calls made on the other caller's thread. Python's hook raises
// KeyboardInterrupt on the main thread: where the main thread, waiting for a
// loop of its own, ran a piece of another thread's loop, that other render
// was stopped (and the main one was not). oneTBB's workers, which wait for
// no loop of their own, still pass checkpoints on.
thread_local std::thread::id g_loop_caller;
std::thread::id g_callers[2];
std::atomic<int> g_foreign_calls{0}, g_own_calls{0}, g_shared_chunks{0};

TEST(Workers, ACheckpointRunsOnlyOnTheThreadThatAskedForTheLoop) {
    const rl::CheckpointHook old = rl::set_checkpoint_hook([] {
        const std::thread::id me = std::this_thread::get_id();
        if (me == g_loop_caller)
            ++g_own_calls;
        else if (me == g_callers[0] || me == g_callers[1])
            ++g_foreign_calls;
    });
    // Loops until one caller has run a piece of the other's (it depends on
    // which threads oneTBB lets into the arena), for at most 10 s.
    const auto start = std::chrono::steady_clock::now();
    const auto loops = [&] {
        const std::thread::id caller = std::this_thread::get_id();
        while (g_shared_chunks == 0 && std::chrono::steady_clock::now() - start < 10s)
            rl::parallel_for(0, 64, [&](int i) {
                volatile double sum = 0;  // a little work an index
                for (int k = 0; k < 200; ++k) sum = sum + k * i;
                const std::thread::id me = std::this_thread::get_id();
                if (me != caller && (me == g_callers[0] || me == g_callers[1])) ++g_shared_chunks;
                g_loop_caller = caller;
                rl::checkpoint();
            });
    };
    g_callers[0] = std::this_thread::get_id();
    std::atomic<bool> ready{false};
    std::thread other([&] {
        g_callers[1] = std::this_thread::get_id();
        ready = true;
        loops();
    });
    while (!ready) std::this_thread::yield();
    loops();  // two callers at once share the arena
    other.join();
    rl::set_checkpoint_hook(old);
    if (g_shared_chunks == 0) GTEST_SKIP() << "neither caller ran a piece of the other's loop";
    EXPECT_EQ(g_foreign_calls.load(), 0) << g_shared_chunks << " pieces run by the other caller";
    EXPECT_GT(g_own_calls.load(), 0);
}

// While a pause is alive, the hook is not called; after it, it is again.
TEST(Workers, APausedThreadSkipsTheHook) {
    static std::atomic<int> calls{0};
    const rl::CheckpointHook old = rl::set_checkpoint_hook([] { ++calls; });
    {
        const rl::CheckpointsPaused paused;
        rl::checkpoint();
    }
    EXPECT_EQ(calls.load(), 0);
    rl::checkpoint();
    EXPECT_EQ(calls.load(), 1);
    rl::set_checkpoint_hook(old);
}

}  // namespace
