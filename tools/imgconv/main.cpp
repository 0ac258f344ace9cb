// imgconv: converts an image between the formats rasterlab reads and writes,
// e.g. a lesson's TGA output to the PNG that its doc page shows.
#include <CLI/CLI.hpp>

#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

int main(int argc, char** argv) {
    CLI::App app{
        "Convert an image: reads TGA/PNG/JPG/BMP, writes .tga (RLE) or .png by extension."};
    std::string input, output;
    bool keep_alpha = false;
    app.add_option("input", input, "Image to read")->required();
    app.add_option("output", output, "Image to write (.tga or .png)")->required();
    app.add_flag("--alpha", keep_alpha, "Keep the alpha channel in TGA output (32-bit)");
    CLI11_PARSE(app, argc, argv);
    return rl::guarded_main("imgconv", [&] {
        rl::save_image(output, rl::load_image(input), keep_alpha);
        return 0;
    });
}
