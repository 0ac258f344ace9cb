// Homogeneous clipping: a triangle in clip space (before the divide by w)
// cut against planes of the view frustum by Sutherland-Hodgman, its
// attributes interpolated at the new vertices. Clipping happens before the
// divide because a vertex behind the eye (w <= 0) has no meaningful window
// position at all; in clip space every plane is linear, so a straight line
// cut is exact. Derivation and pictures: docs/05_perspective.md#clipping.
//
//   const pipeline::ClipPolygon<rl::vec2> polygon = pipeline::clip_triangle(
//       {{{p0, uv0}, {p1, uv1}, {p2, uv2}}},
//       pipeline::clip_planes(pipeline::ClipMode::guard_band, 800, 600));
//   for (int i = 1; i + 1 < polygon.size; ++i)  // a fan: (0, i, i + 1)
//       draw(polygon.vertices[0], polygon.vertices[i], polygon.vertices[i + 1]);
#pragma once

#include <array>
#include <cmath>

#include "rasterlab/named_enum.hpp"
#include "rasterlab/vec.hpp"
#include "varyings.hpp"

namespace pipeline {

// Which planes a triangle is cut against:
//   none        nothing: a vertex with w <= 0 lands on the wrong side of the
//               screen or at infinity (the failure the lab measures);
//   near        the near plane only, so w >= near > 0, but x and y may still
//               run past the rasterizer's 2^22-pixel range;
//   guard_band  near and far, and x, y against a band so wide that no
//               window coordinate passes 2^21 pixels; the rasterizer's own
//               scissor does the rest, and few triangles are ever cut;
//   all         the six planes of the frustum.
enum class ClipMode { none, near, guard_band, all };
RASTERLAB_NAMED_ENUM(ClipMode, kClipModes, {ClipMode::none, "none"}, {ClipMode::near, "near"},
                     {ClipMode::guard_band, "guard-band"}, {ClipMode::all, "all"});

// A plane in clip space: a point p is inside when dot(plane, p) >= 0.
using ClipPlane = rl::vec4;

// The guard band's half-width in NDC units for an image of this size: the
// window x of NDC x = g is (g + 1) / 2 * width, kept within 2^21 pixels, half
// the rasterizer's limit, so that the fixed-point snap adds no overflow.
float guard_band(int width, int height);

// The planes of a mode, at most six (count says how many).
struct ClipPlanes {
    std::array<ClipPlane, 6> planes;
    int count = 0;
};
ClipPlanes clip_planes(ClipMode mode, int width, int height);

// A convex polygon: a triangle cut by k planes has at most 3 + k vertices,
// 9 for the six planes. (A polygon that float rounding has made a little
// non-convex, near the eye, could cross a plane more often than that:
// clip_against refuses it rather than writing past the end.)
template <Interpolable V>
struct ClipPolygon {
    static constexpr int kCapacity = 9;
    std::array<ClipVertex<V>, kCapacity> vertices;
    int size = 0;
};

// [doc:clip-polygon]
// Where the edge from `in` (inside the plane) to `out` crosses it, in the
// clip positions' double. The cut is measured from the inside endpoint, so
// that the same edge gives the same cut in both triangles that share it and
// their common edge cannot crack. Then the coordinate the plane fixes is set
// from the plane's equation (x = -g w for the plane x + g w = 0): between
// endpoints 1e20 apart even double loses a cut at x = -2 (-1e20 + (1e20 - 2)
// rounds to 0), but the cut must lie on the plane, and now does exactly.
template <Interpolable V>
ClipVertex<V> crossing(const ClipVertex<V>& in, const ClipVertex<V>& out, ClipPlane plane) {
    const ClipPosition &p = in.position, &q = out.position, n = rl::cast<double>(plane);
    const double d_in = rl::dot(n, p), d_out = rl::dot(n, q);  // d_in >= 0 > d_out
    const double t = d_in / (d_in - d_out);                    // in [0, 1]
    ClipPosition cut = p + (q - p) * t;
    std::size_t axis = 0;  // the plane's main axis among x, y, z
    for (std::size_t i = 1; i < 3; ++i)
        if (std::abs(n[i]) > std::abs(n[axis])) axis = i;
    if (n[axis] != 0) cut[axis] -= rl::dot(n, cut) / n[axis];  // now dot(n, cut) = 0
    return {cut,
            blend(in.varyings, static_cast<float>(1 - t), out.varyings, static_cast<float>(t))};
}

// One Sutherland-Hodgman pass: keep the vertices inside the plane, and
// where an edge crosses it, add the crossing. The crossing's parameter t
// comes from the signed distances d = dot(plane, p), which are linear along
// the edge in clip space.
template <Interpolable V>
ClipPolygon<V> clip_against(const ClipPolygon<V>& in, ClipPlane plane) {
    ClipPolygon<V> out;
    const auto add = [&out](const ClipVertex<V>& v) {
        if (out.size == ClipPolygon<V>::kCapacity) return false;  // not convex: see above
        out.vertices[static_cast<std::size_t>(out.size++)] = v;
        return true;
    };
    const auto inside = [n = rl::cast<double>(plane)](const ClipVertex<V>& v) {
        return rl::dot(n, v.position) >= 0;
    };
    for (int i = 0; i < in.size; ++i) {
        const ClipVertex<V>& a = in.vertices[static_cast<std::size_t>(i)];
        const ClipVertex<V>& b = in.vertices[static_cast<std::size_t>((i + 1) % in.size)];
        const bool a_inside = inside(a), b_inside = inside(b);
        if (a_inside && !add(a)) return {};
        if (a_inside != b_inside &&  // the edge crosses the plane
            !add(a_inside ? crossing(a, b, plane) : crossing(b, a, plane)))
            return {};
    }
    return out;
}
// [/doc:clip-polygon]

// Whether the triangle needs any cutting against these planes: most do not,
// and they skip clip_triangle's copies.
inline bool inside_all(const ClipPlanes& planes, const ClipPosition (&p)[3]) {
    for (int k = 0; k < planes.count; ++k)
        for (const ClipPosition& q : p)
            if (!(rl::dot(rl::cast<double>(planes.planes[static_cast<std::size_t>(k)]), q) >= 0))
                return false;
    return true;
}

inline bool finite(const ClipPosition& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

// The triangle cut against every plane of the set; empty (size < 3) when
// nothing of it is inside, or when a coordinate is NaN or infinite (such a
// vertex has no place in any plane's half-space).
template <Interpolable V>
ClipPolygon<V> clip_triangle(const std::array<ClipVertex<V>, 3>& triangle,
                             const ClipPlanes& planes) {
    ClipPolygon<V> polygon;
    for (const ClipVertex<V>& v : triangle)
        if (!finite(v.position)) return polygon;
    for (const ClipVertex<V>& v : triangle)
        polygon.vertices[static_cast<std::size_t>(polygon.size++)] = v;
    for (int k = 0; k < planes.count && polygon.size >= 3; ++k)
        polygon = clip_against(polygon, planes.planes[static_cast<std::size_t>(k)]);
    return polygon;
}

}  // namespace pipeline
