// Lesson 01: lines. Draws the wireframe of a model, orthographically, with
// the line method of your choice. Read docs/01_lines.md beside this file.
#include <CLI/CLI.hpp>

#include <cstdio>

#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/mesh.hpp"
#include "wireframe.hpp"

int main(int argc, char** argv) {
    CLI::App app{"Lesson 01, lines: the wireframe of a model (orthographic, x and y in [-1, 1])."};
    std::string model = rl::project_model("rock").string();
    std::string output = "01_lines.tga";
    std::string method_name = "bresenham";
    int width = 800, height = 800;
    app.add_option("-m,--model", model, "OBJ file to draw")->capture_default_str();
    app.add_option("-o,--output", output, "Image to write (.tga or .png)")->capture_default_str();
    app.add_option("--method", method_name, "Line algorithm: parametric, dda, bresenham or wu")
        ->capture_default_str()
        ->check(CLI::IsMember({"parametric", "dda", "bresenham", "wu"}));
    app.add_option("--width", width, "Image width")
        ->capture_default_str()
        ->check(CLI::Range(1, 16384));
    app.add_option("--height", height, "Image height")
        ->capture_default_str()
        ->check(CLI::Range(1, 16384));
    CLI11_PARSE(app, argc, argv);

    return rl::guarded_main("01_lines", [&] {
        std::vector<std::string> warnings;
        const rl::Mesh mesh = rl::load_obj(model, &warnings);
        rl::print_warnings("01_lines", warnings);
        // [doc:lesson01-main]
        rl::Image image(width, height, rl::Rgba{16, 18, 24, 255});
        const lines::LineMethod method = *lines::parse_line_method(method_name);
        const std::size_t edges =
            lines::draw_wireframe(image, mesh, rl::Rgba{235, 235, 220, 255}, method);
        rl::save_image(output, image);
        // [/doc:lesson01-main]
        std::printf("%zu edges of %s drawn with %s into %s\n", edges, model.c_str(),
                    method_name.c_str(), output.c_str());
        return 0;
    });
}
