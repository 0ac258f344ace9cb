// The tile kernels, compiled once per instruction set Highway targets
// (foreach_target re-includes this file for each) and chosen at run time.
// Every formula follows lesson 07's scalar code in the same order, so that
// the image matches lesson 07's within its golden tolerance; what changes is
// that each line works on a vector of pixels. Derivations: docs/12_fast.md.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include "06_shading/colour.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "12_fast/tile_kernels.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
// (after foreach_target)
#include "12_fast/tile_kernels.hpp"
#include "hwy/contrib/math/math-inl.h"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace fast {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using DU = hn::RebindToUnsigned<DF>;
using D64 = hn::ScalableTag<std::int64_t>;
using VF = hn::Vec<DF>;
using VI = hn::Vec<DI>;
using VU = hn::Vec<DU>;
using MF = hn::Mask<DF>;

// The slots of a block: column (slot % 8) and row (slot / 8), as floats
// (slot = row * 8 + column, the bit of a 64-bit coverage word).
struct SlotTables {
    alignas(64) float column[64], row[64];
    SlotTables() {
        for (int s = 0; s < 64; ++s) {
            column[s] = static_cast<float>(s % kBlock);
            row[s] = static_cast<float>(s / kBlock);
        }
    }
};
const SlotTables& slots() {
    static const SlotTables tables;
    return tables;
}

// The lanes [first, first + N) of a 64-bit coverage word as a mask.
HWY_INLINE MF mask_of(DF df, std::uint64_t coverage, int first) {
    const std::uint64_t bits = coverage >> first;
    std::uint8_t bytes[8];
    std::memcpy(bytes, &bits, sizeof bytes);
    return hn::LoadMaskBits(df, bytes);
}

// ---------------------------------------------------------------- coverage

// Which of the block's 64 pixel centres (block origin: pixel ox, oy) lie
// inside the triangle: lesson 02's test E_k > threshold_k for k = 0, 1, 2,
// on the same 64-bit integers, several pixels per instruction. Blocks wholly
// outside one edge, or wholly inside all three, are decided from the
// block's corners (the edge function is linear: its extremes over the block
// are at corners).
HWY_INLINE std::uint64_t block_coverage(const FastTriangle& t, int ox, int oy, bool coarse,
                                        TileCounts& counts) {
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
        for (int row = 0; row < kBlock; ++row) {
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

// The visibility pass: depth and the id of the nearest triangle at every
// pixel (or, without shade_once, each passing pixel shaded at once, as
// lesson 07 does).
HWY_NOINLINE VU shade(DF df, const Material& m, const FastTriangle& t, const VF (&b)[3]);

void RasterizeTile(const TileWork& work, TileBuffers& buffers, TileCounts& counts) {
    const DF df;
    const DU du;
    const std::size_t n = hn::Lanes(df);
    const Techniques& use = work.techniques;
    const int blocks_per_row = buffers.size / kBlock;
    std::fill(buffers.depth.get(), buffers.depth.get() + buffers.pixels,
              1.0f);  // the depth state's clear
    std::fill(buffers.id.get(), buffers.id.get() + buffers.pixels, kNoTriangle);
    std::fill(buffers.block_far.begin(), buffers.block_far.end(), 1.0f);
    const TriangleChunks& triangles = *work.triangles;
    std::size_t piece = 0;
    for (std::size_t i = 0; i < work.bin_size; ++i) {
        const std::uint32_t index = work.bin[i];
        const FastTriangle& t = triangles.at(index, piece);
        const BlockRange r = blocks_of(t, work);
        for (int by = r.first_y; by <= r.last_y; ++by)
            for (int bx = r.first_x; bx <= r.last_x; ++bx) {
                const std::size_t block = static_cast<std::size_t>(by * blocks_per_row + bx);
                // The test is `less`: nothing passes where every pixel is
                // already nearer than the triangle's nearest point.
                if (use.hierarchical_depth && t.z_min >= buffers.block_far[block]) {
                    ++counts.blocks_occluded;
                    continue;
                }
                const int ox = work.x0 + bx * kBlock, oy = work.y0 + by * kBlock;
                const std::uint64_t coverage = block_coverage(t, ox, oy, use.coarse_blocks, counts);
                if (coverage == 0) continue;
                const BlockWeights w = block_weights(t, ox, oy);
                const std::size_t base = block * 64;
                float* depth = buffers.depth.get() + base;
                std::uint32_t* id = buffers.id.get() + base;
                bool changed = false;
                for (int first = 0; first < 64; first += static_cast<int>(n)) {
                    // [doc:depth-pass]
                    const MF covered = mask_of(df, coverage, first);
                    if (hn::AllFalse(df, covered)) continue;
                    VF b[3];
                    weights_at(df, t, w, first, b);
                    // Lesson 03's interpolate_depth: linear in the weights,
                    // clamped to the vertices' range.
                    VF z = hn::Add(hn::Add(hn::Mul(b[0], hn::Set(df, t.z[0])),
                                           hn::Mul(b[1], hn::Set(df, t.z[1]))),
                                   hn::Mul(b[2], hn::Set(df, t.z[2])));
                    z = hn::Min(hn::Max(z, hn::Set(df, t.z_min)), hn::Set(df, t.z_max));
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
                    if (!use.shade_once) {
                        std::uint32_t* colour = buffers.colour.get() + base + first;
                        const VU rgba = shade(df, work.materials[t.model], t, b);
                        hn::Store(hn::IfThenElse(pass_u, rgba, hn::Load(du, colour)), du, colour);
                        counts.shaded += hn::CountTrue(df, pass);
                        counts.lanes += n;
                    }
                }
                if (use.hierarchical_depth && changed) {
                    VF far = hn::Load(df, depth);
                    for (std::size_t first = n; first < 64; first += n)
                        far = hn::Max(far, hn::Load(df, depth + first));
                    buffers.block_far[block] = hn::GetLane(hn::MaxOfLanes(df, far));
                }
            }
    }
}

// ---------------------------------------------------------------- sampling

struct Vec3 {
    VF x, y, z;
};
HWY_INLINE VF dot(const Vec3& a, const Vec3& b) {
    return hn::MulAdd(a.z, b.z, hn::MulAdd(a.y, b.y, hn::Mul(a.x, b.x)));
}
HWY_INLINE Vec3 scale(const Vec3& a, VF s) {
    return {hn::Mul(a.x, s), hn::Mul(a.y, s), hn::Mul(a.z, s)};
}
HWY_INLINE Vec3 sub(const Vec3& a, const Vec3& b) {
    return {hn::Sub(a.x, b.x), hn::Sub(a.y, b.y), hn::Sub(a.z, b.z)};
}
HWY_INLINE Vec3 add(const Vec3& a, const Vec3& b) {
    return {hn::Add(a.x, b.x), hn::Add(a.y, b.y), hn::Add(a.z, b.z)};
}
HWY_INLINE Vec3 select(MF m, const Vec3& a, const Vec3& b) {
    return {hn::IfThenElse(m, a.x, b.x), hn::IfThenElse(m, a.y, b.y), hn::IfThenElse(m, a.z, b.z)};
}
// 1 / sqrt(x) to within a float's last bit or two: the estimate the CPU
// gives (12 or 14 bits) and one Newton step, in place of a square root and a
// division (several times cheaper; the byte written is the same but for a
// pixel in tens of thousands, inside lesson 07's golden tolerance).
HWY_INLINE VF inverse_sqrt(DF df, VF x) {
    const VF y = hn::ApproximateReciprocalSqrt(x);
    const VF half_x = hn::Mul(x, hn::Set(df, 0.5f));
    return hn::Mul(y, hn::NegMulAdd(half_x, hn::Mul(y, y), hn::Set(df, 1.5f)));
}
// rl::normalize: v / |v|, the zero vector left zero.
HWY_INLINE Vec3 normalize(DF df, const Vec3& v) {
    const VF squared = dot(v, v);
    const VF inverse = hn::IfThenElseZero(hn::Gt(squared, hn::Zero(df)), inverse_sqrt(df, squared));
    return scale(v, inverse);
}
HWY_INLINE Vec3 cross(const Vec3& a, const Vec3& b) {
    return {hn::Sub(hn::Mul(a.y, b.z), hn::Mul(a.z, b.y)),
            hn::Sub(hn::Mul(a.z, b.x), hn::Mul(a.x, b.z)),
            hn::Sub(hn::Mul(a.x, b.y), hn::Mul(a.y, b.x))};
}
HWY_INLINE Vec3 broadcast(DF df, const float* v) {
    return {hn::Set(df, v[0]), hn::Set(df, v[1]), hn::Set(df, v[2])};
}

// A texel's channels as values in [0, 1]: byte / 255, or for a decoded
// texture the 16-bit values.
struct Texel {
    VF c[3];
};
struct Fetched {
    VU word, blue;  // blue: decoded textures only
};
HWY_INLINE VU gather_words(const std::vector<std::uint32_t>& words, VI index) {
    return hn::BitCast(
        DU(), hn::GatherIndex(DI(), reinterpret_cast<const std::int32_t*>(words.data()), index));
}
HWY_INLINE Fetched fetch(const PackedTexture& t, VI index, int channels) {
    Fetched f{gather_words(t.texels, index), hn::Zero(DU())};
    if (t.decoded && channels > 2) f.blue = gather_words(t.blue_words, index);
    return f;
}
// The texels at index and index + 1 of every lane: a row's two texels of a
// bilinear lookup, side by side in the packed rows. One 64-bit gather per
// half of the lanes fetches both, in place of two 32-bit gathers of all.
HWY_INLINE void gather_pairs(const std::vector<std::uint32_t>& words, VI index, VU& left,
                             VU& right) {
    const DU du;
#if HWY_TARGET == HWY_SCALAR
    left = gather_words(words, index);
    right = gather_words(words, hn::Add(index, hn::Set(DI(), 1)));
    (void)du;
#else
    const hn::Half<DI> dh;
    const hn::Repartition<std::uint64_t, DU> d64;
    const hn::RebindToSigned<decltype(d64)> di64;
    const auto* base = reinterpret_cast<const std::uint64_t*>(words.data());
    // Byte offsets: the pairs start at any 32-bit word.
    const auto lower = hn::ShiftLeft<2>(hn::PromoteTo(di64, hn::LowerHalf(dh, index)));
    const auto upper = hn::ShiftLeft<2>(hn::PromoteTo(di64, hn::UpperHalf(dh, index)));
    const VU lo = hn::BitCast(du, hn::GatherOffset(d64, base, lower));
    const VU hi = hn::BitCast(du, hn::GatherOffset(d64, base, upper));
    left = hn::ConcatEven(du, hi, lo);  // the first word of each pair
    right = hn::ConcatOdd(du, hi, lo);
#endif
}
HWY_INLINE void fetch_pairs(const PackedTexture& t, VI index, int channels, Fetched& left,
                            Fetched& right) {
    gather_pairs(t.texels, index, left.word, right.word);
    left.blue = right.blue = hn::Zero(DU());
    if (t.decoded && channels > 2) gather_pairs(t.blue_words, index, left.blue, right.blue);
}
HWY_INLINE VF channel(DF df, const PackedTexture& t, const Fetched& f, int c) {
    const DI di;
    if (t.decoded) {
        const VU word = c == 0   ? hn::And(f.word, hn::Set(DU(), 0xffffu))
                        : c == 1 ? hn::ShiftRight<16>(f.word)
                                 : f.blue;
        return hn::Mul(hn::ConvertTo(df, hn::BitCast(di, word)), hn::Set(df, 1.0f / 65535));
    }
    const VI byte =
        hn::BitCast(di, hn::And(hn::ShiftRightSame(f.word, 8 * c), hn::Set(DU(), 0xffu)));
    return hn::Mul(hn::ConvertTo(df, byte), hn::Set(df, 1.0f / 255));
}

// Lesson 04's wrap `repeat` for an index within one period of the texture.
HWY_INLINE VI wrap(VI i, VI size) {
    const DI di;
    i = hn::IfThenElse(hn::Lt(i, hn::Zero(di)), hn::Add(i, size), i);
    return hn::IfThenElse(hn::Lt(i, size), i, hn::Sub(i, size));
}

// Bilinear (or nearest) lookup in one level per lane, `channels` of them.
HWY_INLINE Texel sample_level(DF df, const PackedTexture& t, VI level, VF u, VF v, bool bilinear,
                              int channels) {
    const DI di;
    // Neighbouring pixels mostly share a level: then one lookup serves all lanes.
    const std::int32_t first = hn::GetLane(level);
    const bool one_level = hn::AllTrue(di, hn::Eq(level, hn::Set(di, first)));
    const VI width =
        one_level ? hn::Set(di, t.level_width[first]) : hn::GatherIndex(di, t.level_width, level);
    const VI height =
        one_level ? hn::Set(di, t.level_height[first]) : hn::GatherIndex(di, t.level_height, level);
    const VI offset =
        one_level ? hn::Set(di, t.level_offset[first]) : hn::GatherIndex(di, t.level_offset, level);
    const VI stride =
        one_level ? hn::Set(di, t.level_stride[first]) : hn::GatherIndex(di, t.level_stride, level);
    const VF w = hn::ConvertTo(df, width), h = hn::ConvertTo(df, height);
    // to_texels: the coordinate's fraction, times the size.
    const VF s = hn::Mul(hn::Sub(u, hn::Floor(u)), w);
    const VF tt = hn::Mul(hn::Sub(v, hn::Floor(v)), h);
    Texel out;
    if (!bilinear) {
        const VI i = wrap(hn::ConvertTo(di, hn::Floor(s)), width);
        const VI j = wrap(hn::ConvertTo(di, hn::Floor(tt)), height);
        const Fetched texel = fetch(t, hn::Add(offset, hn::Add(hn::Mul(j, stride), i)), channels);
        for (int c = 0; c < channels; ++c) out.c[c] = channel(df, t, texel, c);
        return out;
    }
    const VF x = hn::Sub(s, hn::Set(df, 0.5f)), y = hn::Sub(tt, hn::Set(df, 0.5f));
    const VF fx0 = hn::Floor(x), fy0 = hn::Floor(y);
    const VF fx = hn::Sub(x, fx0), fy = hn::Sub(y, fy0);
    const VI i = hn::ConvertTo(di, fx0), j = hn::ConvertTo(di, fy0);
    const VI one = hn::Set(di, 1);
    // x0 + 1 wraps to 0 at the row's end: the row's extra texel is that one.
    const VI x0 = wrap(i, width);
    const VI row0 = hn::Add(offset, hn::Mul(wrap(j, height), stride));
    const VI row1 = hn::Add(offset, hn::Mul(wrap(hn::Add(j, one), height), stride));
    Fetched t00, t10, t01, t11;
    fetch_pairs(t, hn::Add(row0, x0), channels, t00, t10);
    fetch_pairs(t, hn::Add(row1, x0), channels, t01, t11);
    const VF gx = hn::Sub(hn::Set(df, 1.0f), fx), gy = hn::Sub(hn::Set(df, 1.0f), fy);
    for (int c = 0; c < channels; ++c) {
        const VF bottom =
            hn::Add(hn::Mul(channel(df, t, t00, c), gx), hn::Mul(channel(df, t, t10, c), fx));
        const VF top =
            hn::Add(hn::Mul(channel(df, t, t01, c), gx), hn::Mul(channel(df, t, t11, c), fx));
        out.c[c] = hn::Add(hn::Mul(bottom, gy), hn::Mul(top, fy));
    }
    return out;
}

// Lesson 04's sample(): the filter, the mip level from the footprint (log2
// of its longer side in texels of level 0), trilinear between two levels.
// A lane whose coordinates are not finite gets the border colour (0, 0, 0).
HWY_INLINE Texel sample(DF df, const PackedTexture& t, VF u, VF v, VF du_dx, VF dv_dx, VF du_dy,
                        VF dv_dy, textures::Filter filter, int channels) {
    const DI di;
    const MF finite = hn::And(hn::IsFinite(u), hn::IsFinite(v));
    u = hn::IfThenElseZero(finite, u), v = hn::IfThenElseZero(finite, v);
    Texel out;
    if (filter != textures::Filter::trilinear) {
        out =
            sample_level(df, t, hn::Zero(di), u, v, filter == textures::Filter::bilinear, channels);
    } else {
        const VF w = hn::Set(df, static_cast<float>(t.level_width[0]));
        const VF h = hn::Set(df, static_cast<float>(t.level_height[0]));
        const VF ax = hn::Mul(du_dx, w), ay = hn::Mul(dv_dx, h);
        const VF bx = hn::Mul(du_dy, w), by = hn::Mul(dv_dy, h);
        // log2 of the longer side = half the log2 of its square: no square roots.
        const VF along_x = hn::MulAdd(ay, ay, hn::Mul(ax, ax));
        const VF along_y = hn::MulAdd(by, by, hn::Mul(bx, bx));
        VF lod = hn::Mul(hn::Set(df, 0.5f),
                         hn::Log2(df, hn::Max(hn::Max(along_x, along_y), hn::Set(df, 1e-30f))));
        lod = hn::IfThenElseZero(hn::IsFinite(lod), lod);
        lod = hn::Min(hn::Max(lod, hn::Zero(df)), hn::Set(df, static_cast<float>(t.levels - 1)));
        const VF lower_f = hn::Floor(lod);
        const VI lower = hn::ConvertTo(di, lower_f);
        const VI upper = hn::Min(hn::Add(lower, hn::Set(di, 1)), hn::Set(di, t.levels - 1));
        const VF blend = hn::Sub(lod, lower_f);
        const Texel a = sample_level(df, t, lower, u, v, true, channels);
        const MF needs_upper = hn::Gt(blend, hn::Zero(df));
        if (hn::AllFalse(df, needs_upper)) {
            out = a;
        } else {
            const Texel b = sample_level(df, t, upper, u, v, true, channels);
            const VF keep = hn::Sub(hn::Set(df, 1.0f), blend);
            for (int c = 0; c < channels; ++c)
                out.c[c] = hn::IfThenElse(
                    needs_upper, hn::Add(hn::Mul(a.c[c], keep), hn::Mul(b.c[c], blend)), a.c[c]);
        }
    }
    for (int c = 0; c < channels; ++c) out.c[c] = hn::IfThenElseZero(finite, out.c[c]);
    return out;
}

// ---------------------------------------------------------------- shading

// Lesson 06's highlight(): max(alignment, 0) to the power shininess, with
// pow(0, 0) = 1.
HWY_INLINE VF highlight(DF df, VF alignment, float shininess) {
    const VF base = hn::Max(alignment, hn::Zero(df));
    VF power;
    if (shininess >= 1 && shininess <= 1024 && shininess == std::floor(shininess)) {
        // A whole exponent (lesson 06's 32): by repeated squaring, a few
        // multiplications in place of a logarithm and an exponential.
        power = hn::Set(df, 1.0f);
        VF square = base;
        for (unsigned e = static_cast<unsigned>(shininess); e != 0; e >>= 1) {
            if (e & 1) power = hn::Mul(power, square);
            if (e > 1) square = hn::Mul(square, square);
        }
    } else {
        power = hn::Exp(df, hn::Mul(hn::Set(df, shininess), hn::Log(df, base)));
    }
    return hn::IfThenElse(hn::Gt(base, hn::Zero(df)), power,
                          hn::Set(df, shininess == 0 ? 1.0f : 0.0f));
}

// Lesson 06's table of first bytes, widened to 32 bits for gathers.
const std::int32_t* first_bytes() {
    static const auto table = [] {
        const shading::SrgbByteTables& tables = shading::srgb_byte_tables();
        std::array<std::int32_t, 4097> wide{};
        for (std::size_t i = 0; i < wide.size(); ++i) wide[i] = tables.first[i];
        return wide;
    }();
    return table.data();
}

// Lesson 06's encode(): the nearest sRGB byte by lesson 06's tables, or the
// naive byte.
HWY_INLINE VI encode_channel(DF df, VF value, bool srgb) {
    const DI di;
    if (!srgb) {
        const VF v =
            hn::Mul(hn::Min(hn::Max(value, hn::Zero(df)), hn::Set(df, 1.0f)), hn::Set(df, 255.0f));
        return hn::ConvertTo(
            di, hn::Add(hn::IfThenElseZero(hn::Ge(v, hn::Zero(df)), v), hn::Set(df, 0.5f)));
    }
    const shading::SrgbByteTables& tables = shading::srgb_byte_tables();
    const MF positive = hn::Gt(value, hn::Zero(df));  // false for NaN
    const MF below_one = hn::Lt(value, hn::Set(df, 1.0f));
    const VF clamped = hn::IfThenElseZero(hn::And(positive, below_one), value);
    const VI slice = hn::ConvertTo(di, hn::Mul(clamped, hn::Set(df, 4096.0f)));
    VI b = hn::GatherIndex(di, first_bytes(), slice);
    // No slice holds more than one step: one comparison finishes the search.
    const VF next = hn::GatherIndex(df, tables.steps.data(), b);
    b = hn::IfThenElse(hn::RebindMask(di, hn::Ge(clamped, next)), hn::Add(b, hn::Set(di, 1)), b);
    b = hn::IfThenElseZero(hn::RebindMask(di, positive), b);
    return hn::IfThenElse(hn::RebindMask(di, hn::And(positive, hn::Not(below_one))),
                          hn::Set(di, 255), b);
}

// Lesson 07's NormalMappedShader::fragment() for N pixels: varyings in, RGBA
// words out.
HWY_NOINLINE VU shade(DF df, const Material& m, const FastTriangle& t, const VF (&b)[3]) {
    // Lesson 05's fragment_at: b . (varyings / w) times 1 / (b . 1/w).
    const VF inverse_w = hn::Add(hn::Add(hn::Mul(b[0], hn::Set(df, t.inverse_w[0])),
                                         hn::Mul(b[1], hn::Set(df, t.inverse_w[1]))),
                                 hn::Mul(b[2], hn::Set(df, t.inverse_w[2])));
    const VF w = hn::Div(hn::Set(df, 1.0f), inverse_w);
    VF v[kVaryingFloats];
    for (int c = 0; c < kVaryingFloats; ++c)
        v[c] = hn::Mul(hn::Add(hn::Add(hn::Mul(b[0], hn::Set(df, t.over_w[0][c])),
                                       hn::Mul(b[1], hn::Set(df, t.over_w[1][c]))),
                               hn::Mul(b[2], hn::Set(df, t.over_w[2][c]))),
                       w);
    const Vec3 position{v[0], v[1], v[2]}, normal{v[3], v[4], v[5]}, tangent{v[6], v[7], v[8]};
    const VF handedness = v[9], u = v[10], vv = v[11];
    // Lesson 05's Fragment::d_dx(&Varyings::uv): the quotient rule.
    const VF du_dx =
        hn::Mul(hn::MulAdd(u, hn::Set(df, -t.d_inverse_w[0]), hn::Set(df, t.d_uv_over_w[0][0])), w);
    const VF dv_dx = hn::Mul(
        hn::MulAdd(vv, hn::Set(df, -t.d_inverse_w[0]), hn::Set(df, t.d_uv_over_w[0][1])), w);
    const VF du_dy =
        hn::Mul(hn::MulAdd(u, hn::Set(df, -t.d_inverse_w[1]), hn::Set(df, t.d_uv_over_w[1][0])), w);
    const VF dv_dy = hn::Mul(
        hn::MulAdd(vv, hn::Set(df, -t.d_inverse_w[1]), hn::Set(df, t.d_uv_over_w[1][1])), w);

    // normal_at(): the map's normal, or the interpolated one.
    Vec3 n = normalize(df, normal);
    if (m.normal_source != NormalSource::interpolated) {
        const Texel texel =
            sample(df, *m.normal_map, u, vv, du_dx, dv_dx, du_dy, dv_dy, m.filter, 3);
        const VF two = hn::Set(df, 2.0f), one = hn::Set(df, 1.0f);
        const Vec3 map{hn::Sub(hn::Mul(two, texel.c[0]), one),
                       hn::Sub(hn::Mul(two, texel.c[1]), one),
                       hn::Sub(hn::Mul(two, texel.c[2]), one)};
        const VF squared = dot(map, map);
        const MF usable = hn::Ge(squared, hn::Set(df, normal_mapping::kShortestMapNormal *
                                                          normal_mapping::kShortestMapNormal));
        const VF inverse_length = inverse_sqrt(df, hn::Max(squared, hn::Set(df, 1e-12f)));
        Vec3 mapped;
        if (m.normal_source == NormalSource::tangent_map) {
            const Vec3 tt = normalize(df, sub(tangent, scale(n, dot(n, tangent))));
            const VF sign =
                hn::IfThenElse(hn::Lt(handedness, hn::Zero(df)), hn::Set(df, -1.0f), one);
            const Vec3 bt = scale(cross(n, tt), sign);
            const Vec3 sum = add(add(scale(tt, map.x), scale(bt, map.y)), scale(n, map.z));
            mapped = scale(sum, inverse_length);
        } else {
            const float* r = m.normal_matrix;
            mapped = normalize(
                df, {hn::MulAdd(
                         hn::Set(df, r[2]), map.z,
                         hn::MulAdd(hn::Set(df, r[1]), map.y, hn::Mul(hn::Set(df, r[0]), map.x))),
                     hn::MulAdd(
                         hn::Set(df, r[5]), map.z,
                         hn::MulAdd(hn::Set(df, r[4]), map.y, hn::Mul(hn::Set(df, r[3]), map.x))),
                     hn::MulAdd(
                         hn::Set(df, r[8]), map.z,
                         hn::MulAdd(hn::Set(df, r[7]), map.y, hn::Mul(hn::Set(df, r[6]), map.x)))});
        }
        n = select(usable, mapped, n);
    }

    // Lesson 06's reflection(): ambient, then each light's diffuse and highlight.
    const Vec3 to_eye = normalize(df, sub(broadcast(df, m.eye), position));
    Vec3 diffuse = broadcast(df, m.ambient);
    Vec3 specular{hn::Zero(df), hn::Zero(df), hn::Zero(df)};
    const Vec3 specular_colour = broadcast(df, m.specular_colour);
    for (int i = 0; i < m.lights; ++i) {
        const Vec3 l = broadcast(df, m.light_direction[i]);
        const Vec3 colour = broadcast(df, m.light_colour[i]);
        const VF n_dot_l = dot(n, l);
        const MF lit = hn::Gt(n_dot_l, hn::Zero(df));
        if (hn::AllFalse(df, lit)) continue;
        const VF alignment =
            m.blinn ? dot(n, normalize(df, add(l, to_eye)))
                    : dot(sub(scale(n, hn::Mul(hn::Set(df, 2.0f), n_dot_l)), l), to_eye);
        const VF strength = highlight(df, alignment, m.shininess);
        const Vec3 d = scale(colour, n_dot_l);
        const Vec3 s =
            scale({hn::Mul(colour.x, specular_colour.x), hn::Mul(colour.y, specular_colour.y),
                   hn::Mul(colour.z, specular_colour.z)},
                  strength);
        diffuse = select(lit, add(diffuse, d), diffuse);
        specular = select(lit, add(specular, s), specular);
    }

    // surface_colour(): albedo times diffuse, plus the highlight times the specular map.
    VF shine = hn::Set(df, 1.0f);
    if (m.specular_map) {
        const VF peak = hn::Max(hn::Max(specular.x, specular.y), specular.z);
        const MF bright = hn::Ge(peak, hn::Set(df, 1e-4f));
        shine = hn::Zero(df);
        if (!hn::AllFalse(df, bright)) {
            const Texel s =
                sample(df, *m.specular_map, u, vv, du_dx, dv_dx, du_dy, dv_dy, m.filter, 1);
            shine = hn::IfThenElseZero(bright, s.c[0]);
        }
    }
    Vec3 albedo;
    if (m.albedo) {
        const Texel a = sample(df, *m.albedo, u, vv, du_dx, dv_dx, du_dy, dv_dy, m.filter, 3);
        albedo = {a.c[0], a.c[1], a.c[2]};
    } else {
        albedo = broadcast(df, m.colour);
    }
    const VF r = hn::MulAdd(specular.x, shine, hn::Mul(albedo.x, diffuse.x));
    const VF g = hn::MulAdd(specular.y, shine, hn::Mul(albedo.y, diffuse.y));
    const VF bl = hn::MulAdd(specular.z, shine, hn::Mul(albedo.z, diffuse.z));
    const DU du;
    const DI di;
    const VU red = hn::BitCast(du, encode_channel(df, r, m.srgb));
    const VU green = hn::BitCast(du, encode_channel(df, g, m.srgb));
    const VU blue = hn::BitCast(du, encode_channel(df, bl, m.srgb));
    (void)di;
    return hn::Or(hn::Or(red, hn::ShiftLeft<8>(green)),
                  hn::Or(hn::ShiftLeft<16>(blue), hn::Set(du, 0xff000000u)));
}

// The plain way: each vector of a block that holds any of the triangle's
// pixels shaded as it is (the lanes of other triangles' pixels wasted).
void shade_by_chunks(const TileWork& work, TileBuffers& buffers, const FastTriangle& t,
                     std::uint32_t index, TileCounts& counts) {
    const DF df;
    const DU du;
    const std::size_t n = hn::Lanes(df);
    const int blocks_per_row = buffers.size / kBlock;
    const BlockRange r = blocks_of(t, work);
    for (int by = r.first_y; by <= r.last_y; ++by)
        for (int bx = r.first_x; bx <= r.last_x; ++bx) {
            const std::size_t base = static_cast<std::size_t>(by * blocks_per_row + bx) * 64;
            const std::uint32_t* id = buffers.id.get() + base;
            std::uint32_t* colour = buffers.colour.get() + base;
            const BlockWeights w = block_weights(t, work.x0 + bx * kBlock, work.y0 + by * kBlock);
            for (int first = 0; first < 64; first += static_cast<int>(n)) {
                const auto mine = hn::Eq(hn::Load(du, id + first), hn::Set(du, index));
                if (hn::AllFalse(du, mine)) continue;
                VF b[3];
                weights_at(df, t, w, first, b);
                const VU rgba = shade(df, work.materials[t.model], t, b);
                counts.shaded += hn::CountTrue(du, mine);
                counts.lanes += n;
                hn::Store(hn::IfThenElse(mine, rgba, hn::Load(du, colour + first)), du,
                          colour + first);
            }
        }
}

// Shades each pixel the visibility pass gave a triangle, one full vector at
// a time: the triangle's pixels in the tile are queued (compressed into
// consecutive lanes) and shaded N at once, so that a vector is full even where
// the triangle covers a few pixels of each block.
void ShadeTile(const TileWork& work, TileBuffers& buffers, TileCounts& counts) {
    const DF df;
    const DU du;
    const std::size_t n = hn::Lanes(df);
    const int blocks_per_row = buffers.size / kBlock;
    const TriangleChunks& triangles = *work.triangles;
    std::size_t piece = 0;
    const SlotTables& s = slots();
    // The queue: tile slots and tile-relative pixel positions; room for one
    // vector more than it ever keeps, as CompressStore writes a whole vector.
    alignas(64) std::uint32_t queue_slot[2 * hn::MaxLanes(du)] = {};
    alignas(64) float queue_x[2 * hn::MaxLanes(df)] = {}, queue_y[2 * hn::MaxLanes(df)] = {};
    alignas(64) std::uint32_t shaded[hn::MaxLanes(du)];
    std::uint32_t* colour = buffers.colour.get();
    for (std::size_t i = 0; i < work.bin_size; ++i) {
        const std::uint32_t index = work.bin[i];
        const FastTriangle& t = triangles.at(index, piece);
        const Material& material = work.materials[t.model];
        const BlockRange r = blocks_of(t, work);
        if (r.first_x > r.last_x) continue;
        if (!work.techniques.full_vectors) {
            shade_by_chunks(work, buffers, t, index, counts);
            continue;
        }
        // The weights, stepped exactly from the tile's first pixel.
        const BlockWeights w = block_weights(t, work.x0, work.y0);
        std::size_t queued = 0;
        const auto shade_queued = [&](std::size_t count) {
            const VF x = hn::Load(df, queue_x), y = hn::Load(df, queue_y);
            VF b[3];
            weights_at(df, t, w, x, y, b);
            hn::Store(shade(df, material, t, b), du, shaded);
            for (std::size_t lane = 0; lane < count; ++lane)
                colour[queue_slot[lane]] = shaded[lane];
            counts.shaded += count;
            counts.lanes += n;
        };
        for (int by = r.first_y; by <= r.last_y; ++by)
            for (int bx = r.first_x; bx <= r.last_x; ++bx) {
                const std::uint32_t base =
                    static_cast<std::uint32_t>(by * blocks_per_row + bx) * 64;
                const std::uint32_t* id = buffers.id.get() + base;
                const VF block_x = hn::Set(df, static_cast<float>(bx * kBlock));
                const VF block_y = hn::Set(df, static_cast<float>(by * kBlock));
                // [doc:lane-queue]
                for (int first = 0; first < 64; first += static_cast<int>(n)) {
                    const auto mine = hn::Eq(hn::Load(du, id + first), hn::Set(du, index));
                    if (hn::AllFalse(du, mine)) continue;
                    const auto mine_f = hn::RebindMask(df, mine);
                    hn::CompressStore(hn::Iota(du, base + static_cast<std::uint32_t>(first)), mine,
                                      du, queue_slot + queued);
                    hn::CompressStore(hn::Add(hn::Load(df, s.column + first), block_x), mine_f, df,
                                      queue_x + queued);
                    queued += hn::CompressStore(hn::Add(hn::Load(df, s.row + first), block_y),
                                                mine_f, df, queue_y + queued);
                    if (queued >= n) {
                        shade_queued(n);
                        queued -= n;
                        std::copy_n(queue_slot + n, queued, queue_slot);
                        std::copy_n(queue_x + n, queued, queue_x);
                        std::copy_n(queue_y + n, queued, queue_y);
                    }
                }
                // [/doc:lane-queue]
            }
        if (queued > 0) shade_queued(queued);
    }
}

void RenderTile(const TileWork& work, TileBuffers& buffers, rl::Image& frame, TileCounts& counts) {
    static_assert(sizeof(rl::Rgba) == 4);
    using Clock = std::chrono::steady_clock;
    const auto ns = [](Clock::duration d) {
        return static_cast<std::uint64_t>(
            std::chrono::duration_cast<std::chrono::nanoseconds>(d).count());
    };
    const Clock::time_point start = Clock::now();
    std::uint32_t background;
    std::memcpy(&background, &rl::kBackground, 4);
    std::fill(buffers.colour.get(), buffers.colour.get() + buffers.pixels, background);
    RasterizeTile(work, buffers, counts);
    const Clock::time_point rasterized = Clock::now();
    if (work.techniques.shade_once) ShadeTile(work, buffers, counts);
    const Clock::time_point shaded = Clock::now();
    // Resolve: the tile's blocks back into the frame's rows, 8 pixels (one
    // block's row) at a time.
    const int blocks_per_row = buffers.size / kBlock;
    for (int y = 0; y < work.height; ++y) {
        rl::Rgba* row = &frame.at(work.x0, work.y0 + y);
        const std::uint32_t* block_row =
            buffers.colour.get() + static_cast<std::size_t>((y / kBlock) * blocks_per_row) * 64 +
            static_cast<std::size_t>((y % kBlock) * kBlock);
        // A whole block's row is one fixed-size copy (a vector move); the
        // frame's last partial block, fewer bytes.
        int x = 0;
        for (; x + kBlock <= work.width; x += kBlock)
            std::memcpy(static_cast<void*>(row + x), block_row + (x / kBlock) * 64, kBlock * 4);
        if (x < work.width)
            std::memcpy(static_cast<void*>(row + x), block_row + (x / kBlock) * 64,
                        static_cast<std::size_t>(work.width - x) * 4);
    }
    counts.raster_ns += ns(rasterized - start);
    counts.shade_ns += ns(shaded - rasterized);
    counts.copy_ns += ns(Clock::now() - shaded);
}

void EncodeSrgb(const float* values, std::uint8_t* bytes, std::size_t count) {
    const DF df;
    const DI di;
    const std::size_t n = hn::Lanes(df);
    alignas(64) float in[hn::MaxLanes(df)];
    alignas(64) std::int32_t out[hn::MaxLanes(di)];
    for (std::size_t i = 0; i < count; i += n) {
        const std::size_t m = std::min(n, count - i);
        for (std::size_t j = 0; j < n; ++j) in[j] = j < m ? values[i + j] : 0.0f;
        hn::Store(encode_channel(df, hn::Load(df, in), true), di, out);
        for (std::size_t j = 0; j < m; ++j) bytes[i + j] = static_cast<std::uint8_t>(out[j]);
    }
}

const char* SimdTarget() {
    return hwy::TargetName(HWY_TARGET);
}

}  // namespace HWY_NAMESPACE
}  // namespace fast
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fast {

HWY_EXPORT(RenderTile);
HWY_EXPORT(RasterizeTile);
HWY_EXPORT(EncodeSrgb);
HWY_EXPORT(SimdTarget);

TileCounts& TileCounts::operator+=(const TileCounts& o) {
    blocks_rejected += o.blocks_rejected, blocks_full += o.blocks_full;
    blocks_partial += o.blocks_partial, blocks_occluded += o.blocks_occluded;
    depth_passed += o.depth_passed, shaded += o.shaded;
    raster_ns += o.raster_ns, shade_ns += o.shade_ns, copy_ns += o.copy_ns;
    lanes += o.lanes;
    return *this;
}

TileBuffers::TileBuffers(int tile_size)
    : size(tile_size),
      pixels(static_cast<std::size_t>(tile_size) * static_cast<std::size_t>(tile_size)),
      depth(hwy::AllocateAligned<float>(pixels)),
      id(hwy::AllocateAligned<std::uint32_t>(pixels)),
      colour(hwy::AllocateAligned<std::uint32_t>(pixels)),
      block_far(pixels / 64) {}

void render_tile(const TileWork& work, TileBuffers& buffers, rl::Image& frame, TileCounts& counts) {
    HWY_DYNAMIC_DISPATCH(RenderTile)(work, buffers, frame, counts);
}
void rasterize_tile(const TileWork& work, TileBuffers& buffers, TileCounts& counts) {
    HWY_DYNAMIC_DISPATCH(RasterizeTile)(work, buffers, counts);
}
void encode_srgb(const float* values, std::uint8_t* bytes, std::size_t count) {
    HWY_DYNAMIC_DISPATCH(EncodeSrgb)(values, bytes, count);
}
const char* simd_target() {
    return HWY_DYNAMIC_DISPATCH(SimdTarget)();
}
std::vector<std::int64_t> simd_targets() {
    return hwy::SupportedAndGeneratedTargets();
}

}  // namespace fast
#endif
