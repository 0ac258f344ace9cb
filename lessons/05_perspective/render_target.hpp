// Where a draw writes: a render target owns its size and holds any number
// of colour attachments, each an image of its own pixel type (8-bit
// rl::Rgba, float, linear rl::vec3 HDR, normals, ids ...), and an optional
// depth attachment with its state (lesson 03's compare, write, clear, bias).
// A target may store several samples per pixel, side by side, for a
// coverage policy other than lesson 05's to fill (pipeline.hpp): where they
// lie, how many a pattern has and how they become one pixel (the resolve)
// are lesson 11's. A target with no colour attachment is a depth-only pass
// (how a shadow map is rendered).
//
//   pipeline::RenderTarget<rl::Rgba, rl::vec3> frame(800, 600);
//   pipeline::draw(geometry, program, frame);   // fragment() returns {rgba, normal}
//   pipeline::RenderTarget<> shadow_map(1024, 1024);  // depth only
//   pipeline::RenderTarget<rl::vec3> samples(800, 600, {.samples = 4}, rl::vec3{});
//   pipeline::draw(geometry, program, samples, {}, multisampling);  // lesson 11's policy
#pragma once

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "02_triangles/screen_triangle.hpp"
#include "03_zbuffer/depth_test.hpp"
#include "rasterlab/image.hpp"
#include "varyings.hpp"

namespace pipeline {

struct TargetOptions {
    int samples = 1;  // per pixel, at least 1 (with the width, at most an int's range of columns)
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
        if (samples_ < 1 || width > std::numeric_limits<int>::max() / samples_)
            throw std::invalid_argument("a target of " + std::to_string(width) +
                                        " pixels a row cannot hold " + std::to_string(samples_) +
                                        " samples a pixel");
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

}  // namespace pipeline
