#include "rasterlab/workers.hpp"

#include <algorithm>

#include <tbb/info.h>

#if defined(__SANITIZE_THREAD__)
#include <sanitizer/tsan_interface.h>
#include <tbb/task_scheduler_observer.h>

// ThreadSanitizer's annotations (exported by its run-time library).
extern "C" {
void AnnotateIgnoreReadsBegin(const char* file, int line);
void AnnotateIgnoreReadsEnd(const char* file, int line);
void AnnotateIgnoreWritesBegin(const char* file, int line);
void AnnotateIgnoreWritesEnd(const char* file, int line);
}
#endif

namespace rl {

#if defined(__SANITIZE_THREAD__)
namespace thread_sanitizer {

namespace {
char fork, join;  // the addresses the fork and the join synchronize on

// Whether this thread is in an arena, and whether its accesses are ignored
// now (in an arena but outside a chunk). A worker may end while still in the
// arena, with no exit call from oneTBB: the sanitizer must then find its
// ignores ended, hence the destructor. Ignores are nested counts in the
// sanitizer, so each change is made once, from the state held here (a chunk
// that throws, as a host's Ctrl-C does, leaves the arena in sight).
struct OutOfSight {
    bool in_arena = false, ignoring = false;
    ~OutOfSight();
};
thread_local OutOfSight out_of_sight;
}  // namespace

void ignore_accesses(bool ignore) {
    if (out_of_sight.ignoring == ignore) return;
    out_of_sight.ignoring = ignore;
    if (ignore) {
        AnnotateIgnoreReadsBegin(__FILE__, __LINE__);
        AnnotateIgnoreWritesBegin(__FILE__, __LINE__);
    } else {
        AnnotateIgnoreReadsEnd(__FILE__, __LINE__);
        AnnotateIgnoreWritesEnd(__FILE__, __LINE__);
    }
}

OutOfSight::~OutOfSight() {
    ignore_accesses(false);
}

void chunks_began() {
    __tsan_release(&fork);
}
void chunk_starts() {
    __tsan_acquire(&fork);
    ignore_accesses(false);
}
void chunk_ended() {
    if (out_of_sight.in_arena) ignore_accesses(true);
    __tsan_release(&join);
}
void chunks_ended() {
    __tsan_acquire(&join);
}

// A thread is out of sight from the moment it enters the arena, a worker
// or a caller of for_chunks alike: a caller waiting in a shared arena runs
// other callers' chunks and oneTBB's tasks, and oneTBB reuses the memory of
// one caller's tasks for another's (seen under ThreadSanitizer, with four
// Python threads rendering at once). In a chunk every thread is in sight.
struct WorkersOutOfSight : tbb::task_scheduler_observer {
    explicit WorkersOutOfSight(tbb::task_arena& arena) : tbb::task_scheduler_observer(arena) {
        observe(true);
    }
    ~WorkersOutOfSight() override { observe(false); }
    void on_scheduler_entry(bool) override {
        out_of_sight.in_arena = true;
        ignore_accesses(true);
    }
    void on_scheduler_exit(bool) override {
        out_of_sight.in_arena = false;
        ignore_accesses(false);
    }
};

}  // namespace thread_sanitizer
#endif

namespace {
thread_local int g_loops_waited = 0;  // LoopWaited alive on this thread
}  // namespace

LoopWaited::LoopWaited() noexcept {
    ++g_loops_waited;
}
LoopWaited::~LoopWaited() {
    --g_loops_waited;
}
bool LoopWaited::here() noexcept {
    return g_loops_waited > 0;
}

// oneTBB runs at most the machine's hardware threads at once: an arena
// asked for more gets no more workers (and oneTBB prints a bare warning),
// yet would report the number asked for. So ask for no more than that.
Workers::Workers(int threads)
    : arena_(threads > 0 ? std::min(threads, tbb::info::default_concurrency())
                         : tbb::task_arena::automatic) {
#if defined(__SANITIZE_THREAD__)
    arena_.initialize();
    out_of_sight_ = std::make_unique<thread_sanitizer::WorkersOutOfSight>(arena_);
#endif
}

Workers::~Workers() = default;

Workers& shared_workers() {
    // Never destroyed: an arena torn down among the static destructors at
    // exit could outlive oneTBB's own state.
    static Workers* const shared = new Workers(0);
    return *shared;
}

}  // namespace rl
