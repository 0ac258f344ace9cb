#include "ambient_occlusion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "09_environment/sphere_sampling.hpp"
#include "rasterlab/workers.hpp"

namespace occlusion {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// A fixed pseudo-random number in [0, 1) for (i, stream): the kernel's seed.
float fixed_random(int i, std::uint32_t stream) {
    return static_cast<float>(environment::unit_interval(environment::hash(
        static_cast<std::uint32_t>(i) * 2654435761u ^ environment::hash(stream))));
}

// A unit direction from two numbers in [0, 1): uniform over the sphere.
rl::vec3 sphere_direction(float u, float v) {
    const float z = 1 - 2 * u, r = std::sqrt(std::max(0.0f, 1 - z * z)), phi = 2 * kPi * v;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Point i's distance from the centre: more points near it, where occluders
// matter most (their cosine and their nearness), as Crytek's kernel does.
float kernel_scale(int i, int n) {
    const float s = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
    return 0.1f + 0.9f * s * s;
}

// Two unit tangents and the normal, turned by `turn` (a share of a full
// turn) about the normal: the pixel's own rotation of the kernel.
struct TurnedFrame {
    rl::vec3 t, b, n;
    TurnedFrame(rl::vec3 normal, float turn) : n(normal) {
        const environment::Frame f(rl::cast<double>(normal));
        const float c = std::cos(2 * kPi * turn), s = std::sin(2 * kPi * turn);
        const rl::vec3 t0 = rl::cast<float>(f.t), b0 = rl::cast<float>(f.b);
        t = t0 * c + b0 * s;
        b = b0 * c - t0 * s;
    }
    rl::vec3 to_world(rl::vec3 local) const { return t * local.x + b * local.y + n * local.z; }
};

// The view depth the depth buffer holds where world point s lands, and s's
// own; nothing when s falls off the screen or on no model (then nothing
// there can hide it).
struct DepthPair {
    float sample, buffer;
};
std::optional<DepthPair> depths_at(const Surfaces& surfaces, rl::vec3 s) {
    const rl::vec3 w = surfaces.screen.project(s);
    if (!(w.z > 0) || !surfaces.inside(w.x, w.y))
        return std::nullopt;  // behind the eye, off screen
    const float buffer = surfaces.screen.depth_of(surfaces.surface_at(w.x, w.y));
    if (std::isnan(buffer)) return std::nullopt;
    return DepthPair{w.z, buffer};
}

// [doc:crytek]
float crytek(const Surfaces& surfaces, rl::vec3 p, float turn, const AoOptions& o) {
    // The ball turned about the line of sight: no normal is used.
    const TurnedFrame frame(rl::normalize(surfaces.screen.eye() - p), turn);
    const float bias = 0.02f * o.radius;
    int hidden = 0;
    for (int i = 0; i < o.samples; ++i) {
        const rl::vec3 s = p + frame.to_world(ball_point(i, o.samples)) * o.radius;
        const std::optional<DepthPair> d = depths_at(surfaces, s);
        if (d && d->buffer < d->sample - bias) ++hidden;
    }
    return 1 - static_cast<float>(hidden) / static_cast<float>(o.samples);
}
// [/doc:crytek]

// [doc:hemisphere]
float hemisphere(const Surfaces& surfaces, rl::vec3 p, float depth, rl::vec3 n, float turn,
                 const AoOptions& o) {
    const TurnedFrame frame(n, turn);
    const float bias = 0.02f * o.radius;
    float hidden = 0;
    for (int i = 0; i < o.samples; ++i) {
        const rl::vec3 s = p + frame.to_world(hemisphere_point(i, o.samples)) * o.radius;
        const std::optional<DepthPair> d = depths_at(surfaces, s);
        if (!d || !(d->buffer < d->sample - bias)) continue;
        // The range check: a surface far in front of p (a nearer object's
        // edge) hides the sample on screen but is not near p: it counts
        // less the farther it is, past the radius.
        const float gap = std::fabs(depth - d->buffer);
        const float t = std::clamp(o.radius / std::max(gap, 1e-6f), 0.0f, 1.0f);
        hidden += t * t * (3 - 2 * t);
    }
    return 1 - hidden / static_cast<float>(o.samples);
}
// [/doc:hemisphere]

// [doc:horizon]
float horizon(const Surfaces& surfaces, int x, int y, rl::vec3 p, float depth, rl::vec3 n,
              float turn, float jitter, const AoOptions& o) {
    const Screen& screen = surfaces.screen;
    const HorizonSteps split = horizon_steps(o.samples);
    const int slices = split.slices, steps = split.steps;
    const rl::vec3 v = rl::normalize(screen.eye() - p);
    const float reach = o.radius * screen.pixels_per_unit(depth);  // in pixels
    float open = 0, unoccluded = 0;
    for (int i = 0; i < slices; ++i) {
        const float phi = kPi * (static_cast<float>(i) + turn) / static_cast<float>(slices);
        const float cx = std::cos(phi), cy = std::sin(phi);
        // The slice: the plane through the eye direction and this screen direction.
        const rl::vec3 along = screen.right() * cx + screen.up() * cy;
        const rl::vec3 t = rl::normalize(along - v * rl::dot(along, v));
        float highest[2] = {-1, -1};  // cosines of the horizons on the +t and -t sides
        for (int side = 0; side < 2; ++side) {
            const float sign = side == 0 ? 1.0f : -1.0f;
            for (int k = 0; k < steps; ++k) {
                const float r = std::max(
                    1.0f, reach * (static_cast<float>(k) + jitter) / static_cast<float>(steps));
                const float qx = static_cast<float>(x) + 0.5f + sign * cx * r,
                            qy = static_cast<float>(y) + 0.5f + sign * cy * r;
                if (!surfaces.inside(qx, qy)) break;  // off the screen: nothing known beyond
                const rl::vec3 h = surfaces.surface_at(qx, qy) - p;
                const float length = rl::length(h);
                if (!(length > 1e-6f) || length > o.radius) continue;  // NaN: no model
                highest[side] = std::max(highest[side], rl::dot(h, v) / length);
            }
        }
        // The normal projected into the slice, and its angle from v (towards t).
        const rl::vec3 axis = rl::normalize(rl::cross(t, v));
        const rl::vec3 projected = n - axis * rl::dot(n, axis);
        const float weight = rl::length(projected);
        if (!(weight > 1e-6f)) continue;
        const float gamma = std::atan2(rl::dot(projected, t), rl::dot(projected, v));
        // Nothing below the surface counts: the horizons at most 90 degrees
        // from the normal.
        const float h2 = std::min(std::acos(std::clamp(highest[0], -1.0f, 1.0f)), gamma + kPi / 2);
        const float h1 = std::max(-std::acos(std::clamp(highest[1], -1.0f, 1.0f)), gamma - kPi / 2);
        open += weight * slice_visibility(h1, h2, gamma);
        // A slice with nothing in it is not exactly 1 when the normal leans
        // in it (cos g + g sin g); only the mean over every slice is. With
        // few slices, dividing by the unoccluded slices' own sum keeps an
        // open floor at 1 rather than at 0.95 or 1.04 pixel by pixel.
        unoccluded += weight * slice_visibility(gamma - kPi / 2, gamma + kPi / 2, gamma);
    }
    if (!(unoccluded > 1e-6f)) return 1;
    return std::clamp(open / unoccluded, 0.0f, 1.0f);
}
// [/doc:horizon]

}  // namespace

// [doc:slice-visibility]
float slice_visibility(float h1, float h2, float gamma) {
    const auto side = [gamma](float h) {
        return 0.25f * (-std::cos(2 * h - gamma) + std::cos(gamma) + 2 * h * std::sin(gamma));
    };
    return side(h1) + side(h2);
}
// [/doc:slice-visibility]

HorizonSteps horizon_steps(int samples) {
    const int steps = std::clamp(samples / 2, 1, 4);
    return {std::max(1, samples / (2 * steps)), steps};
}

void check(const AoOptions& o) {
    if (o.samples < 1 || o.samples > kMaxAoSamples)
        throw std::invalid_argument("--samples: " + std::to_string(o.samples) +
                                    " is outside 1 to " + std::to_string(kMaxAoSamples));
    if (!(o.radius > 0) || !std::isfinite(o.radius))
        throw std::invalid_argument("--radius: " + std::to_string(o.radius) +
                                    " is not a positive length");
    if (o.blur < 0 || o.blur > kMaxBlurRadius)
        throw std::invalid_argument("--blur: " + std::to_string(o.blur) + " is outside 0 to " +
                                    std::to_string(kMaxBlurRadius));
}

rl::vec3 ball_point(int i, int n) {
    return sphere_direction(fixed_random(i, 1), fixed_random(i, 2)) * kernel_scale(i, n);
}

rl::vec3 hemisphere_point(int i, int n) {
    rl::vec3 d = sphere_direction(fixed_random(i, 3), fixed_random(i, 4));
    d.z = std::fabs(d.z);
    return d * kernel_scale(i, n);
}

float rotation_at(int x, int y) {
    // A 4x4 Bayer matrix: neighbours differ as much as they can.
    static constexpr int kBayer[4][4] = {
        {0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    return (static_cast<float>(kBayer[y & 3][x & 3]) + 0.5f) / 16;
}

Surfaces::Surfaces(const GBuffer& gbuffer, const Screen& s)
    : g(gbuffer),
      screen(s),
      depth(g.width(), g.height(), NAN),
      position(g.width(), g.height(), rl::vec3{NAN, NAN, NAN}) {
    rl::parallel_for(0, g.height(), [&](int y) {
        for (int x = 0; x < g.width(); ++x)
            if (const std::optional<rl::vec3> p = screen.position(g, x, y)) {
                position.at(x, y) = *p;
                depth.at(x, y) = screen.view_depth(g.depth()->get(x, y));
            }
    });
}

// [doc:surface-at]
rl::vec3 Surfaces::surface_at(float x, float y) const {
    const int i = static_cast<int>(x), j = static_cast<int>(y);
    const rl::vec3 centre = position.get(i, j);
    if (std::isnan(centre.x)) return centre;
    const rl::vec3 n = g.colour<kNormal>().get(i, j), ray = screen.ray(x, y);
    const float facing = rl::dot(ray, n);
    if (!(std::fabs(facing) > 0.05f)) return centre;
    const rl::vec3 hit = screen.eye() + ray * (rl::dot(centre - screen.eye(), n) / facing);
    // Within a pixel's width along the plane (its footprint, stretched by
    // the slant): farther means the normal does not describe this pixel.
    const float reach = depth.get(i, j) / screen.pixels_per_unit(1) / std::fabs(facing);
    return rl::length(hit - centre) <= reach ? hit : centre;
}
// [/doc:surface-at]

rl::FloatImage raw_occlusion(const Surfaces& surfaces, const AoOptions& o) {
    check(o);
    const GBuffer& g = surfaces.g;
    rl::FloatImage ao(g.width(), g.height(), 1.0f);
    if (o.method == AoMethod::none) return ao;
    // Rows on every core: each pixel reads the G-buffer and writes its own.
    rl::parallel_for(0, g.height(), [&](int y) {
        for (int x = 0; x < g.width(); ++x) {
            const float depth = surfaces.depth.get(x, y);
            if (std::isnan(depth)) continue;
            const rl::vec3 p = surfaces.position.get(x, y), n = g.colour<kNormal>().get(x, y);
            const float turn = o.rotate ? rotation_at(x, y) : 0.5f;
            const float jitter = o.rotate ? rotation_at(y + 1, x + 2) : 0.5f;
            switch (o.method) {
                case AoMethod::crytek:
                    ao.at(x, y) = crytek(surfaces, p, turn, o);
                    break;
                case AoMethod::hemisphere:
                    ao.at(x, y) = hemisphere(surfaces, p, depth, n, turn, o);
                    break;
                case AoMethod::horizon:
                    ao.at(x, y) = horizon(surfaces, x, y, p, depth, n, turn, jitter, o);
                    break;
                case AoMethod::none:
                case AoMethod::baked:
                    break;
            }
        }
    });
    return ao;
}

// [doc:surface-blur]
rl::FloatImage surface_blur(const rl::FloatImage& ao, const Surfaces& surfaces, int radius,
                            float ao_radius) {
    rl::FloatImage out = ao;
    if (radius <= 0) return out;
    const GBuffer& g = surfaces.g;
    const float same_plane = 0.1f * ao_radius, same_facing = std::cos(rl::radians(25.0f));
    rl::parallel_for(0, g.height(), [&](int y) {
        for (int x = 0; x < g.width(); ++x) {
            if (std::isnan(surfaces.depth.get(x, y))) continue;
            const rl::vec3 p = surfaces.position.get(x, y), n = g.colour<kNormal>().get(x, y);
            float sum = 0, count = 0;
            for (int j = std::max(0, y - radius); j <= std::min(g.height() - 1, y + radius); ++j)
                for (int i = std::max(0, x - radius); i <= std::min(g.width() - 1, x + radius);
                     ++i) {
                    // Another surface (or none: NaN fails both): its occlusion is not this one's.
                    if (!(std::fabs(rl::dot(surfaces.position.get(i, j) - p, n)) <= same_plane) ||
                        !(rl::dot(g.colour<kNormal>().get(i, j), n) >= same_facing))
                        continue;
                    sum += ao.get(i, j);
                    count += 1;
                }
            if (count > 0) out.at(x, y) = sum / count;  // 0 only for a broken normal
        }
    });
    return out;
}
// [/doc:surface-blur]

rl::FloatImage ambient_occlusion(const GBuffer& g, const Screen& screen, const AoOptions& o) {
    check(o);
    if (o.method == AoMethod::none) return rl::FloatImage(g.width(), g.height(), 1.0f);
    if (o.method == AoMethod::baked)
        throw std::invalid_argument(
            "baked occlusion comes from the models' vertices, not the screen");
    const Surfaces surfaces(g, screen);
    return surface_blur(raw_occlusion(surfaces, o), surfaces, o.blur, o.radius);
}

}  // namespace occlusion
