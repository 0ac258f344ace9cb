// Lesson 07: normal mapping. The full render: any textured OBJ with its
// diffuse, normal and specular maps, perspective, Blinn-Phong (or Phong)
// shading in linear light. Read docs/07_normal_mapping.md beside it.
#include <chrono>
#include <cstdio>

#include "mapped_cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 07, normal mapping: models with their diffuse, normal and specular maps, lit "
        "per pixel in linear light through lesson 05's camera."};
    rl::ImageOptions image_options{"07_normal_mapping.tga"};
    normal_mapping::MappedCli cli;
    normal_mapping::add_mapped_options(app, cli, "floor, globe and crate from obj/");
    rl::add_image_options(app, image_options);
    return app.run(argc, argv, "07_normal_mapping", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        rl::check_image_output(output);
        const normal_mapping::RenderOptions& options = cli.options;
        const auto [models, camera] =
            normal_mapping::load_scene(cli, width, height, "07_normal_mapping");

        if (options.filter == textures::Filter::trilinear) normal_mapping::build_mip_levels(models);
        // [doc:lesson07-main]
        pipeline::ColourTarget frame = pipeline::colour_target(width, height);
        const auto start = std::chrono::steady_clock::now();
        const pipeline::PipelineCounts counts =
            normal_mapping::render(models, camera, options, frame);
        const std::chrono::duration<double, std::milli> took =
            std::chrono::steady_clock::now() - start;
        rl::save_image(output, frame.colour());
        // [/doc:lesson07-main]
        std::printf(
            "%zu models: %zu faces, %zu back faces, %zu fragments shaded in %.1f ms (rendering "
            "only); %s normal map, %s tangents; into %s\n",
            models.size(), counts.faces, counts.culled, counts.shaded, took.count(),
            normal_mapping::name(options.normal_map), normal_mapping::name(cli.tangents),
            output.c_str());
        return 0;
    });
}
