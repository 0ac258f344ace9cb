// The environment a render reads: an analytic sky or studio, or a Radiance
// .hdr file (a lat-long image), stored as a cube map or a lat-long map and
// read through one filter.
//
//   const environment::Environment env = environment::make_environment(
//       {.source = "sky", .layout = environment::Layout::cube, .size = 256}, warnings);
//   const rl::vec3 light = env.sample({0, 1, 0});
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cube_map.hpp"
#include "latlong_map.hpp"

namespace environment {

enum class Layout { cube, latlong };
RASTERLAB_NAMED_ENUM(Layout, kLayouts, {Layout::cube, "cube"}, {Layout::latlong, "latlong"});

// Rays per side a texel of a built map averages: 4 on small maps, 2 from
// 256 texels up, where the sun's disc (2 degrees in radius) already spans
// 11 texels and 4 would cost four times the build for no measured gain.
inline int texel_samples(int size) {
    return size >= 256 ? 2 : 4;
}

struct EnvironmentOptions {
    std::string source = "sky";  // "sky", "studio", "white" or the path of a lat-long .hdr
    Layout layout = Layout::cube;
    // A cube face's side, or a lat-long map's height (its width is twice
    // that). 512: the lab's 09_maps, where the sky at 800x800 stops gaining
    // (the 99th percentile of its pixels within 1 level of the truth).
    int size = 512;
    MapFilter filter = MapFilter::seamless;
};

class Environment {
  public:
    Environment(CubeMap cube, MapFilter filter) : cube_(std::move(cube)), filter_(filter) {}
    Environment(LatLongMap latlong, MapFilter filter)
        : latlong_(std::move(latlong)), filter_(filter) {}
    Layout layout() const { return cube_ ? Layout::cube : Layout::latlong; }
    MapFilter filter() const { return filter_; }
    // The radiance arriving from `direction` (any length), at mip level `level`.
    rl::vec3 sample(rl::vec3 direction, float level = 0) const {
        return cube_ ? cube_->sample(direction, filter_, level)
                     : latlong_->sample(direction, filter_, level);
    }
    // The radiance from `direction` read trilinearly at mip level `level`,
    // whatever the filter: a wide average, for a prefilter's samples.
    rl::vec3 blurred(rl::vec3 direction, float level) const;
    // The angle one texel of level 0 spans at its face's or row's middle,
    // radians: a cube face's 90 degrees over its size, or 180 over the
    // lat-long map's height.
    double texel_radians() const;
    // The mip level whose texels span `radians` (0 for anything finer than
    // level 0): what a pixel of that angular size should read.
    float level_for(double radians) const;
    const CubeMap* cube() const { return cube_ ? &*cube_ : nullptr; }
    const LatLongMap* latlong() const { return latlong_ ? &*latlong_ : nullptr; }

  private:
    std::optional<CubeMap> cube_;
    std::optional<LatLongMap> latlong_;
    MapFilter filter_;
};

// The largest map a program builds: a cube face or a lat-long height of
// 2048 texels (six faces of 2048² float texels: 384 MiB with their mips).
inline constexpr int kMaxMapSize = 2048;

// The brightest texel a loaded map may hold: a billion times the sky (the
// real sun is about 10^5 times a clear sky's radiance).
inline constexpr float kMaxRadiance = 1e9f;

// Builds the environment the options ask for. A .hdr file is read as a
// lat-long image of at most 2 kMaxMapSize x kMaxMapSize texels (4096 x
// 2048: 128 MiB of floats), its header read first so that a larger one is
// refused before a texel is decoded; as a cube map each face texel reads it
// bilinearly. Its texels must be 0 to kMaxRadiance: others (a broken
// file) are set to 0 with a warning naming how many. Throws std::invalid_argument for a size
// outside 1..kMaxMapSize, rl::FileError for a file that cannot be read.
Environment make_environment(const EnvironmentOptions& options, std::vector<std::string>& warnings);

}  // namespace environment
