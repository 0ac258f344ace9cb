// How far apart two images are, in the figures the golden tests and the labs
// report. Channels compared: red, green, blue (alpha is ignored).
//
//   const rl::ImageDiff d = rl::compare_images(expected, actual, 8);  // d.psnr, d.share_over ...
//   rl::save_image("where.png", rl::difference_overlay(expected, actual, 8));  // magenta: over 8
//   const rl::Image differences = rl::difference_image(expected, actual);
#pragma once

#include "rasterlab/image.hpp"

namespace rl {

struct ImageDiff {
    int max_abs = 0;        // largest channel difference, 0..255
    double mean_abs = 0;    // mean channel difference
    double rmse = 0;        // root mean square channel difference
    double psnr = 0;        // 20 log10(255 / rmse) in dB; +infinity when identical
    double share_over = 0;  // share of pixels whose largest difference exceeds `threshold`
    int threshold = 0;
};

// Throws std::invalid_argument when the sizes differ.
ImageDiff compare_images(const Image& a, const Image& b, int threshold = 0);

// A picture of the differences: black where equal, brightness proportional to
// the largest channel difference (scaled so the worst is white), and red
// where the difference exceeds `threshold`.
Image difference_image(const Image& a, const Image& b, int threshold = 0);

// `actual` dimmed to a third, with every pixel that differs from `expected`
// by more than `threshold` painted magenta: where a method goes wrong, seen
// on the picture it made (the docs' "where it breaks" figures).
Image difference_overlay(const Image& expected, const Image& actual, int threshold = 0);

// PSNR in dB for a given RMSE on a 0..255 scale.
double psnr_from_rmse(double rmse);

}  // namespace rl
