// Lesson 08: shadows. Two passes: the scene's depth from the light into a
// shadow map, then the scene from the camera with lesson 07's shading, the
// key light scaled at every pixel by what the map lets through. Read
// docs/08_shadows.md beside it.
#include <chrono>
#include <cstdio>

#include "03_zbuffer/depth_picture.hpp"
#include "05_perspective/view_cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "scene.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 08, shadows: lesson 07's render with shadows from a shadow map, of a directional "
        "or a spot light."};
    rl::ImageOptions image_options{"08_shadows.tga"};
    pipeline::ViewOptions view;
    shadows::ShadowOptions options;
    normal_mapping::TangentMethod tangents = normal_mapping::TangentMethod::split;
    shadows::Show show = shadows::Show::image;
    shadows::MapFaces map_faces = shadows::MapFaces::front;
    std::vector<float> light_position;
    view.light = {shadows::kSceneLight.x, shadows::kSceneLight.y, shadows::kSceneLight.z};
    pipeline::add_view_options(app, view, "floor, globe, crate and torus from obj/");
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--light-type", options.light.type, shadows::kLightTypes,
                          "The light that casts the shadows (--light: the direction towards it)");
    app.add_option("--light-position", light_position,
                   "Spot light: where it is, x y z (default: along --light, outside the scene)")
        ->expected(3)
        ->check(rl::finite_number());
    rl::Option* cone =
        app.add_option("--cone", options.light.cone_degrees,
                       "Spot light: the cone's full opening angle, degrees (1 to 170)")
            ->capture_default_str()
            ->check(rl::finite_number(1, 170));
    app.add_option(
           "--shadow-map-size", options.map.size,
           "Shadow map texels per side (1 to " + std::to_string(shadows::kMaxShadowMapSize) + ")")
        ->capture_default_str();
    app.add_option("--bias", options.map.constant_bias,
                   "Constant depth bias added to the map (window depth, 0 to 0.1)")
        ->capture_default_str()
        ->check(rl::finite_number(0, 0.1));
    app.add_option("--slope-bias", options.map.slope_bias,
                   "Depth bias per unit of the triangle's depth slope in the map (0 to 100)")
        ->capture_default_str()
        ->check(rl::finite_number(0, 100));
    app.add_option("--normal-offset", options.lookup.normal_offset,
                   "Look up the map this many map texels along the surface normal (0 to 100)")
        ->capture_default_str()
        ->check(rl::finite_number(0, 100));
    rl::add_method_option(app, "--filter", options.lookup.filter, shadows::kShadowFilters,
                          "Shadow filter");
    rl::add_method_option(app, "--fit", options.fit, shadows::kFits,
                          "The light's frustum around the whole scene or what the camera sees");
    rl::add_method_option(app, "--map-faces", map_faces, shadows::kMapFaces,
                          "Faces stored in the map: those facing the light, or those facing away");
    rl::add_method_option(app, "--show", show, shadows::kShows,
                          "Write the image, the shadow map's depth as a picture, or the image with "
                          "nothing in the map (no shadows)");
    rl::add_method_option(app, "--normal-map", options.render.normal_map,
                          normal_mapping::kNormalMaps, "Normal map to use (lesson 07)");
    rl::add_method_option(app, "--tangents", tangents, normal_mapping::kTangentMethods,
                          "Tangent frames of the --model files (lesson 07)");
    rl::add_method_option(app, "--specular", options.render.specular, shading::kSpeculars,
                          "The highlight, Phong's or Blinn's (lesson 06)");
    rl::add_method_option(app, "--texture-filter", options.render.filter, textures::kFilters,
                          "Texture filter, for every map (lesson 04)");
    bool one_light = false;
    app.add_flag("--one-light", one_light, "Only the --light, without the dim fill light");
    return app.run(argc, argv, "08_shadows", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        rl::check_image_output(output);
        shadows::refuse_spot_options(options.light.type, !light_position.empty(),
                                     cone->count() > 0);
        shadows::set_lights(options, view, one_light);
        options.map.cull = shadows::cull_for(map_faces);
        options.casters = show != shadows::Show::unshadowed;
        std::vector<std::string> warnings;
        const auto [models, camera] = shadows::load_scene(view, tangents, width, height, warnings);
        rl::print_warnings("08_shadows", warnings);
        const pipeline::Box box = shadows::scene_box(models);
        const float aspect = static_cast<float>(width) / static_cast<float>(height);
        shadows::place_spot(options, box, light_position);

        if (options.render.filter == textures::Filter::trilinear)
            normal_mapping::build_mip_levels(models);
        // [doc:lesson08-main]
        const auto start = std::chrono::steady_clock::now();
        const shadows::ShadowMap map = shadows::shadow_map_for(models, camera, aspect, options);
        const auto mapped = std::chrono::steady_clock::now();
        pipeline::ColourTarget frame = pipeline::colour_target(width, height);
        const pipeline::PipelineCounts counts =
            shadows::render(models, camera, options, map, frame);
        const auto done = std::chrono::steady_clock::now();
        rl::save_image(output, show == shadows::Show::shadow_map ? zbuffer::depth_picture(map.depth)
                                                                 : frame.colour());
        // [/doc:lesson08-main]
        const std::chrono::duration<double, std::milli> map_ms = mapped - start,
                                                        frame_ms = done - mapped;
        std::printf(
            "%zu models: %zu faces, %zu fragments shaded; %s light, %dx%d shadow map (%s fit, %s "
            "faces, %s filter) in %.1f ms, frame in %.1f ms; %s into %s\n",
            models.size(), counts.faces, counts.shaded, shadows::name(options.light.type),
            map.size(), map.size(), shadows::name(options.fit), shadows::name(map_faces),
            shadows::name(options.lookup.filter), map_ms.count(), frame_ms.count(),
            shadows::name(show), output.c_str());
        return 0;
    });
}
