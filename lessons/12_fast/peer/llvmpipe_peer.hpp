// The peer lesson 12 is measured against: Mesa's llvmpipe, a conformant
// OpenGL implementation that JIT-compiles shaders to SIMD code and rasterizes
// 64x64 tiles on several threads, drawing lesson 07's scene off screen
// (OSMesa) with a GLSL 3.3 shader that does what lesson 07's shader does:
// the same meshes (indexed as the fast path indexes them), the same mip
// levels of the same maps, the same camera matrices and lights.
//
//   fast::LlvmpipePeer peer(800, 800, 2);   // LP_NUM_THREADS = 2
//   peer.upload(models, options);           // outside the timed loop
//   const double ms = peer.render(camera);  // one frame, glFinish included
//   const rl::Image picture = peer.frame();
//
// The lab links it; lesson 12's program loads it from a module when it runs
// the peer (peer.hpp, peer_module.cpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "peer.hpp"

namespace fast {

// What the peer's fragment shader does: lesson 07's shader (the same work
// as ours), or a plain one: one light, Phong, the colour map only, no
// normal or specular map, no sRGB encoding (about half the work: the
// independent check that ours is not slow for its extra work).
enum class PeerShader { same_work, plain };

class LlvmpipePeer : public Peer {
  public:
    LlvmpipePeer(int width, int height, int threads, PeerShader shader = PeerShader::same_work);
    ~LlvmpipePeer() override;
    LlvmpipePeer(const LlvmpipePeer&) = delete;
    LlvmpipePeer& operator=(const LlvmpipePeer&) = delete;

    void upload(const std::vector<normal_mapping::MappedModel>& models,
                const normal_mapping::RenderOptions& options) override;
    // Draws one frame and waits for it (glFinish); returns its milliseconds.
    double render(const pipeline::Camera& camera) override;
    rl::Image frame() const override;      // the last frame, bottom row first
    std::string version() const override;  // GL_VERSION and GL_RENDERER

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace fast
