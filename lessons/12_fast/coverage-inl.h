// The tile kernels' coverage: which pixel centres of an 8x8 block a triangle
// covers (lesson 02's edge test on the same integers), the barycentric
// weights, and the visibility pass that keeps each pixel's nearest triangle.
// docs/12_fast.md, "The same coverage, bit for bit" and "Depth first, then
// shade once".
// Included by tile_kernels.cpp only, once per instruction set (Highway's
// foreach_target): the guard below lets each pass in once.
#if defined(RASTERLAB_FAST_COVERAGE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef RASTERLAB_FAST_COVERAGE_INL_H_
#undef RASTERLAB_FAST_COVERAGE_INL_H_
#else
#define RASTERLAB_FAST_COVERAGE_INL_H_
#endif

#include <algorithm>
#include <cstdint>
#include <limits>

#include "12_fast/simd_types-inl.h"
#include "12_fast/tile_kernels.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace fast {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Which of the block's 64 pixel centres (block origin: pixel ox, oy) lie
// inside the triangle: lesson 02's test E_k > threshold_k for k = 0, 1, 2,
// on the same 64-bit integers, several pixels per instruction. Blocks wholly
// outside one edge, or wholly inside all three, are decided from the
// block's corners (the edge function is linear: its extremes over the block
// are at corners). Only the rows `rows` are tested: no other row holds a
// centre of the triangle's box.
struct BlockRows {
    int first, last;  // 0 to kBlock - 1
};
HWY_INLINE std::uint64_t block_coverage(const FastTriangle& t, int ox, int oy, BlockRows rows,
                                        bool coarse, TileCounts& counts) {
    // [doc:block-corners]
    std::int64_t origin[3];
    bool inside_all = true;
    for (int k = 0; k < 3; ++k) {
        origin[k] = t.edge_at(k, ox, oy);
        if (!coarse) {
            inside_all = false;
            continue;
        }
        // Per pixel to the right E changes by -dy * 256, per pixel up by dx * 256.
        const std::int64_t step_x = -t.edge_dy[k] * triangles::kSubpixels;
        const std::int64_t step_y = t.edge_dx[k] * triangles::kSubpixels;
        const std::int64_t span = kBlock - 1;
        const std::int64_t most = origin[k] + span * std::max<std::int64_t>(step_x, 0) +
                                  span * std::max<std::int64_t>(step_y, 0);
        const std::int64_t least = origin[k] + span * std::min<std::int64_t>(step_x, 0) +
                                   span * std::min<std::int64_t>(step_y, 0);
        if (most <= t.threshold[k]) {  // every centre outside this edge
            ++counts.blocks_rejected;
            return 0;
        }
        inside_all &= least > t.threshold[k];
    }
    if (inside_all) {
        ++counts.blocks_full;
        return ~std::uint64_t{0};
    }
    // [/doc:block-corners]
    ++counts.blocks_partial;
    const D64 d64;
    const std::size_t n = hn::Lanes(d64);
    std::uint64_t coverage = 0;
    for (int k = 0; k < 3; ++k) {
        const std::int64_t step_x = -t.edge_dy[k] * triangles::kSubpixels;
        const std::int64_t step_y = t.edge_dx[k] * triangles::kSubpixels;
        // E at each column of a row, from the row's start: start + column * step_x.
        // (Highway has no 64-bit multiply on every target: the columns' steps
        // are built by adding.)
        alignas(64) std::int64_t column_step[kBlock];
        for (int c = 0; c < kBlock; ++c) column_step[c] = c * step_x;
        std::uint64_t inside = 0;
        for (int row = rows.first; row <= rows.last; ++row) {
            const std::int64_t start = origin[k] + row * step_y;
            for (int c = 0; c < kBlock; c += static_cast<int>(n)) {
                const auto e = hn::Add(hn::Set(d64, start), hn::LoadU(d64, column_step + c));
                const auto in = hn::Gt(e, hn::Set(d64, t.threshold[k]));
                std::uint8_t bits[8] = {};
                hn::StoreMaskBits(d64, in, bits);
                std::uint64_t word = bits[0];
                if (n > 8) word |= std::uint64_t{bits[1]} << 8;  // (no target has more than 8 here)
                inside |= (word & ((n >= 64 ? 0 : (std::uint64_t{1} << n)) - 1))
                          << (row * kBlock + c);
            }
        }
        coverage = k == 0 ? inside : (coverage & inside);
        if (coverage == 0) break;
    }
    return coverage;
}

// The barycentric weights as lesson 02 computes them, b_k = float(E_k) *
// inverse_area with E_k the exact integer at the pixel centre, in input
// order: the weights, the depth and the texture coordinates are then lesson
// 07's to the last bit, and a `nearest` lookup picks lesson 07's texel.
// E_k is stepped from an origin pixel in double, exact while |E_k| < 2^53
// (FastTriangle::edges_fit_double); beyond that, lane by lane in integers.
struct BlockWeights {
    std::int64_t origin[3], dx[3], dy[3];  // E_k at the origin; per pixel right, per pixel up
};
HWY_INLINE BlockWeights block_weights(const FastTriangle& t, int ox, int oy) {
    BlockWeights w;
    for (int k = 0; k < 3; ++k) {
        w.origin[k] = t.edge_at(k, ox, oy);
        w.dx[k] = -t.edge_dy[k] * triangles::kSubpixels;
        w.dy[k] = t.edge_dx[k] * triangles::kSubpixels;
    }
    return w;
}
// E at `column`, `row` pixels from the origin, rounded once to float.
HWY_INLINE VF edge_values(DF df, const FastTriangle& t, const BlockWeights& w, int k, VF column,
                          VF row) {
#if HWY_TARGET != HWY_SCALAR
    if (t.edges_fit_double) {
        const hn::Half<DF> dh;
        const hn::Repartition<double, DF> dd;
        const auto origin = hn::Set(dd, static_cast<double>(w.origin[k]));
        const auto dx = hn::Set(dd, static_cast<double>(w.dx[k]));
        const auto dy = hn::Set(dd, static_cast<double>(w.dy[k]));
        // Every product and sum is an integer below 2^53: exact, fused or not.
        const auto at = [&](auto columns, auto rows) {
            return hn::DemoteTo(dh, hn::MulAdd(hn::PromoteTo(dd, rows), dy,
                                               hn::MulAdd(hn::PromoteTo(dd, columns), dx, origin)));
        };
        return hn::Combine(df, at(hn::UpperHalf(dh, column), hn::UpperHalf(dh, row)),
                           at(hn::LowerHalf(dh, column), hn::LowerHalf(dh, row)));
    }
#else
    (void)t;
#endif
    alignas(64) float columns[hn::MaxLanes(df)], rows[hn::MaxLanes(df)], out[hn::MaxLanes(df)];
    hn::Store(column, df, columns);
    hn::Store(row, df, rows);
    for (std::size_t lane = 0; lane < hn::Lanes(df); ++lane)
        out[lane] =
            static_cast<float>(w.origin[k] + static_cast<std::int64_t>(columns[lane]) * w.dx[k] +
                               static_cast<std::int64_t>(rows[lane]) * w.dy[k]);
    return hn::Load(df, out);
}
// The weights at `column`, `row` pixels from the origin, in input order.
HWY_INLINE void weights_at(DF df, const FastTriangle& t, const BlockWeights& w, VF column, VF row,
                           VF (&b)[3]) {
    const VF inverse_area = hn::Set(df, t.inverse_area);
    VF e[3];
    for (int k = 0; k < 3; ++k) e[k] = hn::Mul(edge_values(df, t, w, k, column, row), inverse_area);
    b[0] = e[0];
    b[1] = t.swapped ? e[2] : e[1];
    b[2] = t.swapped ? e[1] : e[2];
}
// The weights of a block's slots [first, first + N).
HWY_INLINE void weights_at(DF df, const FastTriangle& t, const BlockWeights& w, int first,
                           VF (&b)[3]) {
    const SlotTables& s = slots();
    weights_at(df, t, w, hn::Load(df, s.column + first), hn::Load(df, s.row + first), b);
}

// The blocks of a triangle's box within the tile, as block indices.
struct BlockRange {
    int first_x, last_x, first_y, last_y;
};
HWY_INLINE BlockRange blocks_of(const FastTriangle& t, const TileWork& work) {
    const int x0 = std::max(t.x0, work.x0) - work.x0,
              x1 = std::min(t.x1, work.x0 + work.width - 1) - work.x0;
    const int y0 = std::max(t.y0, work.y0) - work.y0,
              y1 = std::min(t.y1, work.y0 + work.height - 1) - work.y0;
    if (x0 > x1 || y0 > y1) return {0, -1, 0, -1};
    return {x0 / kBlock, x1 / kBlock, y0 / kBlock, y1 / kBlock};
}

// [doc:small-triangles]
// The small-triangle path: the rows of the block whose bottom row is pixel
// row oy that the triangle's box reaches (a triangle of a pixel or two
// reaches one or two of the eight), and the slots [first, end) of those rows
// in whole vectors of n. No other slot can hold one of its pixels.
HWY_INLINE BlockRows rows_of(const FastTriangle& t, int oy, const Techniques& use) {
    if (!use.block_rows) return {0, kBlock - 1};
    return {std::max(t.y0 - oy, 0), std::min(t.y1 - oy, kBlock - 1)};
}
struct SlotRange {
    int first, end;
};
HWY_INLINE SlotRange slots_of(BlockRows rows, std::size_t n) {
    const int step = static_cast<int>(n);
    return {rows.first * kBlock / step * step, ((rows.last + 1) * kBlock + step - 1) / step * step};
}
// [/doc:small-triangles]

// A vector of fragments shaded (shading-inl.h): what depth_pass calls when
// shade_once is off.
HWY_NOINLINE VU shade(DF df, const Material& m, const FastTriangle& t, const VF (&b)[3], MF active);

// The depth pass over the slots of one block a triangle may cover: depth
// and id stored where the triangle is nearer (and, without shade_once, its
// colour). True where any pixel passed.
HWY_INLINE bool depth_pass(DF df, const TileWork& work, const FastTriangle& t, std::uint32_t index,
                           std::uint64_t coverage, const BlockWeights& w, SlotRange slots,
                           std::size_t base, TileBuffers& buffers, TileCounts& counts) {
    const DU du;
    const std::size_t n = hn::Lanes(df);
    float* depth = buffers.depth.get() + base;
    std::uint32_t* id = buffers.id.get() + base;
    bool changed = false;
    for (int first = slots.first; first < slots.end; first += static_cast<int>(n)) {
        // [doc:depth-pass]
        const MF covered = mask_of(df, coverage, first);
        if (hn::AllFalse(df, covered)) continue;
        VF b[3];
        weights_at(df, t, w, first, b);
        // Lesson 03's interpolate_depth: linear in the weights,
        // clamped to the vertices' range.
        VF z =
            hn::Add(hn::Add(hn::Mul(b[0], hn::Set(df, t.z[0])), hn::Mul(b[1], hn::Set(df, t.z[1]))),
                    hn::Mul(b[2], hn::Set(df, t.z[2])));
        z = hn::Min(hn::Max(z, hn::Set(df, t.z_min)), hn::Set(df, t.z_max));
        // Lesson 05's window_depth: a shadow map's bias, kept in [0, 1].
        if (t.depth_bias != 0)
            z = hn::Min(hn::Max(hn::Add(z, hn::Set(df, t.depth_bias)), hn::Zero(df)),
                        hn::Set(df, 1.0f));
        const VF old = hn::Load(df, depth + first);
        const MF pass = hn::And(covered, hn::Lt(z, old));
        if (hn::AllFalse(df, pass)) continue;
        changed = true;
        counts.depth_passed += hn::CountTrue(df, pass);
        hn::Store(hn::IfThenElse(pass, z, old), df, depth + first);
        const auto pass_u = hn::RebindMask(du, pass);
        const VU old_id = hn::Load(du, id + first);
        hn::Store(hn::IfThenElse(pass_u, hn::Set(du, index), old_id), du, id + first);
        // [/doc:depth-pass]
        if (!work.techniques.shade_once) {
            std::uint32_t* colour = buffers.colour.get() + base + first;
            const VU rgba = shade(df, work.materials[t.model], t, b, pass);
            hn::Store(hn::IfThenElse(pass_u, rgba, hn::Load(du, colour)), du, colour);
            counts.shaded += hn::CountTrue(df, pass);
            counts.lanes += n;
        }
    }
    return changed;
}

// The farthest depth left in a block's 64 pixels (its bound for the
// hierarchical depth test).
HWY_INLINE float farthest_in_block(DF df, const float* depth) {
    VF far = hn::Load(df, depth);
    for (std::size_t first = hn::Lanes(df); first < 64; first += hn::Lanes(df))
        far = hn::Max(far, hn::Load(df, depth + first));
    return hn::GetLane(hn::MaxOfLanes(df, far));
}

// One triangle over one 8x8 block of the tile (bx, by in blocks): skipped
// whole where every pixel is already nearer or none is covered, else the
// depth pass over the slots it may cover, and the block's bound updated.
HWY_INLINE void rasterize_block(DF df, const TileWork& work, const FastTriangle& t,
                                std::uint32_t index, int bx, int by, TileBuffers& buffers,
                                TileCounts& counts) {
    const Techniques& use = work.techniques;
    const std::size_t block = static_cast<std::size_t>(by * (buffers.size / kBlock) + bx);
    // The test is `less`: nothing passes where every pixel is already
    // nearer than the triangle's nearest point.
    if (use.hierarchical_depth && t.z_nearest >= buffers.block_far[block]) {
        ++counts.blocks_occluded;
        return;
    }
    const int ox = work.x0 + bx * kBlock, oy = work.y0 + by * kBlock;
    const BlockRows rows = rows_of(t, oy, use);
    const std::uint64_t coverage = block_coverage(t, ox, oy, rows, use.coarse_blocks, counts);
    if (coverage == 0) return;
    const std::size_t base = block * 64;
    const bool changed = depth_pass(df, work, t, index, coverage, block_weights(t, ox, oy),
                                    slots_of(rows, hn::Lanes(df)), base, buffers, counts);
    if (use.hierarchical_depth && changed)
        buffers.block_far[block] = farthest_in_block(df, buffers.depth.get() + base);
}

// The visibility pass over a tile: depth and the id of the nearest triangle
// at every pixel (or, without shade_once, each passing pixel shaded at once,
// as lesson 07 does), the tile's triangles in drawing order.
void RasterizeTile(const TileWork& work, TileBuffers& buffers, TileCounts& counts) {
    const DF df;
    // The depth state's clear, no triangle anywhere, every block's bound the far plane.
    std::fill(buffers.depth.get(), buffers.depth.get() + buffers.pixels, 1.0f);
    std::fill(buffers.id.get(), buffers.id.get() + buffers.pixels, kNoTriangle);
    std::fill(buffers.block_far.begin(), buffers.block_far.end(), 1.0f);
    const TriangleChunks& triangles = *work.triangles;
    std::size_t piece = 0;
    for (std::size_t i = 0; i < work.bin_size; ++i) {
        const std::uint32_t index = work.bin[i];
        const FastTriangle& t = triangles.at(index, piece);
        const BlockRange r = blocks_of(t, work);
        for (int by = r.first_y; by <= r.last_y; ++by)
            for (int bx = r.first_x; bx <= r.last_x; ++bx)
                rasterize_block(df, work, t, index, bx, by, buffers, counts);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace fast
HWY_AFTER_NAMESPACE();

#endif  // RASTERLAB_FAST_COVERAGE_INL_H_
