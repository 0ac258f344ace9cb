#include "mapped_cli.hpp"

#include "rasterlab/main_guard.hpp"

namespace normal_mapping {

void add_mapped_options(rl::CommandLine& app, MappedCli& cli, const std::string& default_scene) {
    pipeline::add_view_options(app, cli.view, default_scene);
    rl::add_method_option(app, "--normal-map", cli.options.normal_map, kNormalMaps,
                          "Normal map to use");
    rl::add_method_option(app, "--tangents", cli.tangents, kTangentMethods, "Tangent frames");
    rl::add_method_option(
        app, "--specular", cli.options.specular, shading::kSpeculars,
        "The highlight, Phong's or Blinn's (lesson 06; lit per pixel either way)");
    rl::add_method_option(app, "--filter", cli.options.filter, textures::kFilters,
                          "Texture filter, for every map (lesson 04)");
    app.add_flag("--naive", cli.naive,
                 "Light the sRGB bytes as if they were linear and write the result as it is "
                 "(what lessons 00-05 did)");
    app.add_flag("--one-light", cli.one_light, "Only the --light, without the dim fill light");
}

MappedScene load_scene(MappedCli& cli, int width, int height, const char* program) {
    std::vector<std::string> warnings;
    MappedScene scene = load_scene(cli, width, height, warnings);
    rl::print_warnings(program, warnings);
    return scene;
}

}  // namespace normal_mapping
