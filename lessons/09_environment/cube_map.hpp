// A cube map: the environment on the six faces of a cube around the eye,
// each face a square float image (with its mip levels, lesson 04's). A
// direction picks the face its largest component points into, and the two
// others, divided by that one, give the place on the face. Derivation and
// pictures: docs/09_environment.md#cube-maps.
//
//   const environment::CubeMap cube = environment::cube_map(environment::Analytic::sky, 128);
//   const rl::vec3 light = cube.sample({0.3f, 0.9f, -0.2f}, environment::MapFilter::seamless);
#pragma once

#include <array>
#include <functional>

#include "04_textures/sampling.hpp"
#include "map_filter.hpp"
#include "rasterlab/image_io.hpp"
#include "sky.hpp"

namespace environment {

// The faces in OpenGL's order: +x, -x, +y, -y, +z, -z.
enum class Face { px, nx, py, ny, pz, nz };
RASTERLAB_NAMED_ENUM(Face, kFaces, {Face::px, "+x"}, {Face::nx, "-x"}, {Face::py, "+y"},
                     {Face::ny, "-y"}, {Face::pz, "+z"}, {Face::nz, "-z"});

// A place on a face: (u, v) in [0, 1]², v up, each face as seen from
// inside the cube (a face's image reads the right way round).
struct FacePoint {
    Face face;
    double u, v;
};

// The face a direction points into and where on it. The face is the axis of
// the largest |component|; a direction on an edge or a corner (two or three
// equal) goes to x before y before z, so that every direction has exactly one
// face, and the point it gets lies on the edge of that face, where the
// neighbouring face's point would lie on its own edge: the same place.
// Zero or non-finite directions give the centre of +x.
FacePoint face_point(rl::dvec3 direction);

// The direction through (u, v) of a face (not unit: the point on the cube of
// side 2). (u, v) may lie outside [0, 1]: the face's plane goes on.
rl::dvec3 face_direction(Face face, double u, double v);

class CubeMap {
  public:
    // Six square faces of one size (checked), indexed by Face.
    explicit CubeMap(std::array<rl::HdrImage, 6> faces);
    int size() const { return size_; }
    const textures::HdrMipChain& face(Face f) const { return faces_[static_cast<std::size_t>(f)]; }
    int levels() const { return faces_[0].levels(); }

    // The radiance from `direction` by `filter`, at mip level `level` (used
    // by MapFilter::trilinear only; 0 is the full size).
    rl::vec3 sample(rl::vec3 direction, MapFilter filter, float level = 0) const;

  private:
    rl::vec3 nearest(Face f, int level, double u, double v) const;
    rl::vec3 per_face(Face f, int level, double u, double v) const;
    rl::vec3 seamless(Face f, int level, double u, double v) const;
    int size_;  // (before faces_: it is checked from the images before they move in)
    std::array<textures::HdrMipChain, 6> faces_;
};

// A function's cube map: each texel the mean of `samples`² radiances spread
// evenly over it (more than one: the sun's disc covers part of a texel).
// Rows are filled on all cores, so `radiance` is called from several
// threads at once.
CubeMap cube_map(const std::function<rl::dvec3(rl::dvec3)>& radiance, int size, int samples = 4);
CubeMap cube_map(Analytic which, int size, int samples = 4);

}  // namespace environment
