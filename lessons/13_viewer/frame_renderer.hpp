// What the viewer shows each frame: the scene drawn by the renderer the
// settings name (lesson 12's fast path, with or without lesson 08's shadows,
// or lesson 07's), at the framebuffer's size, with the wireframe over it if
// asked, lit from the settings' light. The fast renderer is kept between frames and built again
// only when the size or a shading option changes (a moved light is not one).
// With shadows, both of lesson 08's passes run on the fast path: the shadow
// map's (the same map as lesson 08's, texel for texel, kept between frames),
// then the picture, its key light scaled by lesson 08's lookup in the map
// (within one level of lesson 08's picture).
//
//   viewer::FrameRenderer renderer(scene.models, request);
//   const rl::Image& frame = renderer.render(settings, camera, 800, 600);
#pragma once

#include <memory>
#include <vector>

#include "07_normal_mapping/scene.hpp"
#include "08_shadows/scene.hpp"
#include "12_fast/renderer.hpp"
#include "12_fast/shadow_pass.hpp"
#include "controls.hpp"

namespace viewer {

struct FrameStats {
    std::size_t triangles = 0;      // sent to the renderer
    std::size_t pixels_shaded = 0;  // fragments shaded (the fast path: each visible pixel once)
    double shadow_map_ms = 0;       // with shadows: the shadow map's pass, of the frame's time
};

class FrameRenderer {
  public:
    // `request` is the view and lesson 07's options the scene was loaded with
    // (its lighting and output set by normal_mapping::load_scene).
    FrameRenderer(const std::vector<normal_mapping::MappedModel>& models,
                  const normal_mapping::MappedView& request);
    const rl::Image& render(const Settings& settings, const pipeline::Camera& camera, int width,
                            int height);
    const FrameStats& stats() const { return stats_; }
    const rl::Image& frame() const { return *frame_; }

  private:
    normal_mapping::RenderOptions options_for(const Settings& settings) const;
    bool light_moved(const Settings& settings) const;  // from --light's direction
    // Lesson 08's options as its program makes them from the view, lit from the settings' light.
    shadows::ShadowOptions shadow_options(const Settings& settings,
                                          const normal_mapping::RenderOptions& options) const;

    const std::vector<normal_mapping::MappedModel>& models_;
    normal_mapping::MappedView request_;
    std::size_t faces_ = 0;
    std::unique_ptr<fast::Renderer> fast_;
    Settings fast_settings_;  // what fast_ was built for
    int fast_width_ = 0, fast_height_ = 0;
    std::unique_ptr<fast::ShadowPass> shadow_pass_;  // built at the first frame with shadows
    rl::Image picture_;  // lesson 07 draws here (and the wireframe goes on a copy)
    const rl::Image* frame_ = &picture_;
    FrameStats stats_;
};

}  // namespace viewer
