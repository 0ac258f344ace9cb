// The tile kernels' texture sampling: lesson 04's filters on the packed mip
// levels, a vector of lookups at a time (gathers), and the vector maths the
// shader needs. docs/12_fast.md, "Shading in vectors".
// Included by tile_kernels.cpp only, once per instruction set (Highway's
// foreach_target): the guard below lets each pass in once.
#if defined(RASTERLAB_FAST_SAMPLING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef RASTERLAB_FAST_SAMPLING_INL_H_
#undef RASTERLAB_FAST_SAMPLING_INL_H_
#else
#define RASTERLAB_FAST_SAMPLING_INL_H_
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "12_fast/simd_types-inl.h"
#include "12_fast/tile_kernels.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace fast {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
    VF c[4];
    explicit Texel(DF df) : c{hn::Zero(df), hn::Zero(df), hn::Zero(df), hn::Zero(df)} {}
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
    if (!t.blue_words.empty() && channels > 2) f.blue = gather_words(t.blue_words, index);
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
    if (!t.blue_words.empty() && channels > 2)
        gather_pairs(t.blue_words, index, left.blue, right.blue);
}
HWY_INLINE VF channel(DF df, const PackedTexture& t, const Fetched& f, int c) {
    const DI di;
    if (t.one_word) {  // the value's square root in 11, 11, 10 bits: squared back
        const VU bits = c == 0   ? hn::And(f.word, hn::Set(DU(), 0x7ffu))
                        : c == 1 ? hn::And(hn::ShiftRight<11>(f.word), hn::Set(DU(), 0x7ffu))
                                 : hn::ShiftRight<22>(f.word);
        const VF root = hn::Mul(hn::ConvertTo(df, hn::BitCast(di, bits)),
                                hn::Set(df, c == 2 ? 1.0f / 1023 : 1.0f / 2047));
        return hn::Mul(root, root);
    }
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
    Texel out(df);
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
    Texel out(df);
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

}  // namespace HWY_NAMESPACE
}  // namespace fast
HWY_AFTER_NAMESPACE();

#endif  // RASTERLAB_FAST_SAMPLING_INL_H_
