// A post-process edge filter in the manner of FXAA (Lottes, 2009): after a
// frame of one sample a pixel, find the pixels where brightness steps
// sharply, work out which way the edge runs and how far the pixel lies from
// the ends of its step, and blend the pixel with its neighbour across the
// edge by as much as a smooth edge would cover it. It sees only the
// picture: a detail thinner than a pixel that the sampling missed stays
// missing, and a fine pattern that is not an edge (text, a thin stripe) is
// blurred like one. Derivation and pictures: docs/11_antialiasing.md.
//
//   const rl::Grid<rl::vec3> smoothed = antialiasing::edge_filter(frame.light);
#pragma once

#include "rasterlab/image.hpp"
#include "rasterlab/vec.hpp"

namespace antialiasing {

struct EdgeFilterOptions {
    // A pixel is filtered when the brightness range of it and its four
    // neighbours exceeds both: a share of the brightest, and a floor (in
    // perceptual luma, 0 to 1) that keeps noise in the dark unfiltered.
    float relative_threshold = 0.125f;
    float absolute_threshold = 0.0312f;
    // How far the blend may go for a lone bright or dark pixel (subpixel
    // aliasing, 0: never), and how many steps the search along an edge
    // takes each way (each step longer than the last).
    float subpixel = 0.75f;
    int search_steps = 12;
};

// The picture filtered; `light` is linear, and so is the result (the
// brightness the filter compares is the sRGB-encoded luma, as the eye sees).
rl::Grid<rl::vec3> edge_filter(const rl::Grid<rl::vec3>& light,
                               const EdgeFilterOptions& options = {});

}  // namespace antialiasing
