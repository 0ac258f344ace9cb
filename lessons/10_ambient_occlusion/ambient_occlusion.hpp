// Screen-space ambient occlusion: from the G-buffer alone, how much of the
// hemisphere above each visible point is open within a radius, weighted by
// the cosine to the normal (1: open, 0: closed). Three methods, each with
// a fixed-seed kernel and a rotation that differs from pixel to pixel
// (a 4x4 tile of noise), then a blur that keeps to one surface.
// Derivations and pictures: docs/10_ambient_occlusion.md.
//
//   const occlusion::AoOptions options{.method = occlusion::AoMethod::horizon, .samples = 16};
//   const rl::FloatImage ao = occlusion::ambient_occlusion(g, screen, options);
#pragma once

#include <array>

#include "gbuffer.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/named_enum.hpp"

namespace occlusion {

// none: every point open. crytek: points in a ball around the point, no
// normal (Crysis, 2007): a flat floor comes out half closed. hemisphere:
// points in the half ball above the normal, with a range check.
// horizon: per slice of directions through the eye, the highest horizon on
// each side, integrated in closed form against the cosine (ground-truth
// AO, Jimenez et al. 2016). baked: not from the screen; rays cast from
// every vertex at load time (baked_ao.hpp), `samples` rays each.
enum class AoMethod { none, crytek, hemisphere, horizon, baked };
RASTERLAB_NAMED_ENUM(AoMethod, kAoMethods, {AoMethod::none, "none"}, {AoMethod::crytek, "crytek"},
                     {AoMethod::hemisphere, "hemisphere"}, {AoMethod::horizon, "horizon"},
                     {AoMethod::baked, "baked"});
// The methods that read the screen (the G-buffer) alone.
inline constexpr std::array<AoMethod, 3> kScreenSpaceAoMethods = {
    AoMethod::crytek, AoMethod::hemisphere, AoMethod::horizon};

inline constexpr int kMaxAoSamples = 1024;
inline constexpr int kMaxBlurRadius = 8;

struct AoOptions {
    AoMethod method = AoMethod::horizon;
    // Depth-buffer reads a pixel: ball or half-ball points for crytek and
    // hemisphere; slices x 2 sides x steps for horizon (horizon_steps()).
    int samples = 16;
    float radius = 0.5f;  // world units: what lies farther does not occlude
    int blur = 2;        // the blur's half width in pixels (0: none); 2 covers the noise's 4x4 tile
    bool rotate = true;  // false: the same kernel at every pixel (bands)
};

// Throws std::invalid_argument naming the option outside its range.
void check(const AoOptions& options);

// Per pixel, 0 (closed) to 1 (open); 1 where no model is. Throws
// std::invalid_argument for the baked method, which needs the models.
rl::FloatImage ambient_occlusion(const GBuffer& g, const Screen& screen, const AoOptions& options);

// What every method reads, found once per frame from the depth buffer:
// each pixel's view depth and world point (NaN where no model is).
struct Surfaces {
    const GBuffer& g;
    const Screen& screen;
    rl::FloatImage depth;
    rl::Grid<rl::vec3> position;
    Surfaces(const GBuffer& g, const Screen& screen);
    bool inside(float x, float y) const {
        return x >= 0 && y >= 0 && x < static_cast<float>(g.width()) &&
               y < static_cast<float>(g.height());
    }
    // The surface seen at window point (x, y), inside the screen: where the
    // ray through it meets the plane of the pixel it falls in (that pixel's
    // point and normal). The pixel's centre alone is up to half a pixel off
    // the ray, which on a slanted floor is far enough in depth to hide the
    // floor from itself. NaN where no model is; the pixel's point where its
    // plane is nearly edge-on to the ray.
    rl::vec3 surface_at(float x, float y) const;
};

// The unblurred methods, and the blur: a pixel averages its neighbours
// within `radius` pixels that lie on its own surface (within a tenth of the
// AO radius of its tangent plane, their normals within 25 degrees of its own).
rl::FloatImage raw_occlusion(const Surfaces& surfaces, const AoOptions& options);
rl::FloatImage surface_blur(const rl::FloatImage& ao, const Surfaces& surfaces, int radius,
                            float ao_radius);

// The horizon method's cosine-weighted share of one slice's arc between the
// horizons h1 <= 0 <= h2 (angles from the eye direction, towards the slice's
// +t side), the normal projected into the slice at angle gamma: the integral
// of cos(theta - gamma) |sin theta| from h1 to h2, in closed form. An open
// slice seen head-on (h = -pi/2, pi/2, gamma = 0) gives 1.
float slice_visibility(float h1, float h2, float gamma);

// How the horizon method spends its samples: slices x 2 sides x steps,
// up to 4 steps a side, then more slices.
struct HorizonSteps {
    int slices, steps;
};
HorizonSteps horizon_steps(int samples);

// The fixed kernels, in the frame of +z (the normal; crytek's fills the
// whole ball): point i of n, nearer the centre for small i.
rl::vec3 ball_point(int i, int n);
rl::vec3 hemisphere_point(int i, int n);
// The 4x4 tile's rotation at pixel (x, y), a turn in [0, 1): each of 16
// values once per tile.
float rotation_at(int x, int y);

}  // namespace occlusion
