// Lesson 06: shading. Normals, the normal matrix, flat, Gouraud, Phong and
// Blinn-Phong shading as shaders, in linear light. Read docs/06_shading.md
// beside it.
#include <cstdio>

#include "05_perspective/view_cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "scene.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 06, shading: models lit by flat, Gouraud, Phong or Blinn-Phong shading, in "
        "linear light, through lesson 05's camera."};
    rl::ImageOptions image_options{"06_shading.tga"};
    pipeline::ViewOptions view;
    shading::ShadingOptions options;
    shading::Weighting weighting = shading::Weighting::angle;
    bool naive = false, one_light = false;
    float shininess = options.lighting.shininess;
    pipeline::add_view_options(app, view, "floor, globe and torus from obj/");
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--shading", options.model, shading::kShadingModels,
                          "Shading model");
    rl::add_method_option(app, "--weighting", weighting, shading::kWeightings,
                          "Vertex normals, where the OBJ has none, averaged by");
    app.add_option("--shininess", shininess, "Specular exponent (0: highlight everywhere lit)")
        ->check(rl::finite_number(0, 1e6))
        ->capture_default_str();
    app.add_flag("--naive", naive,
                 "Light the sRGB bytes as if they were linear and write the result as it is "
                 "(what lessons 00-05 did)");
    app.add_flag("--one-light", one_light, "Only the --light, without the dim fill light");
    return app.run(argc, argv, "06_shading", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        rl::check_image_output(output);
        options.output = naive ? shading::Output::naive : shading::Output::srgb;
        options.lighting = shading::default_lighting(pipeline::light_direction(view));
        if (one_light) options.lighting.lights.resize(1);
        options.lighting.shininess = shininess;
        std::vector<std::string> warnings;
        const auto [models, camera] =
            shading::load_scene(view, options.output, weighting, width, height, warnings);
        rl::print_warnings("06_shading", warnings);
        std::size_t computed = 0;
        for (const shading::LitModel& m : models) computed += m.computed_normals;
        pipeline::ColourTarget frame = pipeline::colour_target(width, height);
        const pipeline::PipelineCounts counts = shading::render(models, camera, options, frame);
        rl::save_image(output, frame.colour());
        std::printf(
            "%zu models: %zu faces, %zu back faces, %zu clipped, %zu fragments shaded; %s "
            "shading, %s output, %zu corner normals computed (%s-weighted); into %s\n",
            models.size(), counts.faces, counts.culled, counts.clipped, counts.shaded,
            shading::name(options.model), shading::name(options.output), computed,
            shading::name(weighting), output.c_str());
        return 0;
    });
}
