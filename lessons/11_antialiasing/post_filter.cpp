#include "post_filter.hpp"

#include <algorithm>
#include <cmath>

#include "06_shading/colour.hpp"

namespace antialiasing {

namespace {

// Perceptual brightness: Rec. 601's weights on the sRGB-encoded channels.
float luma(rl::vec3 c) {
    const auto e = [](float v) { return shading::linear_to_srgb(std::clamp(v, 0.0f, 1.0f)); };
    return 0.299f * e(c.x) + 0.587f * e(c.y) + 0.114f * e(c.z);
}

// The search's step lengths along an edge, in pixels: short near the pixel,
// longer farther out (FXAA's quality preset 12 grows them the same way).
constexpr float kSteps[12] = {1, 1, 1, 1, 1, 1.5f, 2, 2, 2, 2, 4, 8};

class Picture {
  public:
    Picture(const rl::Grid<rl::vec3>& light) : light_(light), luma_(light.width(), light.height()) {
        for (int y = 0; y < light.height(); ++y)
            for (int x = 0; x < light.width(); ++x) luma_.at(x, y) = luma(light.get(x, y));
    }
    // Clamped to the picture's border.
    float luma_at(int x, int y) const {
        return luma_.get(std::clamp(x, 0, luma_.width() - 1), std::clamp(y, 0, luma_.height() - 1));
    }
    // Bilinear in luma along one axis between two pixels (for the search).
    float luma_between(float x, float y) const {
        const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
        const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
        const float a = luma_at(x0, y0) * (1 - fx) + luma_at(x0 + 1, y0) * fx;
        const float b = luma_at(x0, y0 + 1) * (1 - fx) + luma_at(x0 + 1, y0 + 1) * fx;
        return a * (1 - fy) + b * fy;
    }
    rl::vec3 light_at(int x, int y) const {
        return light_.get(std::clamp(x, 0, light_.width() - 1),
                          std::clamp(y, 0, light_.height() - 1));
    }

  private:
    const rl::Grid<rl::vec3>& light_;
    rl::FloatImage luma_;
};

// [doc:edge-filter]
// The filtered light of pixel (x, y).
rl::vec3 filtered(const Picture& p, int x, int y, const EdgeFilterOptions& o) {
    const float c = p.luma_at(x, y), n = p.luma_at(x, y + 1), s = p.luma_at(x, y - 1),
                e = p.luma_at(x + 1, y), w = p.luma_at(x - 1, y);
    const float highest = std::max({c, n, s, e, w}), lowest = std::min({c, n, s, e, w});
    const float range = highest - lowest;
    // 1. Only where brightness steps enough.
    if (range < std::max(o.absolute_threshold, highest * o.relative_threshold))
        return p.light_at(x, y);
    const float ne = p.luma_at(x + 1, y + 1), nw = p.luma_at(x - 1, y + 1),
                se = p.luma_at(x + 1, y - 1), sw = p.luma_at(x - 1, y - 1);
    // 2. Which way the edge runs: a horizontal edge changes most from row
    // to row (second differences down the columns), a vertical one from
    // column to column.
    const float across_rows =
        std::abs(nw + sw - 2 * w) + 2 * std::abs(n + s - 2 * c) + std::abs(ne + se - 2 * e);
    const float across_columns =
        std::abs(nw + ne - 2 * n) + 2 * std::abs(w + e - 2 * c) + std::abs(sw + se - 2 * s);
    const bool horizontal = across_rows >= across_columns;
    // 3. Which side of the pixel the edge lies on: the neighbour across it
    // that differs more.
    const float before = horizontal ? s : w, after = horizontal ? n : e;
    const bool towards_after = std::abs(after - c) >= std::abs(before - c);
    const float other = towards_after ? after : before;
    const float gradient = std::abs(other - c), edge_luma = (c + other) / 2;
    const float side = towards_after ? 0.5f : -0.5f;  // to the edge, across it
    // 4. Walk along the edge both ways until the pair of pixels astride it
    // stops looking like the edge: the step's two ends.
    const float ex = horizontal ? 1.0f : 0.0f, ey = horizontal ? 0.0f : 1.0f;
    const float ox = static_cast<float>(x) + (horizontal ? 0.0f : side),
                oy = static_cast<float>(y) + (horizontal ? side : 0.0f);
    float back = 0, forward = 0;
    bool back_done = false, forward_done = false;
    float back_delta = 0, forward_delta = 0;
    for (int i = 0; i < o.search_steps && (!back_done || !forward_done); ++i) {
        const float step = kSteps[std::min(i, 11)];
        if (!back_done) {
            back += step;
            back_delta = p.luma_between(ox - ex * back, oy - ey * back) - edge_luma;
            back_done = std::abs(back_delta) >= gradient / 4;
        }
        if (!forward_done) {
            forward += step;
            forward_delta = p.luma_between(ox + ex * forward, oy + ey * forward) - edge_luma;
            forward_done = std::abs(forward_delta) >= gradient / 4;
        }
    }
    // 5. The nearer end decides: if the pixel's own brightness is on the
    // same side of the edge's as that end's, the step does not reach it
    // here; else the pixel is covered the more, the nearer it is to the
    // middle of the step: 0.5 - distance / length.
    const bool back_nearer = back < forward;
    const float distance = std::min(back, forward), length = back + forward;
    const float end_delta = back_nearer ? back_delta : forward_delta;
    const bool centre_below = c - edge_luma < 0;
    float blend = (end_delta < 0) != centre_below ? 0.5f - distance / length : 0.0f;
    // 6. A lone pixel brighter or darker than its surroundings (a detail
    // thinner than a pixel): blend by how far it stands out from their mean.
    const float mean = (2 * (n + s + e + w) + ne + nw + se + sw) / 12;
    const float stand_out = std::clamp(std::abs(mean - c) / range, 0.0f, 1.0f);
    const float smooth = stand_out * stand_out * (3 - 2 * stand_out);
    blend = std::max(blend, smooth * smooth * o.subpixel);
    // 7. Read the light that far across the edge, between the pixel and its
    // neighbour there: a linear blend of the two.
    const int nx = x + (horizontal ? 0 : (towards_after ? 1 : -1)),
              ny = y + (horizontal ? (towards_after ? 1 : -1) : 0);
    const rl::vec3 here = p.light_at(x, y), there = p.light_at(nx, ny);
    return here * (1 - blend) + there * blend;
}
// [/doc:edge-filter]

}  // namespace

rl::Grid<rl::vec3> edge_filter(const rl::Grid<rl::vec3>& light, const EdgeFilterOptions& options) {
    const Picture picture(light);
    rl::Grid<rl::vec3> out(light.width(), light.height());
    for (int y = 0; y < light.height(); ++y)
        for (int x = 0; x < light.width(); ++x) out.at(x, y) = filtered(picture, x, y, options);
    return out;
}

}  // namespace antialiasing
