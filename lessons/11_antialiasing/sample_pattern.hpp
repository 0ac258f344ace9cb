// Where a pixel's samples lie: each an offset from the pixel's centre, in
// pixels, window y pointing up. A pattern decides which edges a pixel sees
// as steps: the derivation and the pictures are in docs/11_antialiasing.md.
//
//   const std::vector<rl::vec2> four =
//   antialiasing::sample_offsets(antialiasing::Pattern::standard, 4);
#pragma once

#include <array>
#include <vector>

#include "rasterlab/named_enum.hpp"
#include "rasterlab/vec.hpp"

namespace antialiasing {

// grid: an ordered n x n grid (1, 4 or 16 samples): every row of samples
// shares its height, so a nearly horizontal edge still steps n times a
// pixel. rotated: 4 samples of a 2 x 2 grid turned so that no two share a
// row or a column (4 heights and 4 widths for 4 samples). standard:
// Direct3D's standard multisample patterns for 1, 2, 4, 8 and 16 samples,
// which GPUs share; like the rotated grid, each has as many distinct rows
// and columns as samples (its 4 is the rotated grid's mirror image).
enum class Pattern { grid, rotated, standard };
RASTERLAB_NAMED_ENUM(Pattern, kPatterns, {Pattern::grid, "grid"}, {Pattern::rotated, "rotated"},
                     {Pattern::standard, "standard"});

inline constexpr int kMaxSamples = 16;

// The offsets of `samples` samples in `pattern`, each within the pixel
// (|offset| < 0.5 on both axes). Throws std::invalid_argument naming the
// pattern and the counts it has when it has no such count.
std::vector<rl::vec2> sample_offsets(Pattern pattern, int samples);

// Whether `pattern` has a layout of `samples` samples.
bool has_count(Pattern pattern, int samples);

}  // namespace antialiasing
