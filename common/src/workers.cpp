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

// Whether this thread is a worker outside a chunk (its accesses ignored).
// A worker may end while still in the arena, with no exit call from oneTBB:
// the sanitizer must then find its ignores ended, hence the destructor.
struct OutOfSight {
    bool now = false;
    ~OutOfSight();
};
thread_local OutOfSight out_of_sight;
}  // namespace

void ignore_accesses(bool ignore) {
    if (ignore) {
        AnnotateIgnoreReadsBegin(__FILE__, __LINE__);
        AnnotateIgnoreWritesBegin(__FILE__, __LINE__);
    } else {
        AnnotateIgnoreReadsEnd(__FILE__, __LINE__);
        AnnotateIgnoreWritesEnd(__FILE__, __LINE__);
    }
}
OutOfSight::~OutOfSight() {
    if (now) ignore_accesses(false);
}

void chunks_began() {
    __tsan_release(&fork);
}
void chunk_starts() {
    __tsan_acquire(&fork);
    if (out_of_sight.now) ignore_accesses(false);
}
void chunk_ended() {
    if (out_of_sight.now) ignore_accesses(true);
    __tsan_release(&join);
}
void chunks_ended() {
    __tsan_acquire(&join);
}

// A worker thread is out of sight from the moment it enters the arena; the
// thread that calls for_chunks stays in sight throughout.
struct WorkersOutOfSight : tbb::task_scheduler_observer {
    explicit WorkersOutOfSight(tbb::task_arena& arena) : tbb::task_scheduler_observer(arena) {
        observe(true);
    }
    ~WorkersOutOfSight() override { observe(false); }
    void on_scheduler_entry(bool worker) override {
        if (!worker || out_of_sight.now) return;
        out_of_sight.now = true;
        ignore_accesses(true);
    }
    void on_scheduler_exit(bool worker) override {
        if (!worker || !out_of_sight.now) return;
        ignore_accesses(false);
        out_of_sight.now = false;
    }
};

}  // namespace thread_sanitizer
#endif

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
