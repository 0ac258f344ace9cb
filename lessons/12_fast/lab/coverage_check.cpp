#include "coverage_check.hpp"

namespace fast {

namespace {

// Pixel (x, y) of a tile's buffers: laid out in 8x8 blocks (tile_kernels.hpp).
std::size_t slot_of(int x, int y, int tile_size) {
    const int blocks_per_row = tile_size / kBlock;
    return static_cast<std::size_t>((y / kBlock) * blocks_per_row + x / kBlock) * 64 +
           static_cast<std::size_t>((y % kBlock) * kBlock + x % kBlock);
}

}  // namespace

std::optional<std::vector<std::pair<int, int>>> covered_pixels(const triangles::ScreenTriangle& t,
                                                               int width, int height, int tile_size,
                                                               const Techniques& techniques,
                                                               CoverageMistake mistake) {
    Setup setup{};
    for (int k = 0; k < 3; ++k) setup.window[k] = {t.v[k].x, t.v[k].y, 0.5f};
    std::vector<FastTriangle> triangles(1);
    if (!fast_triangle(setup, 0, width, height, triangles[0])) return std::nullopt;
    std::vector<std::pair<int, int>> out;
    if (triangles[0].empty()) return out;
    if (mistake == CoverageMistake::inclusive_ties || mistake == CoverageMistake::exclusive_ties)
        for (std::int64_t& threshold : triangles[0].threshold)
            threshold = mistake == CoverageMistake::inclusive_ties ? -1 : 0;
    const TriangleChunks chunks{{triangles.data()}, {0, 1}};
    TileBuffers buffers(tile_size);
    const std::uint32_t bin[1] = {0};
    std::vector<std::vector<bool>> covered(static_cast<std::size_t>(height),
                                           std::vector<bool>(static_cast<std::size_t>(width)));
    // Reads the buffers' ids back into the tile at (x0, y0).
    auto read_back = [&](int x0, int y0) {
        for (int y = 0; y < std::min(tile_size, height - y0); ++y)
            for (int x = 0; x < std::min(tile_size, width - x0); ++x)
                if (buffers.id[slot_of(x, y, tile_size)] == 0)
                    covered[static_cast<std::size_t>(y0 + y)][static_cast<std::size_t>(x0 + x)] =
                        true;
    };
    auto rasterize_at = [&](int x0, int y0) {
        // Origins stepped by tile_size - 1: tile (i, j) is told it starts at
        // (x0 - i, y0 - j).
        const bool off = mistake == CoverageMistake::tile_origin;
        const TileWork work{off ? x0 - x0 / tile_size : x0,
                            off ? y0 - y0 / tile_size : y0,
                            std::min(tile_size, width - x0),
                            std::min(tile_size, height - y0),
                            &chunks,
                            bin,
                            1,
                            nullptr,
                            techniques};
        TileCounts counts;
        rasterize_tile(work, buffers, counts);
    };
    std::vector<std::pair<int, int>> tiles;
    for (int y0 = 0; y0 < height; y0 += tile_size)
        for (int x0 = 0; x0 < width; x0 += tile_size) tiles.push_back({x0, y0});
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        const auto [x0, y0] = tiles[i];
        rasterize_at(x0, y0);
        if (mistake == CoverageMistake::shared_buffer && i + 1 < tiles.size()) {
            // The pair's second tile lands in the same buffer before this
            // one is read: both read back the second's pixels.
            const auto [x1, y1] = tiles[i + 1];
            rasterize_at(x1, y1);
            read_back(x0, y0);
            read_back(x1, y1);
            ++i;
            continue;
        }
        read_back(x0, y0);
    }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (covered[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)])
                out.push_back({x, y});
    return out;
}

}  // namespace fast
