// A peer renderer as the program sees it: lesson 12's program loads Mesa's
// llvmpipe (and through it LLVM) only when it runs the peer, from a module
// built beside it, so that `--no-peer` starts as fast as the other lessons.
//
//   std::unique_ptr<fast::Peer> peer = fast::load_llvmpipe_peer(800, 800, 2);
//   peer->upload(models, options);           // outside the timed loop
//   const double ms = peer->render(camera);  // one frame, finished
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "07_normal_mapping/scene.hpp"

namespace fast {

// Thrown when the peer cannot run here: no OpenGL 3.3 context, or no module
// (the program then says the peer is skipped, and why).
struct PeerUnavailable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Peer {
  public:
    virtual ~Peer() = default;
    virtual void upload(const std::vector<normal_mapping::MappedModel>& models,
                        const normal_mapping::RenderOptions& options) = 0;
    // Draws one frame and waits for it; returns its milliseconds.
    virtual double render(const pipeline::Camera& camera) = 0;
    virtual rl::Image frame() const = 0;      // the last frame, bottom row first
    virtual std::string version() const = 0;  // what the peer says it is
};

// Loads the llvmpipe peer's module (built beside lesson 12's program) and
// makes a peer drawing width x height on `threads` threads. Throws
// PeerUnavailable naming the module or the context that is missing.
std::unique_ptr<Peer> load_llvmpipe_peer(int width, int height, int threads);

}  // namespace fast
