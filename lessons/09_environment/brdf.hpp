// The microfacet BRDF of physically based renderers (Cook-Torrance): a
// rough surface is many tiny mirrors; GGX's D says how many face each way,
// Smith's G how many of those are neither hidden from the light nor from
// the eye, Schlick's F how much each mirror reflects. Then the split sum,
// which turns its integral against an environment into two look-ups, and
// the share of light a single bounce loses (put back, so that the BRDF
// conserves energy at every roughness). Derivation and pictures:
// docs/09_environment.md#glossy-light-the-microfacet-brdf.
//
//   const double alpha = environment::ggx_alpha(0.5);
//   const rl::dvec3 f = environment::cook_torrance(n, v, l, alpha, {0.04, 0.04, 0.04});
//   const environment::SplitSum ab = environment::split_sum_table().at(0.7f, 0.5f);
//   const environment::SpecularShares s = environment::specular_shares({1, 0.71f, 0.29f}, ab);
#pragma once

#include <cmath>
#include <vector>

#include "rasterlab/vec.hpp"

namespace environment {

// GGX's alpha for a "perceptual" roughness in [0, 1]: its square, so that
// equal steps of roughness look like equal steps of blur.
inline double ggx_alpha(double roughness) {
    return roughness * roughness;
}

// D: the density of microfacet normals h at angle acos(n_dot_h) from n
// (per steradian, weighted so that its integral times n.h over the
// hemisphere is 1). alpha must be > 0: at 0 it is a mirror, a spike.
double ggx_distribution(double n_dot_h, double alpha);

// G2: the share of facets seen from both v and l (height-correlated Smith:
// a facet hidden from one is likelier hidden from the other). 1 - at most
// - head-on and 0 at grazing.
double smith_masking(double n_dot_v, double n_dot_l, double alpha);

// Schlick's Fresnel for each channel of the head-on reflectance f0.
rl::dvec3 schlick(double cos_theta, rl::dvec3 f0);

// f(v, l) = D G F / (4 n.l n.v) for unit n, v (towards the eye) and l
// (towards the light); 0 when either is below the surface.
rl::dvec3 cook_torrance(rl::dvec3 n, rl::dvec3 v, rl::dvec3 l, double alpha, rl::dvec3 f0);

// A facet normal about +z drawn with density D(h) (n.h) from u in [0, 1)²
// (u.x picks the angle from the normal, u.y the turn about it): where D is
// large, more samples (importance sampling).
rl::dvec3 ggx_half_vector(rl::dvec2 u, double alpha);

// A facet normal about +z as seen from v (unit, v.z > 0): drawn with
// density G1(v) D(h) max(0, v.h) / v.z, the facets v actually sees (Heitz's
// visible-normal sampling). Its ray's weight f n.l / pdf is F G2 / G1(v),
// at most F: no sample can return more light than arrives, and grazing
// views lose the huge weights that D(h) sampling gives them.
rl::dvec3 ggx_visible_normal(rl::dvec3 v, rl::dvec2 u, double alpha);

// G1(v): the share of facets facing v that v sees (what G2 is for one direction).
double smith_masking_one(double n_dot_v, double alpha);

// The integral of the BRDF times n.l over all light directions for
// Schlick's F splits into f0 * scale + bias (for a given n.v and
// roughness): the BRDF's half of the split sum.
struct SplitSum {
    double scale = 0, bias = 0;
    // f0 = 1: all the light one bounce returns (the directional albedo).
    double albedo() const { return scale + bias; }
};

// SplitSum by importance sampling with `samples` Hammersley points (in
// double; n.v is clamped to at least 1e-4).
SplitSum split_sum(double n_dot_v, double roughness, int samples);

// SplitSum on a 32 x 32 grid of n.v and roughness, read bilinearly: what a
// GPU keeps in a small texture.
class SplitSumTable {
  public:
    static constexpr int kSize = 32;
    static constexpr int kSamples = 1024;  // per entry
    SplitSumTable();
    SplitSum at(float n_dot_v, float roughness) const;

  private:
    std::vector<SplitSum> entries_;  // [roughness row][n.v column], texel centres
};

// The table, built the first time it is asked for (about 20 ms).
const SplitSumTable& split_sum_table();

// Where to read the blurred maps for a rough surface: the prefilter assumed
// the eye on the normal, but seen at a slant a rough lobe leans from the
// mirror direction r towards the normal n. Lagarde and de Rousiers' fit
// (2014) of that lean: all the way to r for a mirror, to n for roughness 1.
inline rl::vec3 dominant_direction(rl::vec3 n, rl::vec3 r, float roughness) {
    const float smooth = 1 - roughness;
    const float towards_r = smooth * (std::sqrt(smooth) + roughness);
    return rl::normalize(n + (r - n) * towards_r);
}

// How much of the prefiltered radiance (`single`: one bounce, f0 scale +
// bias) and of the cosine-weighted mean radiance E / pi (`multiple`: light
// that bounced between facets before leaving) a surface of head-on
// reflectance f0 returns. `multiple` is the energy one bounce lost,
// 1 - albedo, times the Fresnel of many bounces (Fdez-Aguera's estimate);
// with compensate = false it is 0, and rough surfaces come out too dark.
struct SpecularShares {
    rl::vec3 single, multiple;
};
SpecularShares specular_shares(rl::vec3 f0, SplitSum split, bool compensate = true);

}  // namespace environment
