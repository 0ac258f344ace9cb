// Scoring rasterizers against the exact coverage rule: the lab's and the
// stability tests' yardstick, computed independently of the methods.
//
//   const auto batch = triangles::random_triangles(1000, 100.0, 1024, 1);
//   const triangles::CoverageScore s =
//       triangles::score_coverage(triangles::RasterMethod::bbox, batch, 1024, 1024);
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "02_triangles/fans.hpp"  // disc_fan, on_subpixel_grid
#include "02_triangles/raster.hpp"
#include "rasterlab/image.hpp"

namespace triangles {

// Is pixel (x, y) covered by t under the exact rule? Its centre must be
// inside; a centre exactly on an edge counts as inside when moving it by an
// infinitesimal (+e, -e^2) — right, then a hair down — takes it inside, which
// is the top-left rule stated without edge classes. Exact: vertices are
// snapped to the 1/256 grid and everything else is 128-bit integer arithmetic.
bool reference_covers(const ScreenTriangle& t, int x, int y);

// Every pixel the method covers for t, in row order (clamped to the image).
std::vector<std::pair<int, int>> covered_pixels(RasterMethod method, const ScreenTriangle& t,
                                                int width, int height);

struct CoverageScore {
    long triangles = 0;
    long reference_pixels = 0;  // pixels the exact rule covers
    long wrongly_set = 0;       // covered by the method, not by the rule
    long missed = 0;            // covered by the rule, not by the method
    long wrong() const { return wrongly_set + missed; }
    double wrong_per_million() const {
        return reference_pixels ? 1e6 * static_cast<double>(wrong()) / reference_pixels : 0.0;
    }
};

// Compares each triangle's pixels, one triangle at a time.
CoverageScore score_coverage(RasterMethod method, const std::vector<ScreenTriangle>& batch,
                             int width, int height);

struct WatertightScore {
    long pixels = 0;          // pixels inside the mesh (by the exact rule)
    long double_covered = 0;  // pixels the method covers twice or more
    long holes = 0;           // pixels inside the mesh the method misses
};

// Draws all triangles of a mesh whose triangles share edges and counts how
// often the method covers each pixel: it should be once inside, never twice.
WatertightScore score_watertight(RasterMethod method, const std::vector<ScreenTriangle>& mesh,
                                 int width, int height);

// `count` triangles of about `area` square pixels inside a size x size image,
// vertices on the 1/256-pixel grid, windings mixed, no angle under 15 degrees.
std::vector<ScreenTriangle> random_triangles(int count, double area, int size, std::uint64_t seed);

// Small triangles whose vertices lie on pixel centres and corners, so that
// many centres fall exactly on edges: the tie rule's test.
std::vector<ScreenTriangle> tie_triangles(int count, int size, std::uint64_t seed);

// A grid of `cells` x `cells` quads, each split in two, over [margin, size -
// margin]^2, inner vertices moved by multiples of half a pixel.
std::vector<ScreenTriangle> jittered_grid(int cells, int size, float margin, std::uint64_t seed);

}  // namespace triangles
