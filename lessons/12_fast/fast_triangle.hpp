// One triangle as the fast path's tiles read it, set up once per frame: lesson
// 02's fixed-point edge functions (the same integers, so the same coverage,
// bit for bit) and, in the snapped triangle's vertex order, everything the
// depth test and the shader interpolate: window depth, 1/w and the varyings
// divided by w (lesson 05's perspective-correct interpolation), with the
// screen derivatives lesson 05 uses for the mip level.
//
//   fast::FastTriangle t;
//   if (!fast::fast_triangle(setup, model, width, height, t)) { /* refused: count it */ }
//   else if (t.empty()) { /* no pixel centre inside: skip */ }
#pragma once

#include <cstdint>
#include <vector>

#include "02_triangles/raster_edge.hpp"
#include "05_perspective/pipeline.hpp"
#include "07_normal_mapping/normal_mapped.hpp"

namespace fast {

using Varyings = normal_mapping::NormalMappedShader::Varyings;
inline constexpr int kVaryingFloats = sizeof(Varyings) / sizeof(float);  // 12
using Setup = pipeline::TriangleSetup<Varyings>;

struct FastTriangle {
    // Edge k (opposite vertex k) as lesson 02 evaluates it at a pixel centre
    // p, in 1/256 pixel: E_k(p) = a_k (p.y - y_k) - b_k (p.x - x_k), with
    // (x_k, y_k) the edge's first vertex; the centre is inside when E_k > threshold_k
    // for all three (threshold -1 on a top-left edge: E >= 0; else 0: E > 0).
    std::int64_t edge_x[3], edge_y[3], edge_dx[3], edge_dy[3], threshold[3];
    float inverse_area;        // 1 / (2 area) in the same units: weight b_k = E_k * inverse_area
    bool swapped;              // lesson 02 swapped vertices 1 and 2: edge 1 is opposite vertex 2
    bool edges_fit_double;     // |E_k| < 2^53 over the frame: exact when stepped in double
    int x0, y0, x1, y1;        // the pixel centres of its box, inclusive, within the frame
    float z[3], z_min, z_max;  // window depth at the vertices (in input order, as lesson 05's)
    // Lesson 08's depth bias (0 but in a shadow map's pass), added to each
    // sample's depth before its test, and the nearest depth it can give:
    // z_min with the bias, kept in [0, 1] (the hierarchical test's bound).
    float depth_bias = 0, z_nearest;
    float inverse_w[3];               // 1 / w
    float over_w[3][kVaryingFloats];  // varyings / w
    float d_uv_over_w[2][2];          // d(uv / w)/dx, d(uv / w)/dy  (u then v)
    float d_inverse_w[2];             // d(1/w)/dx, d(1/w)/dy
    std::uint32_t model;              // which model's material shades it
    bool empty() const { return x0 > x1 || y0 > y1; }
    // E_k at the centre of pixel (x, y), exactly as lesson 02 computes it.
    std::int64_t edge_at(int k, int x, int y) const {
        const std::int64_t px = std::int64_t{x} * triangles::kSubpixels + triangles::kSubpixels / 2;
        const std::int64_t py = std::int64_t{y} * triangles::kSubpixels + triangles::kSubpixels / 2;
        return edge_dx[k] * (py - edge_y[k]) - edge_dy[k] * (px - edge_x[k]);
    }
};

// A frame's set-up triangles in drawing order, kept in the pieces the
// threads set them up in: copying them into one array would cost about as
// much as setting them up (some 350 bytes a triangle). Triangle i is piece
// c's triangle i - start[c], for the c with start[c] <= i < start[c + 1].
struct TriangleChunks {
    std::vector<const FastTriangle*> data;  // per piece
    std::vector<std::uint32_t> start;       // per piece, then the total
    std::uint32_t size() const { return start.empty() ? 0 : start.back(); }
    // Triangle i. `piece` is where the last lookup found its triangle: a
    // tile reads its triangles in increasing order, so the search only
    // ever steps forwards (it starts again from 0 if i went back).
    const FastTriangle& at(std::uint32_t i, std::size_t& piece) const {
        if (piece >= data.size() || i < start[piece]) piece = 0;
        while (i >= start[piece + 1]) ++piece;
        return data[piece][i - start[piece]];
    }
};

// The fast triangle of a set-up triangle (lesson 05's set_up), clipped to a
// width x height frame. Returns false when lesson 02's rasterizer would refuse
// it (beyond 2^22 pixels, NaN); `out` is then untouched. A triangle of zero
// area comes back empty, as lesson 02 draws nothing of it.
bool fast_triangle(const Setup& t, std::uint32_t model, int width, int height, FastTriangle& out);

}  // namespace fast
