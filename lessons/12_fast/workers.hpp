// The fast path's threads: a oneTBB arena of a given size and the one loop
// the renderer runs on it, body(range) over chunks of [0, count).
//
//   fast::Workers workers(2);
//   workers.for_chunks(tiles, 1, [&](const tbb::blocked_range<std::size_t>& r) { ... });
//
// Under ThreadSanitizer (the `tsan` preset) oneTBB's scheduler is out of its
// sight: libtbb is not instrumented, so a task handed from one thread to
// another looks like a race. There, the workers' own accesses inside oneTBB
// are ignored, and the loop tells the sanitizer what oneTBB guarantees and
// nothing more: every chunk starts after for_chunks began and ends before it
// returns. Two chunks stay unordered, so a race between tiles is reported.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <memory>

namespace fast {

#if defined(__SANITIZE_THREAD__)
namespace thread_sanitizer {
void ignore_accesses(bool ignore);  // on this thread, nested
void chunks_began(), chunk_starts(), chunk_ended(), chunks_ended();
struct WorkersOutOfSight;  // ignores what a worker does outside a chunk
}  // namespace thread_sanitizer
#endif

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
#if defined(__SANITIZE_THREAD__)
        namespace ts = thread_sanitizer;
        ts::chunks_began();
        arena_.execute([&] {
            tbb::parallel_for(all, [&](const tbb::blocked_range<std::size_t>& range) {
                // oneTBB wrote the task this lambda and its range live in: read
                // them while a worker is still out of sight.
                const Body& chunk_body = body;
                const tbb::blocked_range<std::size_t> chunk = range;
                ts::chunk_starts();
                chunk_body(chunk);
                ts::chunk_ended();
            });
        });
        ts::chunks_ended();
#else
        arena_.execute([&] { tbb::parallel_for(all, body); });
#endif
    }

  private:
    tbb::task_arena arena_;
#if defined(__SANITIZE_THREAD__)
    std::unique_ptr<thread_sanitizer::WorkersOutOfSight> out_of_sight_;
#endif
};

}  // namespace fast
