// The lesson's environments as functions of direction: the light arriving
// from every direction around the scene (radiance, in linear units where
// the sky's horizon is about 1), defined analytically so that the lab knows
// the exact answer in any direction, and the maps of cube_map.hpp and
// latlong_map.hpp can be scored against it. Derivation and pictures:
// docs/09_environment.md#radiance-and-irradiance.
//
//   const environment::Sky sky = environment::default_sky();
//   const rl::dvec3 light = environment::radiance(sky, {0, 1, 0});  // the zenith
#pragma once

#include <array>

#include "rasterlab/named_enum.hpp"
#include "rasterlab/vec.hpp"

namespace environment {

// An outdoor sky: a sun disc with a soft corona around it, a gradient from
// the horizon up to the zenith, and a ground below the horizon. Directions
// are world space, +y up.
struct Sky {
    rl::dvec3 sun_direction;          // unit, towards the sun
    double sun_radius_degrees = 2.0;  // the disc's angular radius (the real sun: 0.27)
    rl::dvec3 sun{400, 360, 300};     // the disc's radiance
    rl::dvec3 corona{6, 5, 3.5};      // the glow's radiance next to the disc...
    double corona_degrees = 8.0;      // ...falling by e every this many degrees
    rl::dvec3 zenith{0.18, 0.32, 0.75};
    rl::dvec3 horizon{0.95, 0.95, 1.0};
    rl::dvec3 ground{0.25, 0.2, 0.15};
    // The ground as a checkerboard seen from one unit above it: squares of
    // this side (0: plain), the dark ones this colour. A mirror's image of
    // it shows at once how the mirror bends its view.
    double checker = 1.0;
    rl::dvec3 ground_dark{0.09, 0.07, 0.05};
    double horizon_band = 0.02;  // sin(elevation) over which the ground fades into the sky
};

// The sky the program and the lab use unless told otherwise: the sun up
// and to the right, 35 degrees above the horizon.
Sky default_sky();

// A studio: a dark room lit by two bright rectangular softboxes and a dim
// floor, the other classic environment for reflections (hard-edged lights).
struct Studio {
    rl::dvec3 walls{0.03, 0.03, 0.035};
    rl::dvec3 floor{0.08, 0.075, 0.07};
    rl::dvec3 softbox{12, 12, 11.5};
};

// `white`: radiance 1 from every direction, the "white furnace": a surface
// that neither makes nor loses light vanishes into it.
enum class Analytic { sky, studio, white };
RASTERLAB_NAMED_ENUM(Analytic, kAnalytics, {Analytic::sky, "sky"}, {Analytic::studio, "studio"},
                     {Analytic::white, "white"});

// The radiance arriving from `direction` (any length but zero; made unit
// here). A zero or non-finite direction gives black.
rl::dvec3 radiance(const Sky& sky, rl::dvec3 direction);
rl::dvec3 radiance(const Studio& studio, rl::dvec3 direction);
rl::dvec3 radiance(Analytic which, rl::dvec3 direction);  // the defaults of each

}  // namespace environment
