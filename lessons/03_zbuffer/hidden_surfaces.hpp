// Three ways to show only the nearest surface: the painter's algorithm, a
// BSP tree, and the z-buffer. Each draws a scene into a colour image and an
// ID buffer (which face won each pixel, -1 for none), so the lab can compare
// them pixel by pixel. Derivations: docs/03_zbuffer.md.
//
//   const std::vector<zbuffer::SceneTriangle> scene =
//       zbuffer::build_scene(zbuffer::default_placements(), 800, 800);
//   zbuffer::Frame frame(800, 800);
//   zbuffer::render(zbuffer::HsrMethod::bsp, scene, frame);
#pragma once

#include "rasterlab/named_enum.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>

#include "depth_test.hpp"
#include "scene.hpp"

namespace zbuffer {

enum class HsrMethod { painter, bsp, zbuffer };
RASTERLAB_NAMED_ENUM(HsrMethod, kHsrMethods, {HsrMethod::painter, "painter"},
                     {HsrMethod::bsp, "bsp"}, {HsrMethod::zbuffer, "zbuffer"});

struct Frame {
    rl::Image colour;
    rl::Grid<int> ids;
    rl::FloatImage depth;     // window depth, 1 (the far plane) where nothing was drawn
    std::size_t refused = 0;  // triangles the rasterizer refused (see triangles::rasterize)
    Frame(int width, int height, rl::Rgba background = rl::kBackground)
        : colour(width, height, background), ids(width, height, -1), depth(width, height, 1.0f) {}
};

// Draws every triangle in the given order with no depth test: the last one wins.
void draw_in_order(const std::vector<SceneTriangle>& scene, Frame& frame);

// The painter's order: by each triangle's mean depth, farthest first (a
// stable sort: equal means keep their given order).
void sort_far_to_near(std::vector<SceneTriangle>& scene);

// The painter's algorithm: sort_far_to_near, then draw in order.
void draw_painter(std::vector<SceneTriangle> scene, Frame& frame);

// The z-buffer: keep, per pixel, the depth of the nearest surface drawn so
// far and draw a fragment only if it is nearer (depth test `less`).
void draw_zbuffer(const std::vector<SceneTriangle>& scene, Frame& frame);

// A binary space partitioning tree: each node holds a plane (from one of its
// triangles), the triangles lying in it, and the subtrees in front of and
// behind it; triangles crossing a plane are split in two or three.
struct BspNode {
    rl::dvec3 normal;
    double offset;  // the plane is dot(normal, p) + offset = 0
    std::vector<SceneTriangle> coplanar;
    std::unique_ptr<BspNode> front, back;
};

struct BspTree {
    std::unique_ptr<BspNode> root;
    std::size_t triangles = 0;  // after splitting
    std::size_t nodes = 0;
    int depth = 0;
    std::size_t pieces = 0, max_pieces = 0;  // scene made so far, and the cap
};

// Splitting can multiply the triangles without limit: 3000 random triangles
// once took 59 s and 9.6 GB. The build refuses (throws BspTooLarge) once the
// pieces exceed 16 per input triangle plus 131072 (the lab's soup of 200
// triangles makes 68 738), or the tree grows deeper
// than kMaxBspDepth (its recursion must fit the stack).
inline constexpr std::size_t kBspPiecesPerTriangle = 16;
inline constexpr std::size_t kBspExtraPieces = 131072;
inline constexpr int kMaxBspDepth = 2000;
std::size_t max_bsp_pieces(std::size_t input_triangles);

class BspTooLarge : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Builds the tree; the splitting plane of each node is the first remaining
// triangle's, after a fixed shuffle (keeps the tree shallow on meshes).
BspTree build_bsp(std::vector<SceneTriangle> scene);

// Draws back to front for a viewer looking along +depth: at each node, the
// side away from the viewer first, then the node, then the near side.
void draw_bsp(const BspTree& tree, Frame& frame);

// Renders the scene with one method (building the BSP tree if needed).
void render(HsrMethod method, const std::vector<SceneTriangle>& scene, Frame& frame);

}  // namespace zbuffer
