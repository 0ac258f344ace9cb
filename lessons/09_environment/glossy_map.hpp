// The environment blurred by the GGX lobe of each roughness ahead of time
// (prefiltered), the light half of the split sum: a shader reads the
// blurred light along the mirror direction instead of tracing hundreds of
// rays. Level 0 is the environment itself (roughness 0, a mirror); level k
// of `levels` is blurred for roughness k / (levels - 1), on a cube only as
// fine as that lobe needs; roughness in between mixes two levels.
// Derivation and pictures: docs/09_environment.md#the-split-sum.
//
//   const environment::GlossyMap glossy(env, {.levels = 6, .size = 128, .samples = 64});
//   const rl::vec3 light = glossy.sample(r, 0.5f);
//   const rl::vec3 one = environment::prefiltered_radiance(env, {0, 1, 0},
//                                                          environment::ggx_lobe(env, 0.5, 64));
#pragma once

#include <vector>

#include "environment.hpp"

namespace environment {

struct GlossyOptions {
    // 6 levels of 32 texels at most, 64 samples: the lab's 09_prefilter
    // finds them 7.9% from the truth on average over five roughnesses, on
    // its front of error against build time; the split sum's own error
    // keeps even 11 levels of 128 texels and 256 samples at 6.0%.
    int levels = 6;  // roughness 0, 0.2, ..., 1
    int size = 32;   // the largest prefiltered face (the least rough level's)
    // GGX directions per texel of the least rough level; each level with a
    // quarter of its texels takes four times as many.
    int samples = 64;
};

// The limits a GlossyMap checks (each a program's option).
inline constexpr int kMaxGlossyLevels = 17;
inline constexpr int kMaxGlossySize = 512;
inline constexpr int kMaxGlossySamples = 4096;
// The most environment reads the blurred maps may take, all levels
// together: 2^30, about 35 s on this project's 2-core machine (the lab's
// finest setting, 11 levels of 128 texels and 256 samples, takes 2.5 * 10^8).
inline constexpr long long kMaxGlossyWork = 1LL << 30;

// The light a surface of some roughness reflects towards a viewer along
// its normal r: the environment's radiance over GGX's reflected directions
// l, each weighted by n.l (Karis's prefilter, which takes n = v = r). The
// directions about +z, drawn once per roughness (`ggx_lobe`), turn to
// each r. Each reads the environment's mip level whose texels match the
// solid angle it stands for (filtered importance sampling), so a few dozen
// give little speckle.
struct LobeSample {
    rl::dvec3 direction;  // about +z, the mirror direction
    float level;          // the environment's mip level it reads
};
std::vector<LobeSample> ggx_lobe(const Environment& environment, double roughness, int samples);
rl::vec3 prefiltered_radiance(const Environment& environment, rl::dvec3 r,
                              const std::vector<LobeSample>& lobe);

// One bounce of Cook-Torrance by Monte Carlo: `samples` GGX facet
// normals that v sees (seeded by `seed`), each reflected ray's radiance
// weighted by f n.l / pdf = F G2 / G1(v). The
// reference the split sum is measured against; a bright sun makes it
// speckle (a ray that finds the sun carries hundreds of times the rest).
rl::vec3 glossy_monte_carlo(const Environment& environment, rl::vec3 n, rl::vec3 v, float roughness,
                            rl::vec3 f0, int samples, std::uint32_t seed);

// The face size the lobe of `roughness` needs: about 4 texels across
// alpha radians, a power of two from 8 to `largest`.
int glossy_face_size(double roughness, int largest);

class GlossyMap {
  public:
    // `environment` must outlive this (level 0 reads it). Throws
    // std::invalid_argument for options outside 2..kMaxGlossyLevels,
    // 8..kMaxGlossySize, 1..kMaxGlossySamples, or together over kMaxGlossyWork.
    GlossyMap(const Environment& environment, GlossyOptions options);
    int levels() const { return static_cast<int>(blurred_.size()) + 1; }
    const CubeMap& level(int k) const { return blurred_[static_cast<std::size_t>(k - 1)]; }
    // The prefiltered light along `r` for `roughness` (clamped to 0..1);
    // `mirror_level` is the mip level level 0 is read at.
    rl::vec3 sample(rl::vec3 r, float roughness, float mirror_level = 0) const;
    // Bytes held by the prefiltered levels (level 0 is the environment's).
    std::size_t bytes() const;

  private:
    const Environment* environment_;
    std::vector<CubeMap> blurred_;  // levels 1 .. levels - 1
};

// One image of the maps a render reads, named for a folder of Radiance
// .hdr files: the environment's cube faces (cube_<face>_<level>.hdr, faces
// px nx py ny pz nz, each mip level) or its lat-long map (latlong_<level>.hdr),
// and the split sum's blurred levels (glossy_<k>_<face>.hdr, roughness
// k / (levels - 1)), if given.
struct MapFile {
    std::string name;
    const rl::HdrImage* image;
};
std::vector<MapFile> map_files(const Environment& environment, const GlossyMap* glossy = nullptr);

}  // namespace environment
