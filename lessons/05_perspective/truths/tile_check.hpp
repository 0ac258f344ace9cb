// A check the tests of lessons 05 and later share: a frame drawn whole and
// the same frame drawn tile by tile, the tiles in a shuffled order, must
// agree bit for bit in colour and depth (tiles are how lesson 12 spreads a
// frame over threads), and a tile drawn alone must touch nothing outside it.
//
//   EXPECT_TRUE(pipeline::tiles_add_up(300, 200, 64, [&](ColourTarget& frame,
//       std::optional<triangles::PixelRect> tile) { ... draw with options.tile = tile ... }));
#pragma once

#include <algorithm>
#include <optional>
#include <random>

#include "05_perspective/render_target.hpp"

namespace pipeline {

template <class Draw>
bool tiles_add_up(int width, int height, int tile_size, Draw&& draw) {
    ColourTarget whole = colour_target(width, height), tiled = colour_target(width, height);
    draw(whole, std::optional<triangles::PixelRect>{});
    std::vector<triangles::PixelRect> rects = tiles(width, height, tile_size);
    std::shuffle(rects.begin(), rects.end(), std::mt19937(5));
    for (const triangles::PixelRect& tile : rects)
        draw(tiled, std::optional<triangles::PixelRect>(tile));
    // and a tile alone leaves every pixel outside it as cleared.
    const triangles::PixelRect one = rects.front();
    ColourTarget alone = colour_target(width, height);
    draw(alone, std::optional<triangles::PixelRect>(one));
    const ColourTarget clear = colour_target(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if ((x < one.x0 || x >= one.x1 || y < one.y0 || y >= one.y1) &&
                !(alone.colour().at(x, y) == clear.colour().at(x, y) &&
                  alone.depth()->at(x, y) == clear.depth()->at(x, y)))
                return false;
    return whole.colour() == tiled.colour() && *whole.depth() == *tiled.depth();
}

}  // namespace pipeline
