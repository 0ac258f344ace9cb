// Measuring lines against the ideal segment: what the lab and the stability
// tests use to score the methods. Everything here is computed in double,
// independently of the methods under test.
//
//   lines::LineScore score;
//   for (const lines::Segment& s : lines::random_segments(2000, 1024, 1))
//       lines::score_segment(lines::LineMethod::dda, s, 1024, 1024, score);
#pragma once

#include <cstdint>
#include <vector>

#include "01_lines/line_methods.hpp"

namespace lines {

struct Segment {
    rl::vec2 a, b;
};

// `count` segments inside a size x size image with endpoints on pixel
// centres, lengths spread evenly on a log scale from 2 to 0.9 * size, in all
// directions. The same seed gives the same segments everywhere.
std::vector<Segment> random_segments(int count, int size, std::uint64_t seed);

// The same segments with each endpoint moved off its pixel centre by up to
// half a pixel in x and in y, then scaled by `spread` about the image's
// centre: spread 1 keeps them inside, spread 3 sends most across the image's
// edges, so that draw_line clips them.
std::vector<Segment> moved_segments(std::vector<Segment> segments, int size, double spread,
                                    std::uint64_t seed);

struct PlottedPixel {
    int x, y;
    float coverage;
};

// Every plot call a method makes for the segment, after clipping to a
// width x height image (as draw_line does).
std::vector<PlottedPixel> plotted_pixels(LineMethod method, Segment s, int width, int height);

// Distance from a point to the segment.
double distance_to_segment(rl::dvec2 p, Segment s);

// The exact share of pixel (x, y) that a line one pixel wide covers: the
// rectangle of width 1 centred on the segment, ending flat at its endpoints;
// estimated by 16 x 16 point sampling in double precision.
double exact_coverage(int x, int y, Segment s);

// Figures for one method over many segments.
struct LineScore {
    long segments = 0;
    double length = 0;  // total length of the segments, pixels
    long plot_calls = 0;
    double max_distance = 0;  // largest distance of a lit pixel's centre from the segment
    double sum_distance = 0;  // over all lit pixels
    long lit_pixels = 0;
    long gaps = 0;              // major-axis columns between the endpoints with no pixel
    long duplicates = 0;        // plot calls beyond one per major-axis column
    double coverage_error = 0;  // sum over pixels of |coverage drawn - exact coverage|

    double mean_distance() const { return lit_pixels ? sum_distance / lit_pixels : 0; }
    // Misplaced coverage per pixel of line length: 0 for a perfect
    // anti-aliased line, about 0.3 for a perfect aliased one.
    double coverage_error_per_length() const { return length > 0 ? coverage_error / length : 0; }
};

// Scores the method on the segment's visible part: the part between the
// image's outermost pixel centres, where draw_line clips it (the whole
// segment when it lies inside). Distances are to the true segment, so a
// method that draws a clipped segment between other pixels than the
// unclipped one would shows it.
void score_segment(LineMethod method, Segment s, int width, int height, LineScore& score);

}  // namespace lines
