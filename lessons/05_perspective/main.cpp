// Lesson 05: perspective. Textured models seen through a camera: look-at,
// perspective projection, clipping in clip space, and texture coordinates
// interpolated perspective-correctly. Read docs/05_perspective.md beside it.
#include <cstdio>

#include "rasterlab/cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "scene.hpp"
#include "view_cli.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 05, perspective: textured models through a look-at camera and a perspective "
        "projection, clipped in clip space, texture coordinates interpolated "
        "perspective-correctly."};
    rl::ImageOptions image_options{"05_perspective.tga"};
    pipeline::ViewOptions view;
    pipeline::RenderOptions options;
    pipeline::add_view_options(app, view, "floor, crate and globe from obj/");
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--clip", options.pipeline.clip, pipeline::kClipModes, "Clipping");
    rl::add_method_option(app, "--interpolation", options.pipeline.interpolation,
                          pipeline::kInterpolations, "Interpolation of texture coordinates");
    rl::add_method_option(app, "--lod", options.lod, pipeline::kLodMethods,
                          "Mip level from each pixel's derivatives or one per triangle");
    rl::add_method_option(app, "--filter", options.sampler.filter, textures::kFilters,
                          "Texture filter");
    bool no_light = false;
    app.add_flag("--no-light", no_light, "Texture colour only, no Lambert shading");
    return app.run(argc, argv, "05_perspective", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        rl::check_image_output(output);
        options.light = pipeline::light_direction(view);
        options.lighting = !no_light;
        std::vector<std::string> warnings;
        const auto [models, camera] = pipeline::load_scene(view, width, height, warnings);
        rl::print_warnings("05_perspective", warnings);

        pipeline::ColourTarget frame = pipeline::colour_target(width, height);
        const pipeline::PipelineCounts counts = pipeline::render(models, camera, options, frame);
        rl::save_image(output, frame.colour());
        std::printf(
            "%zu models (%zu culled by their boxes): %zu faces, %zu back faces, %zu clipped, "
            "%zu outside, %zu triangles drawn, %zu refused, %zu fragments shaded; eye (%g, %g, "
            "%g), near %g, far %g; %s interpolation, %s clipping, into %s\n",
            models.size(), counts.objects_culled, counts.faces, counts.culled, counts.clipped,
            counts.outside, counts.drawn, counts.refused, counts.shaded,
            static_cast<double>(camera.eye.x), static_cast<double>(camera.eye.y),
            static_cast<double>(camera.eye.z), static_cast<double>(camera.near),
            static_cast<double>(camera.far), pipeline::name(options.pipeline.interpolation),
            pipeline::name(options.pipeline.clip), output.c_str());
        return 0;
    });
}
