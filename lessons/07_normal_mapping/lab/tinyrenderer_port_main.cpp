// The port of tinyrenderer's renderer as a program of its own, so that the
// lab can time a whole process of it against 07_normal_mapping doing the same
// work (docs/07_normal_mapping_lab.md#where-the-time-goes). It reads one OBJ with
// its diffuse and tangent-space normal maps, frames it with lesson 05's
// camera (the same view options), renders one frame and writes it.
#include <chrono>
#include <cstdio>

#include "05_perspective/view_cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/texture_files.hpp"
#include "tinyrenderer_port.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "The lab's port of tinyrenderer's renderer: one OBJ, its diffuse and normal maps."};
    rl::ImageOptions image_options{"tinyrenderer_port.tga"};
    pipeline::ViewOptions view;
    pipeline::add_view_options(app, view, "the globe from obj/");
    rl::add_image_options(app, image_options);
    return app.run(argc, argv, "07_tinyrenderer_port", [&] {
        rl::check_image_output(image_options.output);
        if (view.models.size() > 1) throw std::invalid_argument("--model: one model only");
        std::vector<std::string> warnings;
        const rl::Mesh mesh =
            rl::load_obj(view.models.empty() ? rl::project_model("globe")
                                             : std::filesystem::path(view.models[0]),
                         &warnings);
        for (const rl::Face& face : mesh.faces)
            for (const rl::Corner& c : face.corners)
                if (c.uv < 0 || c.normal < 0)
                    throw std::invalid_argument("the port needs a normal and a uv at every corner");
        const rl::Image diffuse =
            rl::load_texture(mesh, 0, rl::TextureRole::diffuse, warnings).image;
        const rl::Image normals =
            rl::load_texture(mesh, 0, rl::TextureRole::normal_tangent, warnings).image;
        rl::print_warnings("07_tinyrenderer_port", warnings);
        const int width = image_options.width, height = image_options.height;
        const pipeline::Camera camera =
            pipeline::resolve_camera(view, pipeline::bounds(mesh, rl::mat4::identity()),
                                     static_cast<float>(width) / static_cast<float>(height));
        const auto start = std::chrono::steady_clock::now();
        const tinyrenderer_port::Result result = tinyrenderer_port::render(
            mesh, {&diffuse, &normals}, camera, pipeline::light_direction(view), width, height);
        const std::chrono::duration<double, std::milli> took =
            std::chrono::steady_clock::now() - start;
        rl::save_image(image_options.output, result.image);
        std::printf("%zu faces, %zu fragments shaded in %.1f ms (rendering only); into %s\n",
                    mesh.faces.size(), result.fragments, took.count(),
                    image_options.output.c_str());
        return 0;
    });
}
