// From samples to pixels: each pixel of the picture a weighted mean of
// samples of linear light (averaging sRGB bytes instead darkens every edge:
// docs/11_antialiasing.md#the-resolve).
//
//   const rl::Grid<rl::vec3> light = antialiasing::resolve(frame.colour(), offsets, Resolve::box);
#pragma once

#include <array>
#include <vector>

#include "rasterlab/image.hpp"
#include "rasterlab/named_enum.hpp"
#include "rasterlab/vec.hpp"

namespace antialiasing {

// box: the mean of the pixel's own samples, each weighing the same (what
// GPUs resolve by default; lesson 05's resolve()). tent: every sample
// within one pixel of the pixel's centre, its own and its neighbours',
// weighted by (1 - |dx|)(1 - |dy|): a filter twice as wide, which smooths
// steps further and blurs a little.
enum class Resolve { box, tent };
RASTERLAB_NAMED_ENUM(Resolve, kResolves, {Resolve::box, "box"}, {Resolve::tent, "tent"});

// The picture from an attachment of offsets.size() samples a pixel, stored
// side by side (sample s of pixel (x, y) at (x * samples + s, y)).
rl::Grid<rl::vec3> resolve(const rl::Grid<rl::vec3>& samples, const std::vector<rl::vec2>& offsets,
                           Resolve filter);

// [doc:encoded]
// The resolved light as sRGB bytes: encoded after the resolve, never before
// (the samples' mean must be a mean of light).
rl::Image encoded(const rl::Grid<rl::vec3>& light);
// [/doc:encoded]

}  // namespace antialiasing
