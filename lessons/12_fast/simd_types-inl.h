// The tile kernels' vector types, and a block's pixel slots as SIMD lanes
// see them (docs/12_fast.md, "Shading in vectors").
// Included by tile_kernels.cpp only, once per instruction set (Highway's
// foreach_target): the guard below lets each pass in once.
#if defined(RASTERLAB_FAST_SIMD_TYPES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef RASTERLAB_FAST_SIMD_TYPES_INL_H_
#undef RASTERLAB_FAST_SIMD_TYPES_INL_H_
#else
#define RASTERLAB_FAST_SIMD_TYPES_INL_H_
#endif

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "12_fast/tile_kernels.hpp"
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

// hn::CompressStore (the lanes of v where mask is true, written to `to` in
// order; a whole vector is written), with its table of lane orders kept in
// static storage on AVX2. Highway 1.0.3, Debian 12's, declares that 1 KiB
// table as a local constexpr array, and GCC copies it onto the stack at
// every call (google/highway#1139, fixed in later releases): on an AVX2
// machine those copies took more than half of the shading stage's time at a
// million triangles.
#if HWY_TARGET == HWY_AVX2
// Per 8-bit mask, the indices of its true lanes in order, 4 bits each.
constexpr std::array<std::uint32_t, 256> lane_orders() {
    std::array<std::uint32_t, 256> out{};
    for (unsigned mask = 0; mask < 256; ++mask)
        for (unsigned lane = 0, next = 0; lane < 8; ++lane)
            if ((mask >> lane) & 1) out[mask] |= lane << (4 * next++);
    return out;
}
#endif
template <class D>
HWY_INLINE std::size_t compress_store(hn::Vec<D> v, hn::Mask<D> mask, D d, hn::TFromD<D>* to) {
#if HWY_TARGET == HWY_AVX2
    if constexpr (sizeof(hn::TFromD<D>) == 4 && hn::MaxLanes(D()) == 8) {
        static constexpr std::array<std::uint32_t, 256> kOrders = lane_orders();
        std::uint8_t bits = 0;
        hn::StoreMaskBits(d, mask, &bits);
        const hn::RebindToUnsigned<D> du;
        const auto shifts = hn::ShiftLeft<2>(hn::Iota(du, 0));
        const auto order = hn::And(hn::Set(du, kOrders[bits]) >> shifts, hn::Set(du, 7));
        hn::StoreU(hn::TableLookupLanes(v, hn::IndicesFromVec(d, order)), d, to);
        return static_cast<std::size_t>(std::popcount(bits));
    }
#endif
    return hn::CompressStore(v, mask, d, to);
}

}  // namespace HWY_NAMESPACE
}  // namespace fast
HWY_AFTER_NAMESPACE();

#endif  // RASTERLAB_FAST_SIMD_TYPES_INL_H_
