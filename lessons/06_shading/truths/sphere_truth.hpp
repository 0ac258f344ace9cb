// The lab's ground truth for shading: a sphere lit analytically. At every
// pixel centre a ray from the eye meets the exact sphere in double; its
// exact normal and the same lights give the colour the shading models try
// to reach with a triangle mesh. Also the meshes they draw: UV spheres of
// any tessellation, with exact normals at the vertices.
//
//   const rl::Mesh mesh = shading::uv_sphere(64);
//   const rl::Image truth = shading::sphere_truth(camera, 256, 256, lighting, albedo,
//                                                 shading::Specular::blinn_phong, rl::kBackground);
#pragma once

#include "05_perspective/camera.hpp"
#include "06_shading/colour.hpp"
#include "06_shading/lighting.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/mesh.hpp"

namespace shading {

// A unit sphere at the origin: `segments` around, segments / 2 from pole to
// pole, each vertex's normal its exact position; positions are shared across
// the texture seam and at the poles, as in an OBJ file.
rl::Mesh uv_sphere(int segments);

// Mean and largest angle (degrees) between averaged vertex normals and the
// exact ones of the unit sphere.
struct NormalError {
    double mean = 0, max = 0;
};
NormalError sphere_normal_error(const rl::Mesh& sphere, const std::vector<rl::vec3>& normals);

// The unit sphere at the origin as the camera sees it, lit by `lighting`
// (converted to double) with the same specular model; background elsewhere.
// `output` encodes as the program would: sRGB, or (naive) the light as bytes.
rl::Image sphere_truth(const pipeline::Camera& camera, int width, int height,
                       const Lighting<float>& lighting, rl::vec3 albedo, Specular specular,
                       rl::Rgba background);

// RMSE (0..255) over the pixels where `a` or `b` differs from the
// background: over the sphere and its silhouette in either image.
struct SphereError {
    double rmse = 0;           // over the union of both spheres
    double interior_rmse = 0;  // over pixels both images cover
    long pixels = 0, interior = 0;
};
SphereError compare_spheres(const rl::Image& truth, const rl::Image& image, rl::Rgba background);

}  // namespace shading
