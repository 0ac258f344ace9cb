// The command-line options every lesson program from 05 on shares, spelled
// once: --model (repeatable), --eye, --target, --up, --fov, --near, --far
// and --light, filling a ViewOptions (view_options.hpp). Only the programs
// link this (and CLI11); the lessons' libraries do not.
//
//   pipeline::ViewOptions view;
//   pipeline::add_view_options(app, view, "floor, crate and globe from obj/");
//   return app.run(argc, argv, "05_perspective", [&] {  // once the options are parsed
//       const pipeline::Camera camera = pipeline::resolve_camera(view, box, aspect);
//       return 0;
//   });
#pragma once

#include <string>

#include "rasterlab/cli.hpp"
#include "view_options.hpp"

namespace pipeline {

// `default_scene` says in --help what runs without --model.
void add_view_options(rl::CommandLine& app, ViewOptions& view, const std::string& default_scene);

}  // namespace pipeline
