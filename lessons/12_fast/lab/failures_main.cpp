// 12_failures: the page's failure pictures of the fast path
// (docs/12_fast.md). A fan of triangles around a hub on a pixel centre,
// drawn by the fast path's tile kernels, each pixel in the colour of the
// triangle that covered it (lesson 02's owners picture: red where two did,
// black where none did), with one of the tile loop's mistakes made on
// purpose (--mistake, coverage_check.hpp):
//   inclusive-ties   no tie rule, E >= 0 on every edge: spokes drawn twice
//   exclusive-ties   E > 0 on every edge: spokes not drawn at all
//   tile-origin      tile origins stepped one pixel short per tile
//   shared-buffer    two tiles through one tile buffer
// It prints how many pixels differ from lesson 02's edge rasterizer.
#include <cstdio>

#include "02_triangles/overdraw.hpp"
#include "coverage_check.hpp"
#include "rasterlab/cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 12's failure pictures: a fan of triangles through the fast path's tile kernels, "
        "with one mistake of the tile loop made on purpose."};
    std::string output = "12_failures.tga";
    int size = 64, slices = 12, tile_size = 16;
    fast::CoverageMistake mistake = fast::CoverageMistake::none;
    app.add_option("-o,--output", output, "Image to write (.tga or .png)")->capture_default_str();
    app.add_option("--size", size, "Image width and height in pixels (8 to 1024)")
        ->capture_default_str()
        ->check(rl::range(8, 1024));
    app.add_option("--slices", slices, "Triangles in the fan (3 to 360)")
        ->capture_default_str()
        ->check(rl::range(3, 360));
    app.add_option("--tile-size", tile_size, "Tile side in pixels (8 to 1024, a multiple of 8)")
        ->capture_default_str()
        ->check(rl::range(8, 1024));
    rl::add_method_option(app, "--mistake", mistake, fast::kCoverageMistakes,
                          "The mistake to make");
    return app.run(argc, argv, "12_failures", [&] {
        rl::check_image_output(output);
        if (tile_size % fast::kBlock != 0)
            throw std::invalid_argument("--tile-size: " + std::to_string(tile_size) +
                                        " is not a multiple of 8");
        const auto fast_cover = [&](fast::CoverageMistake m) {
            return [&, m](const triangles::ScreenTriangle& t) {
                return fast::covered_pixels(t, size, size, tile_size, {}, m)
                    .value_or(std::vector<std::pair<int, int>>{});
            };
        };
        const rl::Image picture = triangles::fan_owners(fast_cover(mistake), size, slices);
        const rl::Image right = triangles::fan_owners(
            triangles::covered_by(triangles::RasterMethod::edge, size, size), size, slices);
        long differing = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x)
                differing += picture.get(x, y) != right.get(x, y) ? 1 : 0;
        rl::save_image(output, picture);
        std::printf(
            "a fan of %d triangles, %dx%d, tiles of %d, mistake %s: %ld pixels differ from lesson "
            "02's edge rasterizer; into %s\n",
            slices, size, size, tile_size, fast::name(mistake), differing, output.c_str());
        return 0;
    });
}
