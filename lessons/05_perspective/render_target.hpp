// Where a draw writes: a render target owns its size and holds any number
// of colour attachments, each an image of its own pixel type (8-bit
// rl::Rgba, float, linear rl::vec3 HDR, normals, ids ...), and an optional
// depth attachment with its state (lesson 03's compare, write, clear, bias).
// A target may hold several samples per pixel, which a coverage policy
// other than lesson 05's fills (pipeline.hpp); resolve() averages them into
// one image per attachment. A target with no colour attachment is a
// depth-only pass (how a shadow map is rendered).
//
//   perspective::RenderTarget<rl::Rgba, rl::vec3> frame(800, 600);
//   perspective::draw(geometry, program, frame);   // fragment() returns {rgba, normal}
//   perspective::RenderTarget<> shadow_map(1024, 1024);  // depth only
//   perspective::TargetOptions four;  four.samples = 4;
//   perspective::ColourTarget smooth(800, 600, four, rl::kBackground);
//   perspective::draw(geometry, program, smooth, {}, four_samples);  // a policy of 4 samples
//   const rl::Image picture = perspective::resolve(smooth.colour(), smooth.samples());
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "02_triangles/screen_triangle.hpp"
#include "03_zbuffer/depth_test.hpp"
#include "rasterlab/image.hpp"
#include "varyings.hpp"

namespace perspective {

inline bool valid_sample_count(int samples) {
    return samples == 1 || samples == 2 || samples == 4 || samples == 8 || samples == 16;
}

struct TargetOptions {
    int samples = 1;  // per pixel: 1, 2, 4, 8 or 16
    bool has_depth = true;
    zbuffer::DepthState depth;
};

// Each attachment stores a pixel's samples side by side: sample s of pixel
// (x, y) at (x * samples + s, y). With one sample an attachment is a plain
// image, ready to save.
template <class... Pixels>
class RenderTarget {
  public:
    explicit RenderTarget(int width, int height, const TargetOptions& options = {},
                          Pixels... clear_values)
        : depth_state(options.depth), width_(width), height_(height), samples_(options.samples) {
        if (!valid_sample_count(samples_))
            throw std::invalid_argument("samples per pixel must be 1, 2, 4, 8 or 16, not " +
                                        std::to_string(samples_));
        colour_ = {rl::Grid<Pixels>(width * samples_, height, clear_values)...};
        if (options.has_depth)
            depth_ = rl::FloatImage(width * samples_, height, options.depth.clear);
    }

    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }
    triangles::PixelRect bounds() const { return {0, 0, width_, height_}; }

    // Between frames, what glClear does: every colour attachment back to the
    // given values and the depth to its state's clear value, in place (a
    // frame loop then allocates nothing).
    void clear(Pixels... clear_values) {
        std::apply([&](auto&... grids) { (grids.fill(clear_values), ...); }, colour_);
        if (!depth_.empty()) depth_.fill(depth_state.clear);
    }

    template <std::size_t I = 0>
    auto& colour() {
        return std::get<I>(colour_);
    }
    template <std::size_t I = 0>
    const auto& colour() const {
        return std::get<I>(colour_);
    }

    rl::FloatImage* depth() { return depth_.empty() ? nullptr : &depth_; }
    const rl::FloatImage* depth() const { return depth_.empty() ? nullptr : &depth_; }

    zbuffer::DepthState depth_state;

  private:
    int width_, height_, samples_;
    std::tuple<rl::Grid<Pixels>...> colour_;
    rl::FloatImage depth_;  // empty: no depth attachment
};

// The frame of lessons 05-07: one 8-bit colour image and a depth buffer.
using ColourTarget = RenderTarget<rl::Rgba>;

inline ColourTarget colour_target(int width, int height, rl::Rgba background = rl::kBackground) {
    return ColourTarget(width, height, {}, background);
}

// A width x height frame cut into tiles of size x size pixels (smaller at
// the right and top edges), row by row from the bottom left; a draw limited
// to each tile in turn (PipelineOptions::tile) gives the whole frame.
inline std::vector<triangles::PixelRect> tiles(int width, int height, int size) {
    if (size < 1) throw std::invalid_argument("a tile must be at least 1 pixel wide");
    std::vector<triangles::PixelRect> out;
    for (int y = 0; y < height; y += size)
        for (int x = 0; x < width; x += size)
            out.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
    return out;
}

// The mean of a pixel's samples: bytes rounded to nearest, anything made of
// floats averaged in double (so that equal samples give back exactly their
// value).
template <class Pixel>
Pixel average(const Pixel* samples, int count) {
    if constexpr (std::is_same_v<Pixel, rl::Rgba>) {
        int sum[4] = {0, 0, 0, 0};
        for (int s = 0; s < count; ++s) {
            sum[0] += samples[s].r, sum[1] += samples[s].g;
            sum[2] += samples[s].b, sum[3] += samples[s].a;
        }
        const auto mean = [count](int v) {
            return static_cast<std::uint8_t>((v + count / 2) / count);
        };
        return {mean(sum[0]), mean(sum[1]), mean(sum[2]), mean(sum[3])};
    } else {
        static_assert(Interpolable<Pixel> && !std::is_integral_v<Pixel>,
                      "resolve averages bytes or types made of floats (ids cannot be averaged)");
        std::array<double, sizeof(Pixel) / sizeof(float)> sum{};
        for (int s = 0; s < count; ++s) {
            const Lanes<Pixel> lanes = std::bit_cast<Lanes<Pixel>>(samples[s]);
            for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += lanes[i];
        }
        Lanes<Pixel> mean;
        for (std::size_t i = 0; i < sum.size(); ++i) mean[i] = static_cast<float>(sum[i] / count);
        return std::bit_cast<Pixel>(mean);
    }
}

// One image of width x height from an attachment of `samples` per pixel.
template <class Pixel>
rl::Grid<Pixel> resolve(const rl::Grid<Pixel>& attachment, int samples) {
    rl::Grid<Pixel> out(attachment.width() / samples, attachment.height());
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x)
            out.at(x, y) = average(&attachment.at(x * samples, y), samples);
    return out;
}

}  // namespace perspective
