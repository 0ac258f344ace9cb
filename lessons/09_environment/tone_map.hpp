// From light to bytes: a frame of linear HDR values (any size, the sun
// thousands of times the sky) scaled by the exposure, squeezed into 0..1 by
// a tone map, then encoded to sRGB bytes by lesson 06. Derivation and
// pictures: docs/09_environment.md#hdr-and-tone-mapping.
//
//   environment::LightTarget hdr = environment::light_target(800, 600);  // scene.hpp
//   const rl::Image picture = environment::tone_mapped(hdr.colour(), {environment::ToneMap::aces,
//   0});
#pragma once

#include <array>

#include "06_shading/colour.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/named_enum.hpp"

namespace environment {

// clamp: values above 1 cut to 1 (a bright sky goes flat white);
// reinhard: c / (1 + c), never reaching 1; aces: the curve fitted to the
// film industry's ACES reference (Narkowicz, 2015), a toe and a shoulder.
enum class ToneMap { clamp, reinhard, aces };
RASTERLAB_NAMED_ENUM(ToneMap, kToneMaps, {ToneMap::clamp, "clamp"}, {ToneMap::reinhard, "reinhard"},
                     {ToneMap::aces, "aces"});

// What the frame keeps between drawing and the tone map: float light (HDR,
// no upper limit), or what a render target of bytes would keep (no HDR):
// the exposed light in 256 even steps from 0 to 1, everything brighter cut
// to 1. Linear bytes are coarse in the dark: their first step above black
// is already 13 of 255 once encoded to sRGB, so dark gradients band.
enum class FrameStore { float_light, bytes };
RASTERLAB_NAMED_ENUM(FrameStore, kFrameStores, {FrameStore::float_light, "float"},
                     {FrameStore::bytes, "bytes"});

struct Exposure {
    ToneMap curve = ToneMap::aces;
    float stops = 0;  // the light is scaled by 2^stops first
    FrameStore store = FrameStore::float_light;
};

// One value through the exposure and the curve: 0..1. NaN, negative or
// infinite light gives 0 (an infinite value is not a colour).
float tone_map(float light, const Exposure& exposure);

// Narkowicz's ACES fit before tone_map clamps it: it passes 1 at light
// 7.24 and tends to 2.51 / 2.43 (light 8 gives 1.003).
float aces_curve(float light);
rl::vec3 tone_map(rl::vec3 light, const Exposure& exposure);

// The frame as sRGB bytes (alpha 255).
rl::Image tone_mapped(const rl::Grid<rl::vec3>& light, const Exposure& exposure);

}  // namespace environment
