#include "shadow_lookup.hpp"

#include <algorithm>
#include <cmath>

#include "rasterlab/random.hpp"

namespace shadows {

MapPoint to_map(const ShadowMap& map, rl::vec3 world_point) {
    const rl::vec4 clip = map.light.view_projection * rl::extend(world_point, 1.0f);
    MapPoint out;
    if (!(clip.w > 0)) return out;  // behind a spot light (or NaN)
    const float size = static_cast<float>(map.size());
    const rl::vec3 ndc = clip.xyz() / clip.w;
    out.u = (ndc.x + 1) * 0.5f * size;
    out.v = (ndc.y + 1) * 0.5f * size;
    out.depth = (ndc.z + 1) * 0.5f;
    // The light's box hugs the scene, so a surface on its side (a floor
    // under a light straight above) lands on 1 give or take a rounding:
    // within 10^-5 of the box it is inside.
    constexpr float kRounding = 1e-5f;
    out.inside = std::abs(ndc.x) <= 1 + kRounding && std::abs(ndc.y) <= 1 + kRounding &&
                 ndc.z <= 1 + kRounding;
    out.depth = std::min(out.depth, 1.0f);
    return out;
}

float lit_by_texel(const ShadowMap& map, int x, int y, float depth) {
    x = std::clamp(x, 0, map.size() - 1);
    y = std::clamp(y, 0, map.size() - 1);
    return depth <= map.depth.at(x, y) ? 1.0f : 0.0f;
}

// [doc:visibility]
float visibility(const ShadowMap& map, rl::vec3 world_point, rl::vec3 normal,
                 const ShadowLookup& lookup) {
    // A kernel reaching two texels away compares depths two texels across
    // the surface's slope: it needs twice the offset of one reaching one.
    const float reach =
        lookup.filter == ShadowFilter::pcf5 || lookup.filter == ShadowFilter::poisson ? 2.0f : 1.0f;
    if (lookup.normal_offset != 0)
        world_point +=
            normal * (lookup.normal_offset * reach * map.light.texel_size(world_point, map.size()));
    const MapPoint p = to_map(map, world_point);
    if (!p.inside) return 1.0f;
    const int x = static_cast<int>(std::floor(p.u)), y = static_cast<int>(std::floor(p.v));
    switch (lookup.filter) {
        case ShadowFilter::hard:
            return lit_by_texel(map, x, y, p.depth);
        case ShadowFilter::pcf2: {
            // The four texels around the point, their answers weighted bilinearly
            // (what a GPU's comparison sampler does with linear filtering).
            const float fu = p.u - 0.5f, fv = p.v - 0.5f;
            const int x0 = static_cast<int>(std::floor(fu)), y0 = static_cast<int>(std::floor(fv));
            const float s = fu - static_cast<float>(x0), t = fv - static_cast<float>(y0);
            const float bottom = (1 - s) * lit_by_texel(map, x0, y0, p.depth) +
                                 s * lit_by_texel(map, x0 + 1, y0, p.depth);
            const float top = (1 - s) * lit_by_texel(map, x0, y0 + 1, p.depth) +
                              s * lit_by_texel(map, x0 + 1, y0 + 1, p.depth);
            return (1 - t) * bottom + t * top;
        }
        case ShadowFilter::pcf3:
        case ShadowFilter::pcf5: {
            const int r = lookup.filter == ShadowFilter::pcf3 ? 1 : 2;
            float sum = 0;
            for (int dy = -r; dy <= r; ++dy)
                for (int dx = -r; dx <= r; ++dx) sum += lit_by_texel(map, x + dx, y + dy, p.depth);
            return sum / static_cast<float>((2 * r + 1) * (2 * r + 1));
        }
        case ShadowFilter::poisson: {
            float sum = 0;
            for (const rl::vec2 d :
                 poisson_disc())  // a disc 2 texels in radius, like pcf5's square
                sum += lit_by_texel(map, static_cast<int>(std::floor(p.u + 2 * d.x)),
                                    static_cast<int>(std::floor(p.v + 2 * d.y)), p.depth);
            return sum / static_cast<float>(poisson_disc().size());
        }
    }
    return 1.0f;
}
// [/doc:visibility]

const std::array<rl::vec2, 16>& poisson_disc() {
    static const std::array<rl::vec2, 16> disc = [] {
        // Dart throwing: random points in the disc, each kept only if no kept
        // point is closer than 0.3. 16 points of that spacing fit easily.
        std::array<rl::vec2, 16> points{};
        rl::SplitMix64 random(18);
        std::size_t kept = 0;
        for (int attempt = 0; kept < points.size() && attempt < 100000; ++attempt) {
            const rl::vec2 p{static_cast<float>(random.uniform(-1, 1)),
                             static_cast<float>(random.uniform(-1, 1))};
            if (rl::dot(p, p) > 1) continue;
            bool far_enough = true;
            for (std::size_t i = 0; i < kept; ++i) far_enough &= rl::length(p - points[i]) >= 0.3f;
            if (far_enough) points[kept++] = p;
        }
        return points;
    }();
    return disc;
}

}  // namespace shadows
