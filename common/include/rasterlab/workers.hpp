// Threads: a oneTBB arena of a given size and the one loop run on it,
// body(range) over chunks of [0, count) (lesson 12's tiles), and
// rl::parallel_for, body(i) for each i of a range on every core (lesson 09's
// map rows, lesson 10's occlusion rows and baked faces). A library of its own
// (rasterlab::threads), linked only by the lessons that run threads.
//
//   rl::Workers workers(2);
//   workers.for_chunks(tiles, 1, [&](const tbb::blocked_range<std::size_t>& r) { ... });
//   rl::parallel_for(0, height, [&](int row) { ... });
//
// Under ThreadSanitizer (the `tsan` preset) oneTBB's scheduler is out of its
// sight: libtbb is not instrumented, so a task handed from one thread to
// another looks like a race. There, what any thread does in an arena outside
// a chunk (oneTBB's own work) is ignored, and the loop tells the sanitizer
// what oneTBB guarantees and nothing more: every chunk starts after
// for_chunks began and ends before it returns. Two chunks stay unordered, so
// a race between tiles (or rows) is reported.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <thread>

#include "rasterlab/checkpoint.hpp"

namespace rl {

#if defined(__SANITIZE_THREAD__)
namespace thread_sanitizer {
void ignore_accesses(bool ignore);  // on this thread (each change made once)
void chunks_began(), chunk_starts(), chunk_ended(), chunks_ended();
struct WorkersOutOfSight;  // ignores what any thread does in the arena outside a chunk
}  // namespace thread_sanitizer
#endif

// Alive while this thread waits in for_chunks for a loop it asked for.
class LoopWaited {
  public:
    LoopWaited() noexcept;
    ~LoopWaited();
    LoopWaited(const LoopWaited&) = delete;
    LoopWaited& operator=(const LoopWaited&) = delete;
    static bool here() noexcept;  // whether one is alive on this thread
};

class Workers {
  public:
    // 0: as many as the machine has; more than it has: as many as it has.
    explicit Workers(int threads);
    ~Workers();
    int threads() const { return arena_.max_concurrency(); }
    // Which of the threads runs this chunk: 0 .. threads() - 1.
    static int this_thread() { return std::max(0, tbb::this_task_arena::current_thread_index()); }

    template <class Body>
    void for_chunks(std::size_t count, std::size_t grain, const Body& body) {
        const tbb::blocked_range<std::size_t> all(0, count, grain);
        // A thread that waits for a loop of its own and runs a chunk of
        // another caller's meanwhile (the arena is shared) pauses its
        // checkpoints there: its host's stop is for its own loop, not for the
        // other caller's (rasterlab/checkpoint.hpp). oneTBB's workers, which
        // wait for no loop, pass them on as before.
        const std::thread::id caller = std::this_thread::get_id();
        const LoopWaited waiting;
        const auto run = [&](const Body& chunk_body, const tbb::blocked_range<std::size_t>& chunk) {
            if (std::this_thread::get_id() == caller || !LoopWaited::here())
                return chunk_body(chunk);
            const CheckpointsPaused paused;
            chunk_body(chunk);
        };
#if defined(__SANITIZE_THREAD__)
        namespace ts = thread_sanitizer;
        // The ends are told by destructors: a chunk may throw (a host's Ctrl-C).
        struct ChunksEnded {
            ~ChunksEnded() { ts::chunks_ended(); }
        };
        struct ChunkEnded {
            ~ChunkEnded() { ts::chunk_ended(); }
        };
        ts::chunks_began();
        const ChunksEnded loop;
        arena_.execute([&] {
            tbb::parallel_for(all, [&](const tbb::blocked_range<std::size_t>& range) {
                // oneTBB wrote the task this lambda and its range live in: read
                // them while the thread is still out of sight.
                const Body& chunk_body = body;
                const tbb::blocked_range<std::size_t> chunk = range;
                ts::chunk_starts();
                const ChunkEnded ended;
                run(chunk_body, chunk);
            });
        });
#else
        arena_.execute([&] {
            tbb::parallel_for(
                all, [&](const tbb::blocked_range<std::size_t>& chunk) { run(body, chunk); });
        });
#endif
    }

  private:
    tbb::task_arena arena_;
#if defined(__SANITIZE_THREAD__)
    std::unique_ptr<thread_sanitizer::WorkersOutOfSight> out_of_sight_;
#endif
};

// The arena rl::parallel_for runs on: as many threads as the machine has,
// made once and kept (an arena made afresh for every loop cost more at each
// call: 23 us, then 660 us a call after 16 000 calls, against 4 us for
// oneTBB's own parallel_for). Threads may run loops on it at once.
Workers& shared_workers();

// body(i) for each i in [first, last), in any order, on as many threads as
// the machine has: each i must touch what no other i touches. Under
// ThreadSanitizer, with what for_chunks tells it.
template <class Index, class Body>
void parallel_for(Index first, Index last, const Body& body) {
    if (!(first < last)) return;
    const auto count = static_cast<std::size_t>(last - first);
    shared_workers().for_chunks(count, 1, [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i)
            body(static_cast<Index>(first + static_cast<Index>(i)));
    });
}

}  // namespace rl
