// How a triangle's coverage is sampled and how often its fragment stage
// runs: the coverage policies lesson 05's draw() takes at its seam
// (pipeline.hpp, "coverage"). Each tests the samples of sample_pattern.hpp
// with lesson 02's edge functions, fill rule and all: the triangle moved by
// minus a sample's offset puts that sample where the rasterizer tests, at
// the pixel's centre. Derivations and pictures: docs/11_antialiasing.md.
//
//   const std::vector<rl::vec2> four = antialiasing::sample_offsets(Pattern::grid, 4);
//   pipeline::RenderTarget<rl::vec3> frame(800, 600, {.samples = 4}, background);
//   pipeline::draw(geometry, program, frame, {}, antialiasing::Multisampling{four});
//   const rl::Grid<rl::vec3> light = antialiasing::resolve(frame.colour(), four, Resolve::box);
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "05_perspective/pipeline.hpp"
#include "sample_pattern.hpp"

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
Sampling start_sampling(const T& t, const pipeline::RenderTarget<Pixels...>& target,
                        std::size_t offsets, const pipeline::PipelineOptions& options,
                        pipeline::PipelineCounts& counts) {
    const int n = target.samples();
    if (n != static_cast<int>(offsets))
        throw std::invalid_argument("a pattern of " + std::to_string(offsets) +
                                    " samples a pixel needs a target of as many, not " +
                                    std::to_string(n));
    const triangles::PixelRect rect = options.tile.value_or(target.bounds());
    counts.visited += static_cast<std::size_t>(n) * pipeline::box_samples(t.screen(), rect);
    return {n, rect, pipeline::depth_bias(t, target.depth_state)};
}

// [doc:supersampling]
// Supersampling: every sample tested and shaded on its own, the fragment
// stage run at the sample itself (its weights there), through lesson 05's
// fragment operations. A pixel's cost is its samples' count times one
// sample's: shading, texture reads and all.
struct Supersampling {
    std::vector<rl::vec2> offsets;

    template <class P, class T, class... Pixels>
    bool operator()(const T& t, const P& program, pipeline::RenderTarget<Pixels...>& target,
                    const pipeline::PipelineOptions& options,
                    pipeline::PipelineCounts& counts) const {
        const Sampling sampling = start_sampling(t, target, offsets.size(), options, counts);
        const int n = sampling.n;
        const float bias = sampling.bias;
        bool ok = true;
        for (int s = 0; s < n; ++s)
            ok &=
                triangles::rasterize(options.raster, t.screen(offsets[static_cast<std::size_t>(s)]),
                                     sampling.rect, [&](int x, int y, rl::vec3 b) {
                                         const float z = pipeline::window_depth(t, b, bias);
                                         pipeline::fragment_operations(program, t, x, y, z, b,
                                                                       target, n * x + s, counts);
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
RASTERLAB_NAMED_ENUM(ShadeAt, kShadeAts, {ShadeAt::centre, "centre"},
                     {ShadeAt::centroid, "centroid"});

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

// A pixel's samples as bits: bit s for sample s (kMaxSamples of them).
using SampleMask = std::uint32_t;

// Lesson 02's edge functions of the triangle moved by minus each sample's
// offset: sample[s].covered(x, y) is whether sample s of pixel (x, y) is
// covered, with the fill rule, and its weights there, as rasterizing the
// moved triangle would find them. Multisampling asks pixel by pixel, which
// only the edge method (the production one) answers: another is refused.
struct SampleEdges {
    std::array<triangles::EdgeWeights, kMaxSamples> sample;
    bool all_in_range = true;  // false: the rasterizer refuses one of the moved triangles
};
template <class T>
SampleEdges sample_edges(const T& t, const std::vector<rl::vec2>& offsets,
                         triangles::RasterMethod method) {
    if (method != triangles::RasterMethod::edge)
        throw std::invalid_argument(
            "multisampling tests each sample with lesson 02's edge functions, not the " +
            std::string(name(method)) + " rasterizer");
    if (offsets.size() > kMaxSamples)
        throw std::invalid_argument("at most " + std::to_string(kMaxSamples) +
                                    " samples a pixel, not " + std::to_string(offsets.size()));
    SampleEdges edges;
    for (std::size_t s = 0; s < offsets.size(); ++s) {
        const triangles::ScreenTriangle moved = t.screen(offsets[s]);
        edges.sample[s] = triangles::EdgeWeights(moved);
        edges.all_in_range &= triangles::within_raster_range(moved);
    }
    return edges;
}

// A pixel's samples after the first pass: those the triangle covers, their
// window depths, and those that passed the depth test.
struct PixelSamples {
    SampleMask covered = 0, passed = 0;
    std::array<float, kMaxSamples> depth;
};
template <class T, class... Pixels>
PixelSamples test_samples(const T& t, const SampleEdges& edges, const Sampling& sampling,
                          const pipeline::RenderTarget<Pixels...>& target, int x, int y) {
    PixelSamples p;
    for (int s = 0; s < sampling.n; ++s) {
        const std::optional<rl::vec3> b = edges.sample[s].covered(x, y);
        if (!b) continue;
        p.covered |= SampleMask{1} << s;
        p.depth[s] = pipeline::window_depth(t, *b, sampling.bias);
        if (pipeline::sample_passes(target, sampling.n * x + s, y, p.depth[s]))
            p.passed |= SampleMask{1} << s;
    }
    return p;
}

// [doc:multisampling]
// Multisampling: coverage and depth per sample, the fragment stage once per
// pixel the triangle reaches (at `at`), its outputs written in every sample
// that it covers and that passed the depth test. Two short passes a pixel
// around its coverage mask, as llvmpipe does: the samples' tests, then (if
// any passed) the fragment stage and the writes. A program that discards
// discards the whole pixel's share of the triangle.
struct Multisampling {
    std::vector<rl::vec2> offsets;
    ShadeAt at = ShadeAt::centre;

    template <class P, class T, class... Pixels>
    bool operator()(const T& t, const P& program, pipeline::RenderTarget<Pixels...>& target,
                    const pipeline::PipelineOptions& options,
                    pipeline::PipelineCounts& counts) const {
        const Sampling sampling = start_sampling(t, target, offsets.size(), options, counts);
        const SampleEdges edges = sample_edges(t, offsets, options.raster);
        const triangles::PixelRect box = box_within(t.screen(), sampling.rect);
        const float area2 = triangles::signed_area2(t.screen());
        for (int y = box.y0; y < box.y1; ++y)
            for (int x = box.x0; x < box.x1; ++x) {
                // 1. Each sample's coverage and depth test.
                const PixelSamples samples = test_samples(t, edges, sampling, target, x, y);
                if (samples.passed == 0) continue;
                // 2. The fragment stage once, its outputs written where the test passed.
                const rl::vec2 where = shading_offset(samples.covered, sampling.n);
                const rl::vec3 b = triangles::barycentric(t.screen(),
                                                          {static_cast<float>(x) + 0.5f + where.x,
                                                           static_cast<float>(y) + 0.5f + where.y},
                                                          area2);
                const float z = pipeline::window_depth(t, b, sampling.bias);
                const auto out =
                    pipeline::shade(program, pipeline::fragment_at(t, x, y, z, b), target, counts);
                if (!out) continue;
                for (int s = 0; s < sampling.n; ++s)
                    if (samples.passed & (SampleMask{1} << s)) {
                        pipeline::write_sample(target, sampling.n * x + s, y, samples.depth[s],
                                               *out);
                        ++counts.stored;
                    }
            }
        return edges.all_in_range;
    }

  private:
    // Where the fragment stage runs, from the pixel's centre: nowhere else,
    // or the mean of the covered samples' offsets.
    rl::vec2 shading_offset(SampleMask covered, int n) const {
        if (at == ShadeAt::centre) return {0, 0};
        rl::vec2 sum{0, 0};
        int count = 0;
        for (int s = 0; s < n; ++s)
            if (covered & (SampleMask{1} << s))
                sum = sum + offsets[static_cast<std::size_t>(s)], ++count;
        return sum * (1.0f / static_cast<float>(count));
    }
};
// [/doc:multisampling]

}  // namespace antialiasing
