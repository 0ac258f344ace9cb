// The production method: vertices snapped to fixed point (8 sub-pixel bits),
// edge functions evaluated in 64-bit integers and stepped incrementally from
// pixel to pixel, and the top-left rule for pixel centres exactly on an edge,
// so that triangles sharing an edge cover each pixel exactly once.
//
//   const triangles::ScreenTriangle t{{{10.5f, 10}, {90, 20}, {40, 80.25f}}};
//   triangles::rasterize_edge(t, width, height, [&](int x, int y, rl::vec3 b) {
//       depth.set(x, y, triangles::interpolate(b, z0, z1, z2));  // each shared-edge pixel once
//   });
//   const rl::vec3 b = triangles::EdgeWeights(t).at(x, y);  // the same weights at one pixel
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <utility>

#include "screen_triangle.hpp"

namespace triangles {

inline constexpr int kSubpixelBits = 8;
inline constexpr std::int64_t kSubpixels = std::int64_t{1} << kSubpixelBits;  // 256 per pixel

struct FixedPoint {
    std::int64_t x, y;  // in 1/256 pixel
};

inline FixedPoint snap(rl::vec2 p) {
    return {static_cast<std::int64_t>(std::llround(p.x * static_cast<float>(kSubpixels))),
            static_cast<std::int64_t>(std::llround(p.y * static_cast<float>(kSubpixels)))};
}

// Edge a->b of a counter-clockwise triangle. A centre exactly on the edge
// belongs to the triangle when the edge is a left edge (it runs downwards:
// the inside is to its right) or a top edge (horizontal, running to -x: the
// inside is below). See docs/02_triangles.md for the derivation.
// [doc:top-left]
inline bool is_top_left(FixedPoint a, FixedPoint b) {
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
    return dy < 0 || (dy == 0 && dx < 0);
}
// [/doc:top-left]

// The triangle snapped to fixed point and made counter-clockwise (by
// swapping vertices 1 and 2, remembered so that each weight goes back to its
// input vertex), and twice its area in 1/256-pixel units squared (0: it
// covers nothing).
struct FixedTriangle {
    FixedPoint v[3];
    bool swapped;
    std::int64_t area;
    // Weights in the snapped triangle's order, in the input's order.
    rl::vec3 in_input_order(float w0, float w1, float w2) const {
        return swapped ? rl::vec3{w0, w2, w1} : rl::vec3{w0, w1, w2};
    }
};

inline FixedTriangle fixed_triangle(const ScreenTriangle& t) {
    FixedTriangle f{{snap(t.v[0]), snap(t.v[1]), snap(t.v[2])}, false, 0};
    f.area = (f.v[1].x - f.v[0].x) * (f.v[2].y - f.v[0].y) -
             (f.v[1].y - f.v[0].y) * (f.v[2].x - f.v[0].x);
    if (f.area < 0) {  // make it counter-clockwise; remember the swap
        std::swap(f.v[1], f.v[2]);
        f.swapped = true;
        f.area = -f.area;
    }
    return f;
}

// The pixels of `rect` whose centres lie in the snapped triangle's box.
inline PixelBox centres_in_box(const FixedTriangle& f, const PixelRect& rect) {
    const auto to_pixels = [](std::int64_t fixed) {
        return static_cast<float>(fixed) / kSubpixels;
    };
    const auto [x0, x1] = std::minmax({f.v[0].x, f.v[1].x, f.v[2].x});
    const auto [y0, y1] = std::minmax({f.v[0].y, f.v[1].y, f.v[2].y});
    return {centres_between(to_pixels(x0), to_pixels(x1), rect.x0, rect.x1),
            centres_between(to_pixels(y0), to_pixels(y1), rect.y0, rect.y1)};
}

// [doc:raster-edge]
template <class FragmentStage>
bool rasterize_edge(const ScreenTriangle& t, const PixelRect& rect,
                    FragmentStage&& fragment_stage) {
    if (!within_raster_range(t)) return false;  // |x|, |y| <= 2^22: the products fit 62 bits
    const FixedTriangle f = fixed_triangle(t);
    if (f.area == 0) return true;
    const FixedPoint* v = f.v;
    const std::int64_t area = f.area;
    // Edge k runs between the two vertices other than k; E_k > 0 inside.
    struct Edge {
        std::int64_t step_x, step_y, row, bias;
    } e[3];
    const PixelBox box = centres_in_box(f, rect);
    if (box.empty()) return true;
    const PixelRange xs = box.xs, ys = box.ys;
    const FixedPoint start{xs.first * kSubpixels + kSubpixels / 2,
                           ys.first * kSubpixels + kSubpixels / 2};
    for (int k = 0; k < 3; ++k) {
        const FixedPoint a = v[(k + 1) % 3], b = v[(k + 2) % 3];
        e[k].step_x = -(b.y - a.y) * kSubpixels;  // change of E per pixel to the right
        e[k].step_y = (b.x - a.x) * kSubpixels;   // ... and per pixel up
        e[k].row = (b.x - a.x) * (start.y - a.y) - (b.y - a.y) * (start.x - a.x);
        e[k].bias = is_top_left(a, b) ? 0 : -1;  // on the edge: in only for top-left edges
    }
    const float inverse_area = 1.0f / static_cast<float>(area);
    for (int y = ys.first; y <= ys.last; ++y) {
        std::int64_t w0 = e[0].row, w1 = e[1].row, w2 = e[2].row;
        for (int x = xs.first; x <= xs.last; ++x) {
            if ((w0 + e[0].bias) >= 0 && (w1 + e[1].bias) >= 0 && (w2 + e[2].bias) >= 0) {
                fragment_stage(x, y,
                               f.in_input_order(static_cast<float>(w0) * inverse_area,
                                                static_cast<float>(w1) * inverse_area,
                                                static_cast<float>(w2) * inverse_area));
            }
            w0 += e[0].step_x, w1 += e[1].step_x, w2 += e[2].step_x;
        }
        for (Edge& edge : e) edge.row += edge.step_y;
    }
    return true;
}
// [/doc:raster-edge]

// The weights rasterize_edge hands over at pixel (x, y), and whether it
// covers that pixel, computed directly (the same integers as its
// incremental steps, so the same floats and the same fill rule): for a
// caller that asks about one pixel at a time, as lesson 11's multisampling
// asks about each sample of a pixel in turn. The triangle's setup is done
// once, on construction.
class EdgeWeights {
  public:
    EdgeWeights() = default;  // covers nothing
    // (A triangle the rasterizer refuses gets no setup: its products could overflow.)
    explicit EdgeWeights(const ScreenTriangle& t)
        : f_(within_raster_range(t) ? fixed_triangle(t) : FixedTriangle{}),
          inverse_area_(f_.area != 0 ? 1.0f / static_cast<float>(f_.area) : 0.0f) {
        for (int k = 0; k < 3; ++k)
            bias_[k] = is_top_left(f_.v[(k + 1) % 3], f_.v[(k + 2) % 3]) ? 0 : -1;
    }
    rl::vec3 at(int x, int y) const {
        const Edges e = edges(x, y);
        return weights(e);
    }
    // The weights at (x, y) if rasterize_edge covers it, else nothing.
    std::optional<rl::vec3> covered(int x, int y) const {
        if (f_.area == 0) return std::nullopt;
        const Edges e = edges(x, y);
        for (int k = 0; k < 3; ++k)
            if (e[k] + bias_[k] < 0) return std::nullopt;  // on an edge: in only if top-left
        return weights(e);
    }

  private:
    using Edges = std::array<std::int64_t, 3>;  // E_k at the pixel's centre
    Edges edges(int x, int y) const {
        const FixedPoint p{x * kSubpixels + kSubpixels / 2, y * kSubpixels + kSubpixels / 2};
        Edges e;
        for (int k = 0; k < 3; ++k) {
            const FixedPoint a = f_.v[(k + 1) % 3], b = f_.v[(k + 2) % 3];
            e[k] = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        }
        return e;
    }
    rl::vec3 weights(const Edges& e) const {
        return f_.in_input_order(static_cast<float>(e[0]) * inverse_area_,
                                 static_cast<float>(e[1]) * inverse_area_,
                                 static_cast<float>(e[2]) * inverse_area_);
    }

    FixedTriangle f_{};
    float inverse_area_ = 0;
    Edges bias_{};
};

// The whole image: {0, 0, width, height}.
template <class FragmentStage>
bool rasterize_edge(const ScreenTriangle& t, int width, int height,
                    FragmentStage&& fragment_stage) {
    return rasterize_edge(t, PixelRect{0, 0, width, height}, fragment_stage);
}

}  // namespace triangles
