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

}  // namespace HWY_NAMESPACE
}  // namespace fast
HWY_AFTER_NAMESPACE();

#endif  // RASTERLAB_FAST_SIMD_TYPES_INL_H_
