// imgconv: converts an image between the formats rasterlab reads and writes,
// e.g. a lesson's TGA output to the PNG that its doc page shows.
#include "rasterlab/cli.hpp"

#include <algorithm>
#include <cstdint>

#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Convert an image: reads TGA/PNG/JPG/BMP, writes .tga (RLE) or .png by extension."};
    std::string input, output;
    bool keep_alpha = false, flip = false;
    int scale = 1;
    std::vector<int> crop;
    app.add_option("input", input, "Image to read")->required();
    app.add_option("output", output, "Image to write (.tga or .png)")->required();
    app.add_flag("--alpha", keep_alpha, "Keep the alpha channel in TGA output (32-bit)");
    app.add_option("--scale", scale,
                   "Enlarge by this whole factor, each pixel a square block "
                   "(for close-ups in the docs)")
        ->check(rl::range(1, 64));
    app.add_flag("--flip", flip,
                 "Turn the image upside down (its rows in the opposite order): what a window "
                 "shows when a bottom-row-first frame is sent as it is");
    app.add_option("--crop", crop, "Keep only the rectangle X Y W H (X, Y: its bottom-left pixel)")
        ->expected(4);
    std::vector<int> stretch;
    app.add_option("--stretch", stretch,
                   "Spread the channel values LO..HI over 0..255, those outside clipped: a "
                   "difference in the dark made visible (the figure's caption must say so)")
        ->expected(2)
        ->check(rl::range(0, 255));
    return app.run(argc, argv, "imgconv", [&] {
        rl::Image image = rl::load_image(input);
        if (!crop.empty()) {
            const int x0 = crop[0], y0 = crop[1], w = crop[2], h = crop[3];
            if (w <= 0 || h <= 0 || x0 < 0 || y0 < 0 || x0 + w > image.width() ||
                y0 + h > image.height())
                throw std::invalid_argument("--crop rectangle is not inside the " +
                                            std::to_string(image.width()) + "x" +
                                            std::to_string(image.height()) + " image");
            rl::Image part(w, h);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) part.set(x, y, image.get(x0 + x, y0 + y));
            image = part;
        }
        if (!stretch.empty()) {
            const int lo = stretch[0], hi = stretch[1];
            if (lo >= hi)
                throw std::invalid_argument("--stretch " + std::to_string(lo) + " " +
                                            std::to_string(hi) + ": LO must be below HI");
            const auto spread = [lo, hi](std::uint8_t v) {
                return static_cast<std::uint8_t>(std::clamp((v - lo) * 255 / (hi - lo), 0, 255));
            };
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const rl::Rgba c = image.get(x, y);
                    image.set(x, y, {spread(c.r), spread(c.g), spread(c.b), c.a});
                }
        }
        if (flip) image.flip_vertically();
        rl::Image scaled(image.width() * scale, image.height() * scale);
        for (int y = 0; y < scaled.height(); ++y)
            for (int x = 0; x < scaled.width(); ++x)
                scaled.set(x, y, image.get(x / scale, y / scale));
        rl::save_image(output, scaled, keep_alpha);
        return 0;
    });
}
