// Lesson 07's command line, spelled once for every program that renders its
// scene (07_normal_mapping, 12_fast): lesson 05's view options and the
// shading options (--normal-map, --tangents, --specular, --filter, --naive,
// --one-light), and the scene they ask for, loaded and framed. Only programs
// link this (and CLI11).
//
//   normal_mapping::MappedCli cli;
//   normal_mapping::add_mapped_options(app, cli, "floor, globe and crate from obj/");
//   CLI11_PARSE(app, argc, argv);
//   const normal_mapping::MappedScene scene = normal_mapping::load_scene(cli, 800, 600, "07");
#pragma once

#include <string>
#include <vector>

#include "05_perspective/view_cli.hpp"
#include "scene.hpp"

namespace normal_mapping {

struct MappedCli {
    perspective::ViewOptions view;
    RenderOptions options;
    TangentMethod tangents = TangentMethod::split;
    bool naive = false, one_light = false;
};

void add_mapped_options(CLI::App& app, MappedCli& cli, const std::string& default_scene);

struct MappedScene {
    std::vector<MappedModel> models;
    perspective::Camera camera;
};

// Sets the lighting and the output the options ask for, loads the default
// scene (or the --model files, as stored), prints the loaders' warnings under
// `program`'s name, and frames the camera for a width x height image. Throws
// std::invalid_argument (naming the option) for a camera it cannot use.
MappedScene load_scene(MappedCli& cli, int width, int height, const char* program);

}  // namespace normal_mapping
