#include "brdf.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sphere_sampling.hpp"

namespace environment {

namespace {

constexpr double kPi = std::numbers::pi;

// Smith's Lambda for GGX: the hidden facets' share, seen at angle
// acos(c) from the normal, over the visible ones.
double smith_lambda(double c, double alpha) {
    const double c2 = c * c;
    const double tan2 = std::max(0.0, 1 - c2) / std::max(c2, 1e-300);
    return 0.5 * (std::sqrt(1 + alpha * alpha * tan2) - 1);
}

}  // namespace

double ggx_distribution(double n_dot_h, double alpha) {
    if (n_dot_h <= 0) return 0;
    const double a2 = alpha * alpha;
    const double d = n_dot_h * n_dot_h * (a2 - 1) + 1;
    return a2 / (kPi * d * d);
}

double smith_masking(double n_dot_v, double n_dot_l, double alpha) {
    if (n_dot_v <= 0 || n_dot_l <= 0) return 0;
    return 1 / (1 + smith_lambda(n_dot_v, alpha) + smith_lambda(n_dot_l, alpha));
}

rl::dvec3 schlick(double cos_theta, rl::dvec3 f0) {
    const double m = 1 - std::clamp(cos_theta, 0.0, 1.0);
    const double m5 = (m * m) * (m * m) * m;
    return f0 + (rl::dvec3{1, 1, 1} - f0) * m5;
}

rl::dvec3 cook_torrance(rl::dvec3 n, rl::dvec3 v, rl::dvec3 l, double alpha, rl::dvec3 f0) {
    const double n_dot_v = rl::dot(n, v), n_dot_l = rl::dot(n, l);
    if (n_dot_v <= 0 || n_dot_l <= 0) return {0, 0, 0};
    const rl::dvec3 h = rl::normalize(v + l);
    const double d = ggx_distribution(rl::dot(n, h), alpha);
    const double g = smith_masking(n_dot_v, n_dot_l, alpha);
    return schlick(rl::dot(v, h), f0) * (d * g / (4 * n_dot_l * n_dot_v));
}

rl::dvec3 ggx_half_vector(rl::dvec2 u, double alpha) {
    // Inverting the cumulative distribution of D(h) cos(theta_h) over the
    // hemisphere: cos^2(theta) = (1 - u) / (1 + (alpha^2 - 1) u); phi
    // uniform. Theta takes u.x, which the Hammersley set spreads evenly from
    // 1/2n to 1 - 1/2n: no point sits exactly on the normal.
    const double a2 = alpha * alpha;
    const double cos2 = (1 - u.x) / (1 + (a2 - 1) * u.x);
    const double cos_theta = std::sqrt(std::clamp(cos2, 0.0, 1.0));
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    const double phi = 2 * kPi * u.y;
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

double smith_masking_one(double n_dot_v, double alpha) {
    return n_dot_v <= 0 ? 0 : 1 / (1 + smith_lambda(n_dot_v, alpha));
}

// [doc:visible-normal]
rl::dvec3 ggx_visible_normal(rl::dvec3 v, rl::dvec2 u, double alpha) {
    // Stretch the view so that the rough surface becomes a hemisphere of
    // unit facets (alpha = 1), pick a point on the disc it shows to v (the
    // far half squashed by how much of it v sees), lift it onto the
    // hemisphere, and unstretch that normal.
    const rl::dvec3 stretched = rl::normalize(rl::dvec3{alpha * v.x, alpha * v.y, v.z});
    const double across = stretched.x * stretched.x + stretched.y * stretched.y;
    const rl::dvec3 t1 = across > 0 ? rl::dvec3{-stretched.y, stretched.x, 0} / std::sqrt(across)
                                    : rl::dvec3{1, 0, 0};
    const rl::dvec3 t2 = rl::cross(stretched, t1);
    const double r = std::sqrt(u.x), phi = 2 * kPi * u.y;
    const double p1 = r * std::cos(phi);
    const double s = 0.5 * (1 + stretched.z);
    const double p2 = (1 - s) * std::sqrt(std::max(0.0, 1 - p1 * p1)) + s * r * std::sin(phi);
    const rl::dvec3 on_hemisphere =
        t1 * p1 + t2 * p2 + stretched * std::sqrt(std::max(0.0, 1 - p1 * p1 - p2 * p2));
    return rl::normalize(rl::dvec3{alpha * on_hemisphere.x, alpha * on_hemisphere.y,
                                   std::max(0.0, on_hemisphere.z)});
}
// [/doc:visible-normal]

// [doc:split-sum]
SplitSum split_sum(double n_dot_v, double roughness, int samples) {
    const double alpha = ggx_alpha(roughness);
    const double nv = std::clamp(n_dot_v, 1e-4, 1.0);
    const rl::dvec3 v{std::sqrt(1 - nv * nv), 0, nv};  // n = +z
    SplitSum sum;
    const auto count = static_cast<std::uint32_t>(std::max(samples, 1));
    for (std::uint32_t i = 0; i < count; ++i) {
        const rl::dvec3 h = ggx_visible_normal(v, hammersley(i, count), alpha);
        const double v_dot_h = rl::dot(v, h);
        const rl::dvec3 l = h * (2 * v_dot_h) - v;
        if (l.z <= 0 || v_dot_h <= 0) continue;
        // f n.l / pdf = F G2 / G1(v), with F = f0 (1 - Fc) + Fc.
        const double weight = smith_masking(nv, l.z, alpha) / smith_masking_one(nv, alpha);
        const double m = 1 - v_dot_h, fc = (m * m) * (m * m) * m;
        sum.scale += (1 - fc) * weight;
        sum.bias += fc * weight;
    }
    return {sum.scale / count, sum.bias / count};
}
// [/doc:split-sum]

SplitSumTable::SplitSumTable() : entries_(kSize * kSize) {
    // Entries at the grid's corners (n.v and roughness from 0 to 1), so that
    // a mirror (roughness 0) and a head-on view read their exact entries.
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i)
            entries_[static_cast<std::size_t>(j * kSize + i)] =
                split_sum(static_cast<double>(i) / (kSize - 1),
                          static_cast<double>(j) / (kSize - 1), kSamples);
}

SplitSum SplitSumTable::at(float n_dot_v, float roughness) const {
    const auto place = [](float value, int& index, double& t) {
        const double x =
            (std::isfinite(value) ? std::clamp(static_cast<double>(value), 0.0, 1.0) : 0.0) *
            (kSize - 1);
        index = std::min(static_cast<int>(x), kSize - 2);
        t = x - index;
    };
    int i = 0, j = 0;
    double s = 0, t = 0;
    place(n_dot_v, i, s);
    place(roughness, j, t);
    const auto entry = [&](int a, int b) {
        return entries_[static_cast<std::size_t>((j + b) * kSize + i + a)];
    };
    const auto mix = [](SplitSum p, SplitSum q, double w) {
        return SplitSum{p.scale + (q.scale - p.scale) * w, p.bias + (q.bias - p.bias) * w};
    };
    return mix(mix(entry(0, 0), entry(1, 0), s), mix(entry(0, 1), entry(1, 1), s), t);
}

const SplitSumTable& split_sum_table() {
    static const SplitSumTable table;
    return table;
}

// [doc:specular-shares]
SpecularShares specular_shares(rl::vec3 f0, SplitSum split, bool compensate) {
    const rl::vec3 one{1, 1, 1};
    const auto scale = static_cast<float>(split.scale), bias = static_cast<float>(split.bias);
    const rl::vec3 single = f0 * scale + one * bias;
    if (!compensate) return {single, {0, 0, 0}};
    // One bounce returns `albedo` of the light; the rest hits another facet.
    // Of that, each further bounce keeps f_avg (Fresnel averaged over the
    // hemisphere: f0 + (1 - f0) / 21 for Schlick's), a geometric series.
    const float lost = std::max(0.0f, 1 - static_cast<float>(split.albedo()));
    const rl::vec3 f_avg = f0 + (one - f0) * (1.0f / 21);
    rl::vec3 multiple;
    for (std::size_t c = 0; c < 3; ++c)
        multiple[c] = single[c] * f_avg[c] * lost / (1 - lost * f_avg[c]);
    return {single, multiple};
}
// [/doc:specular-shares]

}  // namespace environment
