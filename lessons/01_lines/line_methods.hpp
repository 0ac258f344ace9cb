// The four line-drawing methods of lesson 01, each a function template that
// reports pixels through a callback `plot(x, y, coverage)` (coverage is 1 for
// the aliased methods). Endpoints are window coordinates: pixel (i, j) covers
// [i, i+1) x [j, j+1) and has its centre at (i + 0.5, j + 0.5).
// These functions do not clip: call them through draw_line() (draw_line.hpp),
// which clips to the image first. The derivations are in docs/01_lines.md.
//
//   lines::line_bresenham(a, b, [&](int x, int y, float) { image.at(x, y) = colour; });
#pragma once

#include "rasterlab/named_enum.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

#include "rasterlab/vec.hpp"

namespace lines {

enum class LineMethod { parametric, dda, bresenham, wu };

RASTERLAB_NAMED_ENUM(LineMethod, kLineMethods, {LineMethod::parametric, "parametric"},
                     {LineMethod::dda, "dda"}, {LineMethod::bresenham, "bresenham"},
                     {LineMethod::wu, "wu"});

// The pixel that contains a point.
inline int pixel_of(float coordinate) {
    return static_cast<int>(std::floor(coordinate));
}

// The naive method: walk t from 0 to 1 in fixed steps of 1/100 and plot the
// pixel under each point. Too few steps leave gaps on long lines, too many
// plot the same pixel again and again on short ones.
// [doc:line-parametric]
template <class Plot>
void line_parametric(rl::vec2 a, rl::vec2 b, Plot&& plot) {
    for (int step = 0; step < 100; ++step) {
        const float t = static_cast<float>(step) / 100.0f;
        const rl::vec2 p = a + (b - a) * t;
        plot(pixel_of(p.x), pixel_of(p.y), 1.0f);
    }
}
// [/doc:line-parametric]

// Digital differential analyser: one step per pixel along the major axis,
// adding a float increment to the other coordinate each time.
// [doc:line-dda]
template <class Plot>
void line_dda(rl::vec2 a, rl::vec2 b, Plot&& plot) {
    const rl::vec2 d = b - a;
    const int steps = static_cast<int>(std::ceil(std::max(std::abs(d.x), std::abs(d.y))));
    if (steps == 0) {
        plot(pixel_of(a.x), pixel_of(a.y), 1.0f);
        return;
    }
    const rl::vec2 increment = d / static_cast<float>(steps);
    rl::vec2 p = a;
    for (int i = 0; i <= steps; ++i, p += increment) plot(pixel_of(p.x), pixel_of(p.y), 1.0f);
}
// [/doc:line-dda]

// Bresenham's algorithm between the centres of the endpoints' pixels, in
// integers only: `error` tracks, scaled by 2*dx*dy, how far the plotted
// pixel is from the ideal line, and decides each step whether to move in x,
// in y or in both. One form serves all eight octants.
// [doc:line-bresenham]
template <class Plot>
void line_bresenham(int x0, int y0, int x1, int y1, Plot&& plot) {
    const int dx = std::abs(x1 - x0), step_x = x0 < x1 ? 1 : -1;
    const int dy = -std::abs(y1 - y0), step_y = y0 < y1 ? 1 : -1;
    int error = dx + dy;
    while (true) {
        plot(x0, y0, 1.0f);
        if (x0 == x1 && y0 == y1) break;
        const int twice = 2 * error;
        if (twice >= dy) {  // the step in x keeps us closer to the line
            error += dy;
            x0 += step_x;
        }
        if (twice <= dx) {  // so does the step in y
            error += dx;
            y0 += step_y;
        }
    }
}
// [/doc:line-bresenham]

template <class Plot>
void line_bresenham(rl::vec2 a, rl::vec2 b, Plot&& plot) {
    line_bresenham(pixel_of(a.x), pixel_of(a.y), pixel_of(b.x), pixel_of(b.y), plot);
}

// Xiaolin Wu's anti-aliased line: along the major axis, the line's centre
// falls between two pixel centres of the minor axis; each gets the share of
// ink that its distance says. The end pixels are weighted by how much of
// them the segment covers along the major axis.
// [doc:line-wu]
template <class Plot>
void line_wu(rl::vec2 a, rl::vec2 b, Plot&& plot) {
    // Work in coordinates where pixel centres are integers.
    float x0 = a.x - 0.5f, y0 = a.y - 0.5f, x1 = b.x - 0.5f, y1 = b.y - 0.5f;
    const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
    if (steep) std::swap(x0, y0), std::swap(x1, y1);
    if (x0 > x1) std::swap(x0, x1), std::swap(y0, y1);
    auto put = [&](int major, int minor, float coverage) {
        if (coverage <= 0.0f) return;
        if (steep)
            plot(minor, major, coverage);
        else
            plot(major, minor, coverage);
    };
    const float gradient = x1 > x0 ? (y1 - y0) / (x1 - x0) : 0.0f;
    // Place the two ends on whole pixel columns.
    const float start = std::round(x0), end = std::round(x1);
    float y = y0 + gradient * (start - x0);
    const float start_weight = 1.0f - (x0 + 0.5f - start);  // share of the first column covered
    const float end_weight = x1 + 0.5f - end;
    for (float x = start; x <= end; x += 1.0f, y += gradient) {
        float weight = 1.0f;
        if (x == start)
            weight = start == end ? x1 - x0 : start_weight;
        else if (x == end)
            weight = end_weight;
        const float below = std::floor(y), fraction = y - below;
        put(static_cast<int>(x), static_cast<int>(below), (1.0f - fraction) * weight);
        put(static_cast<int>(x), static_cast<int>(below) + 1, fraction * weight);
    }
}
// [/doc:line-wu]

// Runs the chosen method (no clipping).
template <class Plot>
void rasterize_line(LineMethod method, rl::vec2 a, rl::vec2 b, Plot&& plot) {
    switch (method) {
        case LineMethod::parametric:
            line_parametric(a, b, plot);
            break;
        case LineMethod::dda:
            line_dda(a, b, plot);
            break;
        case LineMethod::bresenham:
            line_bresenham(a, b, plot);
            break;
        case LineMethod::wu:
            line_wu(a, b, plot);
            break;
    }
}

}  // namespace lines
