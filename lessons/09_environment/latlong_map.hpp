// A lat-long (equirectangular) map: the environment unwrapped like a world
// map, longitude across (u, the full circle) and latitude up (v, pole to
// pole), twice as wide as high. One image, easy to store and paint, but its
// top and bottom rows each squeeze a whole circle into one point (the
// poles), and u = 0 and u = 1 meet at a seam. Derivation and pictures:
// docs/09_environment.md#lat-long-maps.
//
//   const environment::LatLongMap sky = environment::latlong_map(environment::Analytic::sky, 512);
//   const rl::vec3 light = sky.sample({0, 1, 0}, environment::MapFilter::bilinear);
#pragma once

#include <functional>

#include "04_textures/sampling.hpp"
#include "map_filter.hpp"
#include "rasterlab/image_io.hpp"
#include "sky.hpp"

namespace environment {

// Where a direction lands: u = 0.5 looks along -z (the camera's default
// view), u grows towards +x; v = 0 is straight down, 1 straight up. Zero
// or non-finite directions give (0.5, 0.5).
rl::dvec2 latlong_point(rl::dvec3 direction);

// The unit direction of (u, v).
rl::dvec3 latlong_direction(double u, double v);

class LatLongMap {
  public:
    explicit LatLongMap(rl::HdrImage image);
    int width() const { return map_.level(0).width(); }
    int height() const { return map_.level(0).height(); }
    const textures::HdrMipChain& map() const { return map_; }

    // The radiance from `direction`. Across u the map wraps (the seam is
    // filtered across); across v it stops at the poles' rows. `seamless`
    // is `bilinear` here; `trilinear` reads between mip levels.
    rl::vec3 sample(rl::vec3 direction, MapFilter filter, float level = 0) const;

  private:
    rl::vec3 bilinear(int level, double u, double v) const;
    textures::HdrMipChain map_;
};

// A function's lat-long map, `height` rows and twice as many columns, each
// texel the mean of `samples`² radiances spread evenly over it.
LatLongMap latlong_map(const std::function<rl::dvec3(rl::dvec3)>& radiance, int height,
                       int samples = 4);
LatLongMap latlong_map(Analytic which, int height, int samples = 4);

}  // namespace environment
