// A hook that long loops call between small units of work (a band of rows of
// a triangle, a tile), so that a host can stop a render part-way: the Python
// module installs one that raises KeyboardInterrupt on Ctrl-C. The hook may
// throw; the exception leaves the loop like any other, and whatever the loop
// was filling is dropped by its owner, so nothing half-drawn is returned.
// With no hook installed (every program) a checkpoint is one atomic load.
//
//   rl::set_checkpoint_hook([] { if (stop_requested()) throw Stopped(); });
//   for (...) { rl::checkpoint(); draw_some(); }
#pragma once

namespace rl {

using CheckpointHook = void (*)();

// Installs `hook` for every thread (nullptr removes it); returns the old one.
CheckpointHook set_checkpoint_hook(CheckpointHook hook) noexcept;

// Calls the installed hook, if any, unless a CheckpointsPaused is alive on
// this thread.
void checkpoint();

// While one is alive on a thread, checkpoint() there does nothing: the
// thread runs a piece of another thread's loop while it waits for a loop of
// its own (rl::Workers makes one then), and a host's stop belongs to the
// thread's own loop. Without it, Python's main thread, running a chunk of
// another thread's render in the shared arena, raised KeyboardInterrupt in
// that other render.
class CheckpointsPaused {
  public:
    CheckpointsPaused() noexcept;
    ~CheckpointsPaused();
    CheckpointsPaused(const CheckpointsPaused&) = delete;
    CheckpointsPaused& operator=(const CheckpointsPaused&) = delete;
};

}  // namespace rl
