#include "fast_triangle.hpp"

#include <algorithm>
#include <cmath>

namespace fast {

bool fast_triangle(const Setup& t, std::uint32_t model, int width, int height, FastTriangle& out) {
    const triangles::ScreenTriangle screen = t.screen();
    if (!triangles::within_raster_range(screen)) return false;
    const triangles::FixedTriangle f = triangles::fixed_triangle(screen);
    FastTriangle& o = out;
    o.model = model;
    if (f.area == 0) {  // lesson 02 draws nothing of it
        o.x0 = o.y0 = 0, o.x1 = o.y1 = -1;
        return true;
    }
    const triangles::FixedPoint* v = f.v;
    const auto [xs, ys] = triangles::centres_in_box(f, {0, 0, width, height});
    o.x0 = xs.first, o.x1 = xs.last, o.y0 = ys.first, o.y1 = ys.last;
    if (o.empty()) return true;  // no centre in its box: the rest would be thrown away
    // [doc:edges]
    for (int k = 0; k < 3; ++k) {
        const triangles::FixedPoint a = v[(k + 1) % 3], b = v[(k + 2) % 3];
        o.edge_x[k] = a.x, o.edge_y[k] = a.y;
        o.edge_dx[k] = b.x - a.x, o.edge_dy[k] = b.y - a.y;
        o.threshold[k] = triangles::is_top_left(a, b) ? -1 : 0;
    }
    // [/doc:edges]
    o.inverse_area = 1.0f / static_cast<float>(f.area);
    // The weights come out in input order, as lesson 02's in_input_order
    // gives them, and every sum over the vertices runs in lesson 05's order:
    // float sums depend on their order, and a texel picked by `nearest`
    // flips on the last bit of a coordinate.
    o.swapped = f.swapped;
    // |E_k| at any centre of the frame is at most |dx| |y - y_k| + |dy| |x - x_k|.
    double most = 0;
    const double fw = (static_cast<double>(width) + 1) * triangles::kSubpixels;
    const double fh = (static_cast<double>(height) + 1) * triangles::kSubpixels;
    for (int k = 0; k < 3; ++k) {
        const double ex = static_cast<double>(o.edge_x[k]), ey = static_cast<double>(o.edge_y[k]);
        most = std::max(most, std::abs(static_cast<double>(o.edge_dx[k])) *
                                      std::max(std::abs(ey), std::abs(fh - ey)) +
                                  std::abs(static_cast<double>(o.edge_dy[k])) *
                                      std::max(std::abs(ex), std::abs(fw - ex)));
    }
    o.edges_fit_double = most < 0x1p52;
    for (int i = 0; i < 3; ++i) {
        o.z[i] = t.window[i].z;
        o.inverse_w[i] = t.inverse_w[i];
        const auto& lanes = std::bit_cast<pipeline::Lanes<Varyings>>(t.over_w[i]);
        std::copy(lanes.begin(), lanes.end(), o.over_w[i]);
    }
    o.z_min = std::min({o.z[0], o.z[1], o.z[2]});
    o.z_max = std::max({o.z[0], o.z[1], o.z[2]});
    o.depth_bias = 0, o.z_nearest = o.z_min;
    o.d_uv_over_w[0][0] = t.d_over_w_dx.uv.x, o.d_uv_over_w[0][1] = t.d_over_w_dx.uv.y;
    o.d_uv_over_w[1][0] = t.d_over_w_dy.uv.x, o.d_uv_over_w[1][1] = t.d_over_w_dy.uv.y;
    o.d_inverse_w[0] = t.d_inverse_w_dx, o.d_inverse_w[1] = t.d_inverse_w_dy;
    return true;
}

}  // namespace fast
