// The picture lesson 00 draws: every pixel set by hand, designed so that a
// wrong origin, swapped colour bytes or a broken RLE run are visible at once.
#pragma once

#include "rasterlab/image.hpp"

namespace lesson00 {

// A width x height test card:
//  - background: red grows to the right, green grows upwards, so the
//    bottom-left corner is dark and the top-right one yellow;
//  - a white square at the origin (pixel (0, 0), bottom-left) and pure red,
//    green and blue squares in the other corners, so that a flipped image or a
//    red/blue swap (TGA stores blue first) cannot go unnoticed;
//  - a band of flat colour across the middle, where RLE compresses well, and
//    a one-pixel checkerboard under it, where it cannot.
rl::Image make_test_card(int width, int height);

}  // namespace lesson00
