#include "rasterlab/checkpoint.hpp"

#include <atomic>

namespace rl {

namespace {

std::atomic<CheckpointHook> g_hook{nullptr};
thread_local int g_paused = 0;  // CheckpointsPaused alive on this thread

}  // namespace

CheckpointsPaused::CheckpointsPaused() noexcept {
    ++g_paused;
}
CheckpointsPaused::~CheckpointsPaused() {
    --g_paused;
}

CheckpointHook set_checkpoint_hook(CheckpointHook hook) noexcept {
    return g_hook.exchange(hook);
}

void checkpoint() {
    if (g_paused > 0) return;
    if (const CheckpointHook hook = g_hook.load(std::memory_order_relaxed)) hook();
}

}  // namespace rl
