// The picture lesson 00 draws: every pixel set by hand, designed so that a
// wrong origin, swapped colour bytes or a broken RLE run are visible at once.
//
//   const rl::Image card = lesson00::make_test_card(640, 480);
//   const rl::Image wrong = lesson00::misread(card, lesson00::Misreading::origin);
#pragma once

#include "rasterlab/named_enum.hpp"

#include <array>

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

// The two classic mistakes of a first TGA decoder, for the page's "where it
// breaks" pictures: byte_order reads TGA's blue-green-red pixels as
// red-green-blue (red and blue swap); origin ignores the header's origin bit
// and takes the file's first row for the top one (the picture turns upside
// down, since our files start at the bottom).
enum class Misreading { none, byte_order, origin };
RASTERLAB_NAMED_ENUM(Misreading, kMisreadings, {Misreading::none, "none"},
                     {Misreading::byte_order, "byte-order"}, {Misreading::origin, "origin"});

// What such a decoder shows for an image written correctly.
rl::Image misread(const rl::Image& image, Misreading mistake);

}  // namespace lesson00
