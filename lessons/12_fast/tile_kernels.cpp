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
// The kernels by topic, each once per instruction set:
#include "12_fast/coverage-inl.h"
#include "12_fast/sampling-inl.h"
#include "12_fast/shading-inl.h"
#include "12_fast/simd_types-inl.h"

HWY_BEFORE_NAMESPACE();
namespace fast {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
            const int oy = work.y0 + by * kBlock;
            const BlockWeights w = block_weights(t, work.x0 + bx * kBlock, oy);
            const SlotRange slots = slots_of(rows_of(t, oy, work.techniques), n);
            for (int first = slots.first; first < slots.end; first += static_cast<int>(n)) {
                const auto mine = hn::Eq(hn::Load(du, id + first), hn::Set(du, index));
                if (hn::AllFalse(du, mine)) continue;
                VF b[3];
                weights_at(df, t, w, first, b);
                const VU rgba = shade(df, work.materials[t.model], t, b, hn::RebindMask(df, mine));
                counts.shaded += hn::CountTrue(du, mine);
                counts.lanes += n;
                hn::Store(hn::IfThenElse(mine, rgba, hn::Load(du, colour + first)), du,
                          colour + first);
            }
        }
}

// Shades the first `count` lanes of `f` into the tile slots `slots` of `colour`.
void shade_into_slots(DF df, const Material& m, const Fragments& f, const std::uint32_t* slots,
                      std::size_t count, std::uint32_t* colour, TileCounts& counts) {
    const DU du;
    alignas(64) std::uint32_t shaded[hn::MaxLanes(du)];
    hn::Store(shade(df, m, f, hn::FirstN(df, count)), du, shaded);
    for (std::size_t lane = 0; lane < count; ++lane) colour[slots[lane]] = shaded[lane];
    counts.shaded += count;
    counts.lanes += hn::Lanes(df);
}

// Pixels waiting for the shader: their fragments (interpolated, so that
// pixels of different triangles of one model can share a vector) and the
// tile slots their colours go to. Room for a vector more than it ever
// keeps, as each append writes whole vectors.
struct FragmentQueue {
    static constexpr std::size_t kRoom = 2 * hn::MaxLanes(DF());
    alignas(64) float value[kFragmentFloats][kRoom] = {};
    alignas(64) std::uint32_t slot[kRoom] = {};
    std::size_t size = 0;
    std::uint32_t model = 0;  // whose material shades them

    // The first `count` lanes of `f` and `slots`.
    void append(DF df, const Fragments& f, const std::uint32_t* slots, std::size_t count) {
        const DU du;
        for (int c = 0; c < kFragmentFloats; ++c) hn::StoreU(f.value[c], df, value[c] + size);
        hn::StoreU(hn::LoadU(du, slots), du, slot + size);
        size += count;
    }
    // Shades the first min(size, N) pixels into `colour`, then moves the
    // rest to the front.
    void shade_front(DF df, const Material& m, std::uint32_t* colour, TileCounts& counts) {
        const std::size_t count = std::min(size, hn::Lanes(df));
        Fragments f;
        for (int c = 0; c < kFragmentFloats; ++c) f.value[c] = hn::Load(df, value[c]);
        shade_into_slots(df, m, f, slot, count, colour, counts);
        size -= count;
        for (int c = 0; c < kFragmentFloats; ++c) std::copy_n(value[c] + count, size, value[c]);
        std::copy_n(slot + count, size, slot);
    }
};

// Shades each pixel the visibility pass gave a triangle, one full vector at
// a time: the triangle's pixels in the tile are queued (compressed into
// consecutive lanes), interpolated N at once, and their fragments queued
// again with those of the triangles that follow (while the model is the
// same), so that a vector is full even where each triangle covers a few
// pixels of the tile.
void ShadeTile(const TileWork& work, TileBuffers& buffers, TileCounts& counts) {
    const DF df;
    const DU du;
    const std::size_t n = hn::Lanes(df);
    const int blocks_per_row = buffers.size / kBlock;
    const TriangleChunks& triangles = *work.triangles;
    std::size_t piece = 0;
    const SlotTables& s = slots();
    // A triangle's pixels: tile slots and tile-relative positions; room for
    // one vector more than it ever keeps, as compress_store writes a whole vector.
    alignas(64) std::uint32_t queue_slot[2 * hn::MaxLanes(du)] = {};
    alignas(64) float queue_x[2 * hn::MaxLanes(df)] = {}, queue_y[2 * hn::MaxLanes(df)] = {};
    FragmentQueue fragments;
    std::uint32_t* colour = buffers.colour.get();
    const auto shade_all = [&] {
        while (fragments.size > 0)
            fragments.shade_front(df, work.materials[fragments.model], colour, counts);
    };
    for (std::size_t i = 0; i < work.bin_size; ++i) {
        const std::uint32_t index = work.bin[i];
        const FastTriangle& t = triangles.at(index, piece);
        const BlockRange r = blocks_of(t, work);
        if (r.first_x > r.last_x) continue;
        if (!work.techniques.full_vectors) {
            shade_by_chunks(work, buffers, t, index, counts);
            continue;
        }
        // [doc:fragment-queue]
        // The fragment queue holds one material's pixels.
        if (t.model != fragments.model) shade_all();
        fragments.model = t.model;
        // The weights, stepped exactly from the tile's first pixel.
        const BlockWeights w = block_weights(t, work.x0, work.y0);
        std::size_t queued = 0;
        const Material& material = work.materials[t.model];
        const auto interpolate_queued = [&](std::size_t count) {
            VF b[3];
            weights_at(df, t, w, hn::Load(df, queue_x), hn::Load(df, queue_y), b);
            const Fragments f = interpolate(df, t, b);
            // A full vector needs no queue: a pixel's colour depends on no other lane.
            if (count == n) {
                shade_into_slots(df, material, f, queue_slot, n, colour, counts);
                return;
            }
            fragments.append(df, f, queue_slot, count);
            if (fragments.size >= n) fragments.shade_front(df, material, colour, counts);
        };
        // [/doc:fragment-queue]
        for (int by = r.first_y; by <= r.last_y; ++by)
            for (int bx = r.first_x; bx <= r.last_x; ++bx) {
                const std::uint32_t base =
                    static_cast<std::uint32_t>(by * blocks_per_row + bx) * 64;
                const std::uint32_t* id = buffers.id.get() + base;
                const VF block_x = hn::Set(df, static_cast<float>(bx * kBlock));
                const VF block_y = hn::Set(df, static_cast<float>(by * kBlock));
                const SlotRange slots =
                    slots_of(rows_of(t, work.y0 + by * kBlock, work.techniques), n);
                // [doc:lane-queue]
                for (int first = slots.first; first < slots.end; first += static_cast<int>(n)) {
                    const auto mine = hn::Eq(hn::Load(du, id + first), hn::Set(du, index));
                    if (hn::AllFalse(du, mine)) continue;
                    const auto mine_f = hn::RebindMask(df, mine);
                    compress_store(hn::Iota(du, base + static_cast<std::uint32_t>(first)), mine, du,
                                   queue_slot + queued);
                    compress_store(hn::Add(hn::Load(df, s.column + first), block_x), mine_f, df,
                                   queue_x + queued);
                    queued += compress_store(hn::Add(hn::Load(df, s.row + first), block_y), mine_f,
                                             df, queue_y + queued);
                    if (queued >= n) {
                        interpolate_queued(n);
                        queued -= n;
                        std::copy_n(queue_slot + n, queued, queue_slot);
                        std::copy_n(queue_x + n, queued, queue_x);
                        std::copy_n(queue_y + n, queued, queue_y);
                    }
                }
                // [/doc:lane-queue]
            }
        if (queued > 0) interpolate_queued(queued);
        if (!work.techniques.across_triangles) shade_all();
    }
    shade_all();
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

void EncodeSrgb(const float* values, std::uint8_t* bytes, std::size_t count, bool one_gather) {
    const DF df;
    const DI di;
    const std::size_t n = hn::Lanes(df);
    alignas(64) float in[hn::MaxLanes(df)];
    alignas(64) std::int32_t out[hn::MaxLanes(di)];
    for (std::size_t i = 0; i < count; i += n) {
        const std::size_t m = std::min(n, count - i);
        for (std::size_t j = 0; j < n; ++j) in[j] = j < m ? values[i + j] : 0.0f;
        hn::Store(encode_channel(df, hn::Load(df, in), true, one_gather), di, out);
        for (std::size_t j = 0; j < m; ++j) bytes[i + j] = static_cast<std::uint8_t>(out[j]);
    }
}

void DecodeTexels(const PackedTexture& texture, const std::int32_t* index, std::size_t count,
                  float* rgb) {
    const DF df;
    const DI di;
    const std::size_t n = hn::Lanes(df);
    alignas(64) std::int32_t at[hn::MaxLanes(di)];
    alignas(64) float out[hn::MaxLanes(df)];
    for (std::size_t i = 0; i < count; i += n) {
        const std::size_t m = std::min(n, count - i);
        for (std::size_t j = 0; j < n; ++j) at[j] = j < m ? index[i + j] : index[i];
        const Fetched texel = fetch(texture, hn::Load(di, at), 3);
        for (int c = 0; c < 3; ++c) {
            hn::Store(channel(df, texture, texel, c), df, out);
            for (std::size_t j = 0; j < m; ++j)
                rgb[3 * (i + j) + static_cast<std::size_t>(c)] = out[j];
        }
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
HWY_EXPORT(DecodeTexels);
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
void encode_srgb(const float* values, std::uint8_t* bytes, std::size_t count, bool one_gather) {
    HWY_DYNAMIC_DISPATCH(EncodeSrgb)(values, bytes, count, one_gather);
}

void decode_texels(const PackedTexture& texture, const std::int32_t* index, std::size_t count,
                   float* rgb) {
    HWY_DYNAMIC_DISPATCH(DecodeTexels)(texture, index, count, rgb);
}
const char* simd_target() {
    return HWY_DYNAMIC_DISPATCH(SimdTarget)();
}
std::vector<std::int64_t> simd_targets() {
    return hwy::SupportedAndGeneratedTargets();
}

}  // namespace fast
#endif
