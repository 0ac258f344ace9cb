// The arguments every lesson's render function shares: the models (paths or
// Mesh objects from load_mesh), the Camera, the light, the image size. They
// become what the programs' command lines fill: a model path, or lesson 05's
// ViewOptions.
//
//   const pipeline::ViewOptions view = py_rl::view_options(models, camera, light);
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "05_perspective/view_options.hpp"
#include "made_by_init.hpp"
#include "rasterlab/mesh.hpp"

namespace py_rl {

namespace py = pybind11;

// rasterlab.Mesh: an OBJ as load_mesh() read it, for inspection; a render
// given one loads its file again the way that lesson's program does (with
// the textures and encodings the lesson uses), so pictures match the
// programs' byte for byte.
struct Mesh {
    rl::Mesh mesh;
    std::vector<std::string> warnings;
};

// rasterlab.Camera: lesson 05's camera options; what is None is framed to
// fit the scene, as the programs do without --eye, --target, --near, --far.
struct Camera {
    std::vector<float> eye, target, up{0, 1, 0};
    float fov = 50;
    std::optional<float> near, far;
};

// A model given as a path (str or os.PathLike) or a Mesh; `keyword` names
// the argument in a refusal (a path with a NUL in it).
std::string model_path(py::handle model, const char* keyword = "model");

// Lesson 09's environment argument (and lesson 10's when not None): the
// name of an analytic one or the path of a lat-long .hdr file, as a str or
// an os.PathLike; anything else is a TypeError naming the argument.
std::string environment_source(py::handle environment);

// None (the lesson's default scene), one model or a sequence of them (at most
// pipeline::kMaxModels, as --model).
std::vector<std::string> model_paths(py::handle models);

// The view lesson 05's options would give: models, camera (None: framed) and
// --light (three numbers).
pipeline::ViewOptions view_options(py::handle models, const std::optional<Camera>& camera,
                                   const std::vector<double>& light);

// The programs' --light default (ViewOptions'), as a keyword's default.
std::vector<double> default_light();

// --width and --height: 1 to 16384.
void check_size(int width, int height);

// Registers rasterlab.Mesh, rasterlab.load_mesh and rasterlab.Camera.
void bind_scene_args(py::module_& m);

}  // namespace py_rl

RASTERLAB_REFUSE_USE_BEFORE_INIT(Mesh, "Mesh")
RASTERLAB_REFUSE_USE_BEFORE_INIT(Camera, "Camera")
