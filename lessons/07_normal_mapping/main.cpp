// Lesson 07: normal mapping. The full render: any textured OBJ with its
// diffuse, normal and specular maps, perspective, Blinn-Phong (or Phong)
// shading in linear light. Read docs/07_normal_mapping.md beside it.
#include <chrono>
#include <cstdio>

#include "05_perspective/view_cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "scene.hpp"

int main(int argc, char** argv) {
    CLI::App app{
        "Lesson 07, normal mapping: models with their diffuse, normal and specular maps, lit "
        "per pixel in linear light through lesson 05's camera."};
    rl::ImageOptions image_options{"07_normal_mapping.tga"};
    perspective::ViewOptions view;
    normal_mapping::RenderOptions options;
    normal_mapping::TangentMethod tangents = normal_mapping::TangentMethod::split;
    perspective::add_view_options(app, view, "floor, globe and crate from obj/");
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--normal-map", options.normal_map, normal_mapping::kNormalMaps,
                          "Normal map to use");
    rl::add_method_option(app, "--tangents", tangents, normal_mapping::kTangentMethods,
                          "Tangent frames");
    rl::add_method_option(
        app, "--specular", options.specular, shading::kSpeculars,
        "The highlight, Phong's or Blinn's (lesson 06; lit per pixel either way)");
    rl::add_method_option(app, "--filter", options.filter, textures::kFilters,
                          "Texture filter, for every map (lesson 04)");
    bool naive = false, one_light = false;
    app.add_flag("--naive", naive,
                 "Light the sRGB bytes as if they were linear and write the result as it is "
                 "(what lessons 00-05 did)");
    app.add_flag("--one-light", one_light, "Only the --light, without the dim fill light");
    CLI11_PARSE(app, argc, argv);
    const std::string& output = image_options.output;
    const int width = image_options.width, height = image_options.height;

    return rl::guarded_main("07_normal_mapping", [&] {
        rl::check_image_output(output);
        options.lighting = shading::default_lighting(perspective::light_direction(view));
        if (one_light) options.lighting.lights.resize(1);
        options.output = naive ? shading::Output::naive : shading::Output::srgb;
        std::vector<std::string> warnings;
        std::vector<normal_mapping::MappedModel> models;
        if (view.models.empty())
            models = normal_mapping::default_scene(tangents, warnings, options.output,
                                                   options.normal_map);
        for (const std::string& path : view.models)  // as stored: the identity model matrix
            models.push_back(normal_mapping::load_mapped_model(path, rl::mat4::identity(), tangents,
                                                               warnings, options.output,
                                                               options.normal_map));
        rl::print_warnings("07_normal_mapping", warnings);
        perspective::Box box;
        for (const normal_mapping::MappedModel& m : models)
            box.add(perspective::bounds(m.lit.model.mesh, m.lit.model.transform));
        const float aspect = static_cast<float>(width) / static_cast<float>(height);
        const perspective::Camera camera = perspective::resolve_camera(view, box, aspect);
        rl::print_warnings("07_normal_mapping", {perspective::depth_precision_warning(camera)});

        if (options.filter == textures::Filter::trilinear) normal_mapping::build_mip_levels(models);
        // [doc:lesson07-main]
        perspective::ColourTarget frame = perspective::colour_target(width, height);
        const auto start = std::chrono::steady_clock::now();
        const perspective::PipelineCounts counts =
            normal_mapping::render(models, camera, options, frame);
        const std::chrono::duration<double, std::milli> took =
            std::chrono::steady_clock::now() - start;
        rl::save_image(output, frame.colour());
        // [/doc:lesson07-main]
        std::printf(
            "%zu models: %zu faces, %zu back faces, %zu fragments shaded in %.1f ms (rendering "
            "only); %s normal map, %s tangents; into %s\n",
            models.size(), counts.faces, counts.back_faces, counts.fragments, took.count(),
            normal_mapping::name(options.normal_map), normal_mapping::name(tangents),
            output.c_str());
        return 0;
    });
}
