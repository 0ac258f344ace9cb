// Lesson 03: the z-buffer. Draws a scene of overlapping models with flat
// shading and hidden surfaces removed by the method of your choice, and a
// picture of the depth buffer. Read docs/03_zbuffer.md beside this file.
#include <cstdio>

#include "depth_picture.hpp"
#include "hidden_surfaces.hpp"
#include "rasterlab/cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

int main(int argc, char** argv) {
    CLI::App app{
        "Lesson 03, the z-buffer: overlapping models, hidden surfaces removed "
        "(orthographic, flat shading)."};
    std::string model;
    std::string depth_output;
    rl::ImageOptions image_options{"03_zbuffer.tga"};
    zbuffer::HsrMethod method = zbuffer::HsrMethod::zbuffer;
    app.add_option("-m,--model", model,
                   "OBJ file to draw alone (default: the rock pierced by the torus)");
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--hsr", method, zbuffer::kHsrMethods, "Hidden-surface method");
    app.add_option("--depth-out", depth_output, "Also write the depth buffer as a picture here");
    CLI11_PARSE(app, argc, argv);
    const auto& [output, width, height] = image_options;

    return rl::guarded_main("03_zbuffer", [&] {
        std::vector<zbuffer::Placement> placements = zbuffer::default_placements();
        if (!model.empty()) placements = {{model}};
        std::vector<std::string> warnings;
        const auto scene = zbuffer::build_scene(placements, width, height, &warnings);
        rl::print_warnings("03_zbuffer", warnings);
        // [doc:lesson03-main]
        zbuffer::Frame frame(width, height);
        zbuffer::render(method, scene, frame);
        rl::save_image(output, frame.colour);
        if (!depth_output.empty())
            rl::save_image(depth_output, zbuffer::depth_picture(frame.depth));
        // [/doc:lesson03-main]
        std::printf("%zu front faces drawn with %s into %s\n", scene.size(), zbuffer::name(method),
                    output.c_str());
        return 0;
    });
}
