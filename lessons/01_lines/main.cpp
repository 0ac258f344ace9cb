// Lesson 01: lines. Draws the wireframe of a model, orthographically, with
// the line method of your choice. Read docs/01_lines.md beside this file.
#include <cstdio>

#include "rasterlab/cli.hpp"

#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/mesh.hpp"
#include "wireframe.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 01, lines: the wireframe of a model (orthographic, x and y in [-1, 1])."};
    std::string model = rl::project_model("rock").string();
    rl::ImageOptions image_options{"01_lines.tga"};
    lines::LineMethod method = lines::LineMethod::bresenham;
    rl::add_model_option(app, model);
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--method", method, lines::kLineMethods, "Line algorithm");
    return app.run(argc, argv, "01_lines", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        rl::check_image_output(output);  // before any work: a bad path costs nothing
        std::vector<std::string> warnings;
        const rl::Mesh mesh = rl::load_obj(model, &warnings);
        rl::print_warnings("01_lines", warnings);
        // [doc:lesson01-main]
        rl::Image image(width, height, rl::kBackground);
        const std::size_t edges = lines::draw_wireframe(image, mesh, lines::kWireColour, method);
        rl::save_image(output, image);
        // [/doc:lesson01-main]
        std::printf("%zu edges of %s drawn with %s into %s\n", edges, model.c_str(),
                    lines::name(method), output.c_str());
        return 0;
    });
}
