// The scene of lesson 03: triangles already in window coordinates (x, y in
// pixels, z = window depth in [0, 1], 0 nearest), each with the colour flat
// shading gives it and the index that identifies it in an ID buffer.
//
//   const auto scene = zbuffer::build_scene({{rl::project_model("rock")}}, 800, 800);
#pragma once

#include <string>
#include <vector>

#include "02_triangles/raster.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/mesh.hpp"
#include "rasterlab/transform.hpp"

namespace zbuffer {

struct SceneTriangle {
    rl::vec3 v[3];  // window x, y; depth z
    rl::Rgba colour;
    int id;  // the face it came from (pieces of a split face share it)
};

// A model placed in the scene: rotated, scaled, then moved.
struct Placement {
    std::filesystem::path model;
    rl::mat3 rotation = rl::mat3::identity();
    float scale = 1.0f;
    rl::vec3 offset{};
};

// Lesson 01's orthographic view with a depth: x, y in [-1, 1] fill the
// image, and as the viewer looks down -z the window depth is (1 - z) / 2, so
// z = 1 is nearest (depth 0) and z = -1 farthest (depth 1).
inline rl::vec3 orthographic_to_window(rl::vec3 p, int width, int height) {
    return rl::ndc_to_window({p.x, p.y, -p.z}, width, height);
}

// Loads and places the models, puts each face in the window
// (orthographic_to_window), culls back faces as lesson 02 does (added to
// `culled`).
// Each face is shaded flat (lesson 02's Lambert) and numbered in order.
std::vector<SceneTriangle> build_scene(const std::vector<Placement>& placements, int width,
                                       int height, std::vector<std::string>* warnings = nullptr,
                                       std::size_t* culled = nullptr);

// The lesson's default: the rock with a tilted torus passing through it.
std::vector<Placement> default_placements();

inline triangles::ScreenTriangle screen(const SceneTriangle& t) {
    return {{t.v[0].xy(), t.v[1].xy(), t.v[2].xy()}};
}

}  // namespace zbuffer
