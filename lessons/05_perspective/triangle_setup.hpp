// Stage 4's output and stage 7's input: a triangle after the divide and the
// viewport with the constants its pixels need (TriangleSetup, set_up), and
// one pixel's fragment with its interpolated varyings (Fragment, fragment_at).
// Derivations: docs/05_perspective.md.
//
//   const auto t = pipeline::set_up(a, b, c, pipeline::NoFlat{}, face,
//                                      pipeline::Interpolation::perspective_correct, 800, 600);
//   const auto f = pipeline::fragment_at(t, x, y, z, weights);  // f.varyings, f.d_dx()
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "02_triangles/screen_triangle.hpp"
#include "clipping.hpp"
#include "pipeline_options.hpp"
#include "rasterlab/transform.hpp"
#include "varyings.hpp"

namespace pipeline {

// [doc:triangle-setup]
// The per-triangle constants the per-pixel work needs, computed once after
// the divide and the viewport (a GPU's "triangle setup").
template <Interpolable V, class F = NoFlat>
struct TriangleSetup {
    rl::vec3 window[3];  // x, y in pixels, z the window depth in [0, 1]
    V vertex[3];         // the varyings at the three vertices
    float inverse_w[3];  // 1 / w (all 1 for affine interpolation)
    bool perspective_correct = true;
    V over_w[3];                 // varyings / w
    V d_over_w_dx, d_over_w_dy;  // screen derivatives of sum(b_i varyings_i / w_i) ...
    float d_inverse_w_dx = 0, d_inverse_w_dy = 0;  // ... and of sum(b_i / w_i)
    float depth_slope = 0;                         // max(|dz/dx|, |dz/dy|), for the slope bias
    [[no_unique_address]] F flat{};
    int face = 0;  // the face it came from
    triangles::ScreenTriangle screen(rl::vec2 offset = {}) const {
        return {{window[0].xy() - offset, window[1].xy() - offset, window[2].xy() - offset}};
    }
};

// A value of the divide in float. One past float's range (a vertex just in
// front of the eye when only the near plane clips) becomes +-FLT_MAX, which
// the rasterizer then refuses, rather than an undefined conversion.
inline float to_float(double v) {
    constexpr double kLargest = std::numeric_limits<float>::max();
    return static_cast<float>(std::clamp(v, -kLargest, kLargest));  // (NaN stays NaN)
}
inline rl::vec3 to_float(const rl::dvec3& v) {
    return {to_float(v.x), to_float(v.y), to_float(v.z)};
}

// Divide, viewport, and the constants of one triangle of clip-space vertices
// (their own flat values, G, are not read: `flat` is the triangle's).
template <Interpolable V, class F, class G = NoFlat>
TriangleSetup<V, F> set_up(const ClipVertex<V, G>& a, const ClipVertex<V, G>& b,
                           const ClipVertex<V, G>& c, const F& flat, int face,
                           Interpolation interpolation, int width, int height) {
    TriangleSetup<V, F> t;
    const ClipVertex<V, G>* v[3] = {&a, &b, &c};
    t.perspective_correct = interpolation == Interpolation::perspective_correct;
    for (int k = 0; k < 3; ++k) {
        const ClipPosition& p = v[k]->position;
        const float inverse_w = to_float(1 / p.w);
        t.window[k] = rl::ndc_to_window(to_float(p.xyz() / p.w), width, height);
        t.vertex[k] = v[k]->varyings;
        t.inverse_w[k] = t.perspective_correct ? inverse_w : 1.0f;
        t.over_w[k] = scaled(t.vertex[k], t.inverse_w[k]);
    }
    // The barycentric weight b_k is linear on screen: b_k = E_k / (2 area),
    // where E_k is the edge function of the edge opposite vertex k, so
    // db_k/dx = -(y_j - y_i) / (2 area) and db_k/dy = (x_j - x_i) / (2 area).
    const float area2 = triangles::signed_area2(t.screen());
    const float inverse_area2 = area2 != 0 ? 1 / area2 : 0.0f;
    float dz_dx = 0, dz_dy = 0;
    for (int k = 0; k < 3; ++k) {
        const rl::vec3 &i = t.window[(k + 1) % 3], &j = t.window[(k + 2) % 3];
        const float db_dx = (i.y - j.y) * inverse_area2, db_dy = (j.x - i.x) * inverse_area2;
        t.d_over_w_dx = blend(t.d_over_w_dx, 1.0f, t.over_w[k], db_dx);
        t.d_over_w_dy = blend(t.d_over_w_dy, 1.0f, t.over_w[k], db_dy);
        t.d_inverse_w_dx += t.inverse_w[k] * db_dx;
        t.d_inverse_w_dy += t.inverse_w[k] * db_dy;
        dz_dx += t.window[k].z * db_dx, dz_dy += t.window[k].z * db_dy;
    }
    t.depth_slope = std::max(std::abs(dz_dx), std::abs(dz_dy));
    t.flat = flat;
    t.face = face;
    return t;
}
// [/doc:triangle-setup]

// One pixel (one sample of it) reaching the fragment stage.
template <Interpolable V, class F = NoFlat>
struct Fragment {
    int x, y;
    float depth;
    V varyings;
    float inverse_w;  // interpolated 1 / w at this pixel
    const TriangleSetup<V, F>* triangle;
    int face() const { return triangle->face; }
    const F& flat() const { return triangle->flat; }
    // How the varyings change per pixel to the right (d_dx) and up (d_dy):
    // exact for either interpolation, from the quotient rule on
    // varyings = (varyings / w) / (1 / w), both of which are linear on screen.
    V d_dx() const {
        return scaled(blend(triangle->d_over_w_dx, 1.0f, varyings, -triangle->d_inverse_w_dx),
                      1 / inverse_w);
    }
    V d_dy() const {
        return scaled(blend(triangle->d_over_w_dy, 1.0f, varyings, -triangle->d_inverse_w_dy),
                      1 / inverse_w);
    }
    // The same for one member only (f.d_dx(&Varyings::uv)): a fragment stage
    // that needs the derivatives of its texture coordinates alone skips the rest.
    template <class M, class W = V>
    M d_dx(M W::*member) const {
        return (triangle->d_over_w_dx.*member + varyings.*member * -triangle->d_inverse_w_dx) *
               (1 / inverse_w);
    }
    template <class M, class W = V>
    M d_dy(M W::*member) const {
        return (triangle->d_over_w_dy.*member + varyings.*member * -triangle->d_inverse_w_dy) *
               (1 / inverse_w);
    }
};

// The fragment at barycentric weights b: perspective-correct varyings are
// b . (varyings / w) divided by b . (1 / w); affine ones are b . varyings.
template <Interpolable V, class F>
Fragment<V, F> fragment_at(const TriangleSetup<V, F>& t, int x, int y, float z, rl::vec3 b) {
    const V over_w = weighted(t.over_w, b);
    if (!t.perspective_correct) return {x, y, z, over_w, 1.0f, &t};
    const float inverse_w = b.x * t.inverse_w[0] + b.y * t.inverse_w[1] + b.z * t.inverse_w[2];
    return {x, y, z, scaled(over_w, 1 / inverse_w), inverse_w, &t};
}

}  // namespace pipeline
