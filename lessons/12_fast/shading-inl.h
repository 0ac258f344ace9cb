// The tile kernels' shader: lesson 07's fragment function for a vector of
// pixels (lesson 06's lights and highlight, the normal map, the specular
// map) and lesson 06's sRGB encoding. docs/12_fast.md, "Shading in vectors".
// Included by tile_kernels.cpp only, once per instruction set (Highway's
// foreach_target): the guard below lets each pass in once.
#if defined(RASTERLAB_FAST_SHADING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef RASTERLAB_FAST_SHADING_INL_H_
#undef RASTERLAB_FAST_SHADING_INL_H_
#else
#define RASTERLAB_FAST_SHADING_INL_H_
#endif

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "06_shading/colour.hpp"
#include "08_shadows/shadow_lookup.hpp"
#include "12_fast/sampling-inl.h"
#include "12_fast/simd_types-inl.h"
#include "12_fast/tile_kernels.hpp"
#include "hwy/contrib/math/math-inl.h"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace fast {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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

// Lesson 06's two tables folded into one 32-bit entry per slice of [0, 1),
// so that a lane reads its byte with one gather instead of two: the slice's
// first byte in the top 8 bits, and in the low 24 where the next step falls
// inside the slice, as a fraction of the slice (exact: see
// docs/12_fast.md, "sRGB with one gather"), or 2^24 - 1 where the slice
// holds no step (no fraction of a value in the slice reaches it).
const std::int32_t* srgb_entries() {
    static const auto table = [] {
        const shading::SrgbByteTables& tables = shading::srgb_byte_tables();
        std::array<std::int32_t, 4096> entries{};
        for (std::size_t i = 0; i < entries.size(); ++i) {
            const std::uint32_t first = tables.first[i];
            const double step = tables.steps[first];
            std::uint32_t fraction = (1u << 24) - 1;
            bool exact = i > 0;  // a value of slice 0 may reach the fraction 1 - 2^-24
            if (step < static_cast<double>(i + 1) / 4096.0) {
                const double scaled = (step * 4096.0 - static_cast<double>(i)) * 16777216.0;
                exact = scaled == std::floor(scaled) && scaled < 16777215.0;
                fraction = static_cast<std::uint32_t>(scaled);
            }
            // Lesson 06's steps always pass; checked here rather than assumed.
            if (!exact) throw std::logic_error("srgb_entries: a step is not a 24-bit fraction");
            entries[i] = static_cast<std::int32_t>((first << 24) | fraction);
        }
        return entries;
    }();
    return table.data();
}

// Lesson 06's table of first bytes, widened to 32 bits for gathers (the
// lab's step before the tables were folded).
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
// [doc:encode-channel]
HWY_INLINE VI encode_channel(DF df, VF value, bool srgb, bool one_gather) {
    const DI di;
    if (!srgb) {
        const VF v =
            hn::Mul(hn::Min(hn::Max(value, hn::Zero(df)), hn::Set(df, 1.0f)), hn::Set(df, 255.0f));
        return hn::ConvertTo(
            di, hn::Add(hn::IfThenElseZero(hn::Ge(v, hn::Zero(df)), v), hn::Set(df, 0.5f)));
    }
    const MF positive = hn::Gt(value, hn::Zero(df));  // false for NaN
    const MF below_one = hn::Lt(value, hn::Set(df, 1.0f));
    const VF clamped = hn::IfThenElseZero(hn::And(positive, below_one), value);
    const VF scaled = hn::Mul(clamped, hn::Set(df, 4096.0f));  // exact: a power of two
    const VI slice = hn::ConvertTo(di, scaled);
    VI b;
    MF past_step;  // lesson 06's `value >= steps[b]`, which adds one to b
    if (one_gather) {
        const VI entry = hn::GatherIndex(di, srgb_entries(), slice);
        b = hn::And(hn::ShiftRight<24>(entry), hn::Set(di, 255));
        const VF step = hn::Mul(hn::ConvertTo(df, hn::And(entry, hn::Set(di, (1 << 24) - 1))),
                                hn::Set(df, 1.0f / 16777216.0f));
        // Both sides exact, so this is the same comparison as below.
        past_step = hn::Ge(hn::Sub(scaled, hn::ConvertTo(df, slice)), step);
    } else {
        b = hn::GatherIndex(di, first_bytes(), slice);
        past_step =
            hn::Ge(clamped, hn::GatherIndex(df, shading::srgb_byte_tables().steps.data(), b));
    }
    // No slice holds more than one step: one comparison finishes the search.
    b = hn::IfThenElse(hn::RebindMask(di, past_step), hn::Add(b, hn::Set(di, 1)), b);
    b = hn::IfThenElseZero(hn::RebindMask(di, positive), b);
    return hn::IfThenElse(hn::RebindMask(di, hn::And(positive, hn::Not(below_one))),
                          hn::Set(di, 255), b);
}
// [/doc:encode-channel]

// Lesson 08's visibility() at each lane of `lit` (a kept lane the key light
// reaches), 1 at the others (no light there to take away, or a colour thrown
// away). Lane by lane, in scalar code: each filter reads its own number of
// texels (1 to 25, clamped at the map's edge) around each lane's point, and
// lesson 08's function is the definition the picture must keep.
// [doc:light-reaching]
HWY_INLINE VF light_reaching(DF df, const Material& m, const Vec3& position, const Vec3& normal,
                             MF lit) {
    alignas(64) float x[hn::MaxLanes(df)], y[hn::MaxLanes(df)], z[hn::MaxLanes(df)];
    alignas(64) float nx[hn::MaxLanes(df)], ny[hn::MaxLanes(df)], nz[hn::MaxLanes(df)];
    alignas(64) float out[hn::MaxLanes(df)];
    hn::Store(position.x, df, x), hn::Store(position.y, df, y), hn::Store(position.z, df, z);
    hn::Store(normal.x, df, nx), hn::Store(normal.y, df, ny), hn::Store(normal.z, df, nz);
    std::uint8_t bits[8] = {};
    hn::StoreMaskBits(df, lit, bits);
    for (std::size_t lane = 0; lane < hn::Lanes(df); ++lane)
        out[lane] = (bits[lane / 8] >> (lane % 8)) & 1
                        ? shadows::visibility(*m.shadow_map, {x[lane], y[lane], z[lane]},
                                              rl::normalize(rl::vec3{nx[lane], ny[lane], nz[lane]}),
                                              m.shadow_lookup)
                        : 1.0f;
    return hn::Load(df, out);
}
// [/doc:light-reaching]

// What the shader reads of a pixel's triangle, lane by lane: lesson 05's
// perspective-correct varyings and the uv's screen derivatives (the mip
// level's footprint). Once interpolated, pixels of different triangles can
// share a vector (docs/12_fast.md, "Vectors across triangles").
inline constexpr int kFragmentFloats = kVaryingFloats + 4;
struct Fragments {
    // The varyings (position, normal, tangent, handedness, u, v), then
    // du/dx, dv/dx, du/dy, dv/dy.
    VF value[kFragmentFloats];
};

// The fragments of N pixels of triangle `t` at weights `b`.
HWY_INLINE Fragments interpolate(DF df, const FastTriangle& t, const VF (&b)[3]) {
    Fragments f;
    // Lesson 05's fragment_at: b . (varyings / w) times 1 / (b . 1/w).
    const VF inverse_w = hn::Add(hn::Add(hn::Mul(b[0], hn::Set(df, t.inverse_w[0])),
                                         hn::Mul(b[1], hn::Set(df, t.inverse_w[1]))),
                                 hn::Mul(b[2], hn::Set(df, t.inverse_w[2])));
    const VF w = hn::Div(hn::Set(df, 1.0f), inverse_w);
    for (int c = 0; c < kVaryingFloats; ++c)
        f.value[c] = hn::Mul(hn::Add(hn::Add(hn::Mul(b[0], hn::Set(df, t.over_w[0][c])),
                                             hn::Mul(b[1], hn::Set(df, t.over_w[1][c]))),
                                     hn::Mul(b[2], hn::Set(df, t.over_w[2][c]))),
                             w);
    // Lesson 05's Fragment::d_dx(&Varyings::uv): the quotient rule.
    const VF u = f.value[10], v = f.value[11];
    for (int axis = 0; axis < 2; ++axis) {
        const VF minus_d_inverse_w = hn::Set(df, -t.d_inverse_w[axis]);
        f.value[kVaryingFloats + 2 * axis] =
            hn::Mul(hn::MulAdd(u, minus_d_inverse_w, hn::Set(df, t.d_uv_over_w[axis][0])), w);
        f.value[kVaryingFloats + 2 * axis + 1] =
            hn::Mul(hn::MulAdd(v, minus_d_inverse_w, hn::Set(df, t.d_uv_over_w[axis][1])), w);
    }
    return f;
}

// Lesson 07's NormalMappedShader::fragment() for N pixels: fragments in,
// RGBA words out; with a shadow map, lesson 08's ShadowedShader::fragment().
// `active`: the lanes whose colours are kept (the others' are computed and
// thrown away; only the shadow lookup, lane by lane, skips them).
HWY_NOINLINE VU shade(DF df, const Material& m, const Fragments& f, MF active) {
    const VF(&v)[kFragmentFloats] = f.value;
    const Vec3 position{v[0], v[1], v[2]}, normal{v[3], v[4], v[5]}, tangent{v[6], v[7], v[8]};
    const VF handedness = v[9], u = v[10], vv = v[11];
    const VF du_dx = v[12], dv_dx = v[13], du_dy = v[14], dv_dy = v[15];

    // normal_at(): the map's normal, or the interpolated one.
    Vec3 n = normalize(df, normal);
    VF specular_texel = hn::Zero(df);  // the specular map's, read with the normal map
    if (m.normal_source != NormalSource::interpolated) {
        const Texel texel = sample(df, *m.normal_map, u, vv, du_dx, dv_dx, du_dy, dv_dy, m.filter,
                                   m.specular_in_normal_alpha ? 4 : 3);
        if (m.specular_in_normal_alpha) specular_texel = texel.c[3];
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
    for (int k = 0; k < m.lights; ++k) {
        // With shadows, lesson 08's order: the other lights, then the key light (light 0).
        const int i = m.shadow_map ? (k + 1) % m.lights : k;
        const Vec3 l = broadcast(df, m.light_direction[i]);
        const Vec3 colour = broadcast(df, m.light_colour[i]);
        const VF n_dot_l = dot(n, l);
        const MF lit = hn::Gt(n_dot_l, hn::Zero(df));
        if (hn::AllFalse(df, lit)) continue;
        const VF alignment =
            m.blinn ? dot(n, normalize(df, add(l, to_eye)))
                    : dot(sub(scale(n, hn::Mul(hn::Set(df, 2.0f), n_dot_l)), l), to_eye);
        const VF strength = highlight(df, alignment, m.shininess);
        Vec3 d = scale(colour, n_dot_l);
        Vec3 s = scale({hn::Mul(colour.x, specular_colour.x), hn::Mul(colour.y, specular_colour.y),
                        hn::Mul(colour.z, specular_colour.z)},
                       strength);
        // [doc:shadowed-key-light]
        if (i == 0 && m.shadow_map) {  // the offset goes along the interpolated normal
            const VF reaching = light_reaching(df, m, position, normal, hn::And(lit, active));
            d = scale(d, reaching), s = scale(s, reaching);
        }
        // [/doc:shadowed-key-light]
        diffuse = select(lit, add(diffuse, d), diffuse);
        specular = select(lit, add(specular, s), specular);
    }

    // surface_colour(): albedo times diffuse, plus the highlight times the specular map.
    VF shine = hn::Set(df, 1.0f);
    if (m.specular_map) {
        const VF peak = hn::Max(hn::Max(specular.x, specular.y), specular.z);
        const MF bright = hn::Ge(peak, hn::Set(df, 1e-4f));
        shine = hn::Zero(df);
        if (m.specular_in_normal_alpha) {
            shine = hn::IfThenElseZero(bright, specular_texel);
        } else if (!hn::AllFalse(df, bright)) {
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
    const VU red = hn::BitCast(du, encode_channel(df, r, m.srgb, m.srgb_one_gather));
    const VU green = hn::BitCast(du, encode_channel(df, g, m.srgb, m.srgb_one_gather));
    const VU blue = hn::BitCast(du, encode_channel(df, bl, m.srgb, m.srgb_one_gather));
    (void)di;
    return hn::Or(hn::Or(red, hn::ShiftLeft<8>(green)),
                  hn::Or(hn::ShiftLeft<16>(blue), hn::Set(du, 0xff000000u)));
}

// The same for N pixels of one triangle at weights `b` (the paths that
// shade a triangle's pixels where it covers them).
HWY_NOINLINE VU shade(DF df, const Material& m, const FastTriangle& t, const VF (&b)[3],
                      MF active) {
    return shade(df, m, interpolate(df, t, b), active);
}

}  // namespace HWY_NAMESPACE
}  // namespace fast
HWY_AFTER_NAMESPACE();

#endif  // RASTERLAB_FAST_SHADING_INL_H_
