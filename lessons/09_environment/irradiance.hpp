// Diffuse light from the whole environment. A matte (Lambert) surface with
// normal n reflects albedo / pi times its irradiance, E(n) = the integral
// over the sphere of L(w) max(0, n.w) dw: the environment seen through a
// cosine-shaped window. Three ways to have E at every pixel: spherical
// harmonics (the environment's 1, 4 or 9 smoothest components, which the
// cosine window keeps almost whole), a small cube map of E computed by brute
// force, or Monte Carlo rays at each pixel. Derivation and pictures:
// docs/09_environment.md#diffuse-light-irradiance-three-ways.
//
//   const environment::ShLight sh = environment::project_sh(cube, 3);
//   const rl::vec3 e = environment::irradiance(sh, normal);            // 9 numbers per channel
//   const environment::CubeMap e_map = environment::irradiance_map(cube, 16);
//   const environment::DiffuseLight diffuse(
//       [&](rl::vec3 d) { return env.sample(d); }, environment::Irradiance::sh3);
//   const rl::vec3 e2 = diffuse.at(normal);
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

#include "cube_map.hpp"

namespace environment {

// The environment's radiance as real spherical harmonics of bands 0 to
// order - 1 (order 1: 1 coefficient per channel, 2: 4, 3: 9), in the order
// l = 0; l = 1 (m = -1, 0, 1); l = 2 (m = -2 .. 2).
struct ShLight {
    int order = 3;
    std::array<rl::dvec3, 9> coefficients{};
};

// The nine basis functions at a unit direction.
std::array<double, 9> sh_basis(rl::dvec3 d);

// The solid angle of texel (i, j) of a size x size cube face: exact (the
// texels near a face's corners subtend less than those at its centre).
double texel_solid_angle(int i, int j, int size);

// Projects the cube map (level 0) onto the first `order` bands, each texel
// weighted by its solid angle. Throws std::invalid_argument for an order
// outside 1..3.
ShLight project_sh(const CubeMap& cube, int order);

// E(n) from the harmonics: each band scaled by the cosine window's own
// coefficient (pi, 2 pi / 3, pi / 4), then summed at n. Never negative
// (a truncated series can dip below 0 opposite a bright sun: clamped).
rl::vec3 irradiance(const ShLight& sh, rl::vec3 normal);

// A size x size cube map of E, each texel's E summed over every texel of
// the source's mip level that is at most 32 texels a side (the cosine window
// is wide: finer texels change E by little and cost their square).
CubeMap irradiance_map(const CubeMap& source, int size);

// E(n) by Monte Carlo: `samples` cosine-distributed directions around n,
// each worth pi / samples of the radiance `source` gives for it; `seed`
// picks the directions (a pixel's own seed gives noise that does not crawl
// between frames).
rl::vec3 irradiance_monte_carlo(const std::function<rl::vec3(rl::vec3)>& source, rl::vec3 normal,
                                int samples, std::uint32_t seed);

// How a render finds E at a pixel.
enum class Irradiance { sh1, sh2, sh3, convolved, monte_carlo };
RASTERLAB_NAMED_ENUM(Irradiance, kIrradiances, {Irradiance::sh1, "sh1"}, {Irradiance::sh2, "sh2"},
                     {Irradiance::sh3, "sh3"}, {Irradiance::convolved, "convolved"},
                     {Irradiance::monte_carlo, "monte-carlo"});

// The most Monte Carlo rays a pixel may take.
inline constexpr int kMaxIrradianceSamples = 65536;

// One method's diffuse light, prepared once per environment: the harmonics
// or the convolved map (from a 64-texel cube of the environment: E needs no
// more), or, for Monte Carlo, the environment itself and the ray count.
class DiffuseLight {
  public:
    // `environment` must outlive this (Monte Carlo reads it per pixel).
    // Throws std::invalid_argument for samples outside 1..kMaxIrradianceSamples.
    DiffuseLight(const std::function<rl::vec3(rl::vec3)>& environment, Irradiance method,
                 int samples = 64);
    Irradiance method() const { return method_; }
    // E at a unit normal; `seed` is used by Monte Carlo only.
    rl::vec3 at(rl::vec3 normal, std::uint32_t seed = 0) const;

  private:
    Irradiance method_;
    int samples_;
    std::function<rl::vec3(rl::vec3)> environment_;
    ShLight sh_;
    std::optional<CubeMap> convolved_;
};

}  // namespace environment
