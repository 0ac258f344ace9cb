// Lesson 07's command line, spelled once for every program that renders its
// scene (07_normal_mapping, 12_fast): lesson 05's view options and the
// shading options (--normal-map, --tangents, --specular, --filter, --naive,
// --one-light), and the scene they ask for, loaded and framed. Only programs
// link this (and CLI11).
//
//   normal_mapping::MappedCli cli;
//   normal_mapping::add_mapped_options(app, cli, "floor, globe and crate from obj/");
//   return app.run(argc, argv, "07_normal_mapping", [&] {  // once the options are parsed
//       const normal_mapping::MappedScene scene = normal_mapping::load_scene(cli, 800, 600, "07");
//       return 0;
//   });
#pragma once

#include <string>
#include <vector>

#include "05_perspective/view_cli.hpp"
#include "scene.hpp"

namespace normal_mapping {

using MappedCli = MappedView;  // (scene.hpp)

void add_mapped_options(rl::CommandLine& app, MappedCli& cli, const std::string& default_scene);

using MappedScene = pipeline::ViewedScene<MappedModel>;

// normal_mapping::load_scene(), its warnings printed under `program`'s name.
MappedScene load_scene(MappedCli& cli, int width, int height, const char* program);

}  // namespace normal_mapping
