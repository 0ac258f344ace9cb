// Lesson 07's keywords (those of its command line, mapped_cli.hpp), read
// once for every function that renders its scene: lesson07.render and
// lesson12.render.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "07_normal_mapping/scene.hpp"
#include "scene_args.hpp"

namespace py_rl {

normal_mapping::MappedView mapped_view(py::handle models, const std::optional<Camera>& camera,
                                       const std::vector<double>& light,
                                       const std::string& normal_map, const std::string& tangents,
                                       const std::string& specular, const std::string& filter,
                                       bool naive, bool one_light);

}  // namespace py_rl
