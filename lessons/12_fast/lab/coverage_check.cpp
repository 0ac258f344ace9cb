#include "coverage_check.hpp"

namespace fast {

std::optional<std::vector<std::pair<int, int>>> covered_pixels(const triangles::ScreenTriangle& t,
                                                               int width, int height, int tile_size,
                                                               const Techniques& techniques) {
    Setup setup{};
    for (int k = 0; k < 3; ++k) setup.window[k] = {t.v[k].x, t.v[k].y, 0.5f};
    std::vector<FastTriangle> triangles(1);
    if (!fast_triangle(setup, 0, width, height, triangles[0])) return std::nullopt;
    std::vector<std::pair<int, int>> out;
    if (triangles[0].empty()) return out;
    TileBuffers buffers(tile_size);
    const std::uint32_t bin[1] = {0};
    std::vector<std::vector<bool>> covered(static_cast<std::size_t>(height),
                                           std::vector<bool>(static_cast<std::size_t>(width)));
    for (int y0 = 0; y0 < height; y0 += tile_size)
        for (int x0 = 0; x0 < width; x0 += tile_size) {
            const TileWork work{x0,
                                y0,
                                std::min(tile_size, width - x0),
                                std::min(tile_size, height - y0),
                                &triangles,
                                bin,
                                1,
                                nullptr,
                                techniques};
            TileCounts counts;
            rasterize_tile(work, buffers, counts);
            const int blocks_per_row = tile_size / kBlock;
            for (int y = 0; y < work.height; ++y)
                for (int x = 0; x < work.width; ++x) {
                    const std::size_t slot =
                        static_cast<std::size_t>((y / kBlock) * blocks_per_row + x / kBlock) * 64 +
                        static_cast<std::size_t>((y % kBlock) * kBlock + x % kBlock);
                    if (buffers.id[slot] == 0)
                        covered[static_cast<std::size_t>(y0 + y)]
                               [static_cast<std::size_t>(x0 + x)] = true;
                }
        }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (covered[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)])
                out.push_back({x, y});
    return out;
}

}  // namespace fast
