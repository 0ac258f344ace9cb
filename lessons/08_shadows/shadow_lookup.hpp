// The second pass's question at every shaded point: how much of the light
// reaches it? The point goes to the light's clip space, then to a position
// (u, v) in the map and a depth z; it is lit where z is no deeper than what
// the map stored there. Filters compare more than one texel and average the
// answers (percentage-closer filtering: the comparisons are averaged, never
// the depths). A normal offset moves the point along its surface normal by
// a number of map texels first, away from the surface it might shadow itself
// with. Derivations: docs/08_shadows.md#filtering-percentage-closer.
//
//   const float lit = shadows::visibility(map, world_point, world_normal,
//                                         {shadows::ShadowFilter::pcf2, 1.0f});
#pragma once

#include "rasterlab/named_enum.hpp"
#include "shadow_map.hpp"

namespace shadows {

enum class ShadowFilter { hard, pcf2, pcf3, pcf5, poisson };
RASTERLAB_NAMED_ENUM(ShadowFilter, kShadowFilters, {ShadowFilter::hard, "hard"},
                     {ShadowFilter::pcf2, "pcf2"}, {ShadowFilter::pcf3, "pcf3"},
                     {ShadowFilter::pcf5, "pcf5"}, {ShadowFilter::poisson, "poisson"});

struct ShadowLookup {
    // 2x2: the closest to a sun-sized light in the lab (08_filters), at no measurable cost.
    ShadowFilter filter = ShadowFilter::pcf2;
    float normal_offset = 1;  // along the normal, in map texels at the point (twice that for
                              // pcf5 and poisson, which reach two texels away)
};

// Where a world point lands in the map: texel coordinates (0..size across
// the map) and window depth from the light. `inside` is false beyond the
// map's sides, behind a spot light, or past its far plane: nothing there
// can be in shadow.
struct MapPoint {
    float u = 0, v = 0, depth = 0;
    bool inside = false;
};
MapPoint to_map(const ShadowMap& map, rl::vec3 world_point);

// Whether the map's texel (x, y) lets a point at `depth` through: 1 lit,
// 0 shadowed. Texels beyond the map's edge are taken from the edge.
float lit_by_texel(const ShadowMap& map, int x, int y, float depth);

// The light that reaches the point, 0 (shadowed) to 1 (lit). `normal` is
// the surface's unit normal there (for the normal offset).
float visibility(const ShadowMap& map, rl::vec3 world_point, rl::vec3 normal,
                 const ShadowLookup& lookup);

// The Poisson disc of the `poisson` filter: 16 points in the unit disc, no
// two closer than 0.3, from a fixed seed (the same picture on every run).
const std::array<rl::vec2, 16>& poisson_disc();

}  // namespace shadows
