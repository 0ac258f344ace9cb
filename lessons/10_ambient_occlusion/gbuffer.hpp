// The first pass of a deferred renderer: the scene drawn once into a
// G-buffer, several images of what each pixel sees, for later passes to
// read instead of the triangles. Here: the direct light (lesson 08's key
// light through its shadow map, and the fill light), the albedo, the
// surface normal (interpolated, world space) and the depth. The ambient
// light is left out: it is added later, darkened by ambient occlusion.
// Derivation and pictures: docs/10_ambient_occlusion.md#the-g-buffer.
//
//   const occlusion::GBuffer g = occlusion::render_gbuffer(models, camera, options, map, 800, 800);
//   const occlusion::Screen screen(camera, 800, 800);
//   const std::optional<rl::vec3> p = screen.position(g, 400, 400);  // world space
#pragma once

#include <optional>
#include <tuple>

#include "08_shadows/scene.hpp"
#include "09_environment/scene.hpp"

namespace occlusion {

// Three colour attachments and depth: direct light (linear, HDR), albedo
// (linear) and the unit world normal; 0 where no model is.
using GBuffer = pipeline::RenderTarget<rl::vec3, rl::vec3, rl::vec3>;
inline constexpr std::size_t kDirect = 0, kAlbedo = 1, kNormal = 2;

// [doc:gbuffer-shader]
// Lesson 08's shader, told there is no ambient term, writing three values
// a pixel instead of one colour.
struct GBufferShader {
    shadows::ShadowedShader lit;
    using Varyings = shadows::ShadowedShader::Varyings;

    pipeline::ClipVertex<Varyings> vertex(const shading::SurfaceCorner& in) const {
        return lit.vertex(in);
    }
    std::tuple<rl::vec3, rl::vec3, rl::vec3> fragment(const pipeline::Fragment<Varyings>& f) const {
        const rl::vec2 dx = f.d_dx(&Varyings::uv), dy = f.d_dy(&Varyings::uv);
        return {lit.fragment(f), lit.surface.u.albedo(f.varyings.uv, dx, dy),
                rl::normalize(f.varyings.normal)};
    }
};
// [/doc:gbuffer-shader]

// The G-buffer of the scene from `camera`: lesson 08's second pass with
// its ambient term set to 0 (options.render.lighting.ambient is ignored).
GBuffer render_gbuffer(const std::vector<normal_mapping::MappedModel>& models,
                       const pipeline::Camera& camera, const shadows::ShadowOptions& options,
                       const shadows::ShadowMap& map, int width, int height,
                       pipeline::PipelineCounts* counts = nullptr);

// Between the screen and the world for one camera and image size: a
// pixel's surface point from the depth buffer, and where a world point
// lands on the screen.
class Screen {
  public:
    Screen(const pipeline::Camera& camera, int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    // The view depth (distance along the viewing axis) of window depth z:
    // the inverse of z = (1/near - 1/d) / (1/near - 1/far).
    float view_depth(float window_depth) const;
    // The world point seen at pixel (x, y), or nothing where the depth is
    // the clear value (no model).
    std::optional<rl::vec3> position(const GBuffer& g, int x, int y) const;
    // The world point at view depth d along the ray through window point (x, y).
    rl::vec3 at_depth(float x, float y, float d) const;
    // Where a world point lands: window x, y and its view depth (w).
    rl::vec3 project(rl::vec3 p) const;
    // The unit ray from the eye through window point (x, y).
    rl::vec3 ray(float x, float y) const { return rays_.ray(x, y); }
    // A world point's view depth.
    float depth_of(rl::vec3 p) const { return rl::dot(p - eye_, forward_); }
    // How many pixels a length of 1 spans at view depth d (at the screen's centre).
    float pixels_per_unit(float d) const { return focal_ / d; }
    rl::vec3 eye() const { return eye_; }
    rl::vec3 right() const { return right_; }
    rl::vec3 up() const { return up_; }

  private:
    rl::mat4 view_projection_;
    environment::PixelRays rays_;
    rl::vec3 eye_, forward_, right_, up_;
    float inverse_near_, inverse_span_, focal_;
    int width_, height_;
};

}  // namespace occlusion
