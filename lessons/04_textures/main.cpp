// Lesson 04: textures. Draws a textured model with the filter and wrap mode
// of your choice. Read docs/04_textures.md beside this file.
#include <cstdio>

#include "rasterlab/cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/texture_files.hpp"
#include "textured.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 04, textures: a model with its diffuse texture (orthographic, z-buffered)."};
    std::string model = rl::project_model("crate").string();
    rl::ImageOptions image_options{"04_textures.tga"};
    textures::TexturedOptions options;
    bool no_light = false;
    std::vector<float> turn{textures::kDefaultTurnX, textures::kDefaultTurnY};
    rl::add_model_option(app, model);
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--filter", options.sampler.filter, textures::kFilters,
                          "Texture filter");
    rl::add_method_option(app, "--wrap", options.sampler.wrap, textures::kWraps, "Wrap mode");
    app.add_option("--uv-scale", options.uv_scale,
                   "Multiply texture coordinates by this (shows wrapping)")
        ->check(rl::finite_number(-1e7, 1e7))
        ->capture_default_str();
    app.add_option("--uv-offset", options.uv_offset.x, "Then add this to u and v")
        ->check(rl::finite_number(-1e7, 1e7))
        ->capture_default_str();
    app.add_option("--turn", turn, "Rotate the model about x, then y, in degrees")
        ->expected(2)
        ->check(rl::finite_number(-3600, 3600))
        ->capture_default_str();
    app.add_option("--scale", options.scale, "Scale the model")
        ->check(rl::finite_number(1e-6, 1e6))
        ->capture_default_str();
    app.add_flag("--no-light", no_light, "Texture colour only, no Lambert shading");
    return app.run(argc, argv, "04_textures", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        rl::check_image_output(output);  // before any work: a bad path costs nothing
        options.uv_offset.y = options.uv_offset.x;
        options.lighting = !no_light;
        options.rotation = rl::rotation_y(turn[1]) * rl::rotation_x(turn[0]);
        options.sampler.border = textures::kLoudBorder;
        std::vector<std::string> warnings;
        const rl::Mesh mesh = rl::load_obj(model, &warnings);
        const rl::Texture diffuse = rl::load_texture(mesh, 0, rl::TextureRole::diffuse, warnings);
        rl::print_warnings("04_textures", warnings);
        // [doc:lesson04-main]
        const textures::MipChain chain(diffuse.image);
        zbuffer::Frame frame(width, height);
        const triangles::DrawCounts counts = textures::draw_textured(frame, mesh, chain, options);
        rl::save_image(output, frame.colour);
        // [/doc:lesson04-main]
        std::printf(
            "%zu faces of %s drawn, %zu culled, %zu refused; textured with %s (%d mip levels), "
            "%s filter, %s wrap, into %s\n",
            counts.drawn, model.c_str(), counts.culled, counts.refused,
            diffuse.is_default ? "a plain default" : diffuse.source.filename().c_str(),
            chain.levels(), textures::name(options.sampler.filter),
            textures::name(options.sampler.wrap), output.c_str());
        return 0;
    });
}
