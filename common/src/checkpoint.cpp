#include "rasterlab/checkpoint.hpp"

#include <atomic>

namespace rl {

namespace {

std::atomic<CheckpointHook> g_hook{nullptr};

}  // namespace

CheckpointHook set_checkpoint_hook(CheckpointHook hook) noexcept {
    return g_hook.exchange(hook);
}

void checkpoint() {
    if (const CheckpointHook hook = g_hook.load(std::memory_order_relaxed)) hook();
}

}  // namespace rl
