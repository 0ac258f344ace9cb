// The ground truth of lesson 05, computed without the pipeline: for each
// pixel centre, a ray from the eye in double precision, intersected with
// every triangle of the scene. It gives which triangle a pixel shows (the
// frustum-clipped coverage, exactly) and the texture coordinates there (the
// exact perspective-correct value), for the lab and the tests.
//
//   const pipeline::RayCamera rays(camera, 640, 480);
//   const rl::Grid<int> truth = pipeline::exact_ids(scene, rays);
#pragma once

#include <optional>
#include <vector>

#include "05_perspective/pipeline.hpp"

namespace pipeline {

// A triangle in world space, in double, with texture coordinates.
struct WorldTriangle {
    rl::dvec3 p[3];
    rl::dvec2 uv[3];
};

// Pixel centres as rays: the eye, and for pixel (x, y) the direction through
// its centre (x + 0.5, y + 0.5); `depth` is the distance along the viewing
// axis per unit of ray parameter, so a hit at t lies at view depth t.
class RayCamera {
  public:
    RayCamera(const Camera& camera, int width, int height);
    rl::dvec3 eye() const { return eye_; }
    rl::dvec3 direction(double x, double y) const;  // window coordinates; forward component 1
    int width() const { return width_; }
    int height() const { return height_; }
    double near() const { return near_; }
    double far() const { return far_; }

  private:
    rl::dvec3 eye_, forward_, right_, up_;
    double tan_x_, tan_y_, near_, far_;
    int width_, height_;
};

// Where the ray from the eye along `direction` meets the triangle: the ray
// parameter (the view depth) and barycentric weights; empty when it misses.
struct Hit {
    double depth;
    rl::dvec3 weights;
};
std::optional<Hit> intersect(const WorldTriangle& t, rl::dvec3 eye, rl::dvec3 direction);

// Per pixel, the index of the nearest front-facing triangle whose hit lies
// between the near and far planes, or -1.
rl::Grid<int> exact_ids(const std::vector<WorldTriangle>& scene, const RayCamera& rays);

// World triangles as the pipeline's geometry ...
struct WorldCorner {
    const WorldTriangle* triangle;
    int corner;
};
struct WorldScene {
    const std::vector<WorldTriangle>* scene;
    int face_count() const { return static_cast<int>(scene->size()); }
    WorldCorner corner(int face, int k) const {
        return {&(*scene)[static_cast<std::size_t>(face)], k};
    }
};

// ... and the program that draws them into a target of two attachments:
// which triangle each pixel shows, and its texture coordinates there.
struct WorldProgram {
    rl::mat4 view_projection;
    using Varyings = rl::vec2;
    ClipVertex<rl::vec2> vertex(const WorldCorner& c) const {
        const auto k = static_cast<std::size_t>(c.corner);
        return {clip_position(view_projection, rl::cast<float>(c.triangle->p[k])),
                rl::cast<float>(c.triangle->uv[k])};
    }
    std::tuple<int, rl::vec2> fragment(const Fragment<rl::vec2>& f) const {
        return {f.face(), f.varyings};
    }
};
using WorldTarget = RenderTarget<int, rl::vec2>;  // ids (-1: none), uv (NaN: none)
WorldTarget world_target(int width, int height);

// The scene drawn through the pipeline with the given options, each pixel
// holding the index of the triangle it shows (-1 for none).
rl::Grid<int> pipeline_ids(const std::vector<WorldTriangle>& scene, const Camera& camera, int width,
                           int height, const PipelineOptions& options,
                           PipelineCounts* counts = nullptr);

// Pixels whose triangle differs between two ID grids, and how many pixels
// either shows a triangle in.
struct IdDifference {
    long wrong = 0, covered = 0;
};
IdDifference compare_ids(const rl::Grid<int>& truth, const rl::Grid<int>& ids);

// Random triangles around the eye (half of them within reach of the near
// plane or behind it), facing it, for the clipping tests and the lab.
std::vector<WorldTriangle> triangles_around(const Camera& camera, int count, unsigned seed,
                                            double extent);

}  // namespace pipeline
