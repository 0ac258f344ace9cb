// How a triangle's coverage is sampled and how often its fragment stage
// runs: the coverage policies lesson 05's draw() takes at its seam
// (pipeline.hpp, "coverage"). Each tests the samples of sample_pattern.hpp
// with lesson 02's rasterizer, fill rule and all: the triangle moved by
// minus a sample's offset puts that sample where the rasterizer tests, at
// the pixel's centre. Derivations and pictures: docs/11_antialiasing.md.
//
//   const antialiasing::Supersampling ssaa{antialiasing::sample_offsets(Pattern::grid, 4)};
//   perspective::RenderTarget<rl::vec3> frame(800, 600, {.samples = 4}, background);
//   perspective::draw(geometry, program, frame, {}, ssaa);
//   const rl::Grid<rl::vec3> picture = perspective::resolve(frame.colour(), 4);
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "05_perspective/pipeline.hpp"

namespace antialiasing {

// What both policies find first for a triangle: the target's samples a
// pixel (one for each offset of the pattern, or std::invalid_argument), the
// rectangle drawn and the depth bias; the samples the rasterizer will visit
// are counted.
struct Sampling {
    int n;
    triangles::PixelRect rect;
    float bias;
};
template <class T, class... Pixels>
Sampling start_sampling(const T& t, const perspective::RenderTarget<Pixels...>& target,
                        std::size_t offsets, const perspective::PipelineOptions& options,
                        perspective::PipelineCounts& counts) {
    const int n = target.samples();
    if (n != static_cast<int>(offsets))
        throw std::invalid_argument("a pattern of " + std::to_string(offsets) +
                                    " samples a pixel needs a target of as many, not " +
                                    std::to_string(n));
    const triangles::PixelRect rect = options.tile.value_or(target.bounds());
    counts.visited += static_cast<std::size_t>(n) * perspective::box_samples(t.screen(), rect);
    return {n, rect, perspective::depth_bias(t, target.depth_state)};
}

// [doc:supersampling]
// Supersampling: every sample tested and shaded on its own, the fragment
// stage run at the sample itself (its weights there), through lesson 05's
// fragment operations. A pixel's cost is its samples' count times one
// sample's: shading, texture reads and all.
struct Supersampling {
    std::vector<rl::vec2> offsets;

    template <class P, class T, class... Pixels>
    bool operator()(const T& t, const P& program, perspective::RenderTarget<Pixels...>& target,
                    const perspective::PipelineOptions& options,
                    perspective::PipelineCounts& counts) const {
        const Sampling sampling = start_sampling(t, target, offsets.size(), options, counts);
        const int n = sampling.n;
        const float bias = sampling.bias;
        bool ok = true;
        for (int s = 0; s < n; ++s)
            ok &= triangles::rasterize(
                options.raster, t.screen(offsets[static_cast<std::size_t>(s)]), sampling.rect,
                [&](int x, int y, rl::vec3 b) {
                    const float z = perspective::window_depth(t, b, bias);
                    if (perspective::fragment_operations(program, t, x, y, z, b, target, n * x + s))
                        ++counts.fragments;
                });
        return ok;
    }
};
// [/doc:supersampling]

// Where multisampling runs the fragment stage in a pixel: at its centre
// (which may lie outside the triangle: its varyings are then extrapolated,
// and a texture can be read beyond the triangle's part of it), or at the
// centroid of the samples the triangle covers (always inside the triangle,
// for a convex pattern).
enum class ShadeAt { centre, centroid };
inline constexpr std::array<rl::Named<ShadeAt>, 2> kShadeAtNames = {
    {{ShadeAt::centre, "centre"}, {ShadeAt::centroid, "centroid"}}};
inline constexpr std::array<ShadeAt, 2> kShadeAts = rl::values_of(kShadeAtNames);
inline const char* name(ShadeAt value) {
    return rl::name_in(kShadeAtNames, value);
}

// The pixels whose samples a triangle may cover, within `rect`: its
// bounding box grown by a pixel on every side (samples lie up to half a
// pixel from their centre); empty for a triangle the rasterizer refuses.
inline triangles::PixelRect box_within(const triangles::ScreenTriangle& t,
                                       const triangles::PixelRect& rect) {
    if (!triangles::within_raster_range(t)) return {rect.x0, rect.y0, rect.x0, rect.y0};
    const auto [x0, x1] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
    const auto [y0, y1] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    const auto clamp = [](float v, int low, int high) {
        return static_cast<int>(std::clamp(v, static_cast<float>(low), static_cast<float>(high)));
    };
    return {clamp(std::floor(x0) - 1, rect.x0, rect.x1),
            clamp(std::floor(y0) - 1, rect.y0, rect.y1), clamp(std::ceil(x1) + 1, rect.x0, rect.x1),
            clamp(std::ceil(y1) + 1, rect.y0, rect.y1)};
}

// [doc:multisampling]
// Multisampling: coverage and depth per sample, the fragment stage once per
// pixel the triangle reaches (at `at`), its outputs stored in every sample
// that it covers and that passed the depth test. A program that discards
// discards the whole pixel's share of the triangle.
struct Multisampling {
    std::vector<rl::vec2> offsets;
    ShadeAt at = ShadeAt::centre;

    template <class P, class T, class... Pixels>
    bool operator()(const T& t, const P& program, perspective::RenderTarget<Pixels...>& target,
                    const perspective::PipelineOptions& options,
                    perspective::PipelineCounts& counts) const {
        const Sampling sampling = start_sampling(t, target, offsets.size(), options, counts);
        const int n = sampling.n;
        const float bias = sampling.bias;
        const zbuffer::DepthState& state = target.depth_state;
        rl::FloatImage* const depth = target.depth();
        // Per sample of the triangle's box within the rectangle (a pixel of
        // margin for samples off the centre): its depth where the triangle
        // covers it (NaN: not covered), and whether that depth passed the test.
        const triangles::PixelRect box = box_within(t.screen(), sampling.rect);
        const int width = box.x1 - box.x0, height = box.y1 - box.y0;
        if (width <= 0 || height <= 0) return triangles::within_raster_range(t.screen());
        std::vector<float> covered(static_cast<std::size_t>(width) * height * n, NAN);
        std::vector<char> passed(covered.size(), 0);
        const auto slot = [&](int x, int y, int s) {
            return (static_cast<std::size_t>(y - box.y0) * width + (x - box.x0)) * n + s;
        };
        bool ok = true;
        for (int s = 0; s < n; ++s)
            ok &= triangles::rasterize(
                options.raster, t.screen(offsets[static_cast<std::size_t>(s)]), box,
                [&](int x, int y, rl::vec3 b) {
                    const float z = perspective::window_depth(t, b, bias);
                    covered[slot(x, y, s)] = z;
                    passed[slot(x, y, s)] =
                        !depth || zbuffer::depth_passes(state.compare, z, depth->at(n * x + s, y));
                });
        const float area2 = triangles::signed_area2(t.screen());
        for (int y = box.y0; y < box.y1; ++y)
            for (int x = box.x0; x < box.x1; ++x) {
                const std::size_t first = slot(x, y, 0);
                if (std::none_of(passed.begin() + static_cast<std::ptrdiff_t>(first),
                                 passed.begin() + static_cast<std::ptrdiff_t>(first + n),
                                 [](char p) { return p != 0; }))
                    continue;
                // Where the fragment stage runs: the centre, or the mean of
                // the covered samples' offsets.
                rl::vec2 where{0, 0};
                if (at == ShadeAt::centroid) {
                    int count = 0;
                    for (int s = 0; s < n; ++s)
                        if (!std::isnan(covered[first + static_cast<std::size_t>(s)]))
                            where = where + offsets[static_cast<std::size_t>(s)], ++count;
                    where = where * (1.0f / static_cast<float>(count));
                }
                const rl::vec3 b = triangles::barycentric(t.screen(),
                                                          {static_cast<float>(x) + 0.5f + where.x,
                                                           static_cast<float>(y) + 0.5f + where.y},
                                                          area2);
                const auto fragment =
                    perspective::fragment_at(t, x, y, perspective::window_depth(t, b, bias), b);
                const auto out = program.fragment(fragment);
                if constexpr (perspective::ProgramTraits<P>::may_discard)
                    if (!out) continue;
                for (int s = 0; s < n; ++s) {
                    const std::size_t i = first + static_cast<std::size_t>(s);
                    if (!passed[i]) continue;
                    if constexpr (sizeof...(Pixels) > 0) {
                        if constexpr (perspective::ProgramTraits<P>::may_discard)
                            perspective::store(target, n * x + s, y, *out);
                        else
                            perspective::store(target, n * x + s, y, out);
                    }
                    if (depth && state.write) depth->at(n * x + s, y) = covered[i];
                    ++counts.fragments;
                }
            }
        return ok;
    }
};
// [/doc:multisampling]

}  // namespace antialiasing
