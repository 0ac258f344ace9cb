// Image storage: a grid of pixels kept bottom row first, as OpenGL's window
// coordinates are (pixel (0, 0) is the bottom-left one). See docs/00_framebuffer.md.
//
//   rl::Image image(800, 600, rl::kBackground);
//   image.set(10, 20, rl::Rgba{255, 0, 0, 255});  // 10 pixels right, 20 up from the bottom-left
//   rl::FloatImage depth(800, 600, 1.0f);  // any pixel type: rl::Grid<T>
//   if (depth.contains(x, y) && z < depth.at(x, y)) depth.set(x, y, z);
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace rl {

struct Rgba {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;
    friend bool operator==(const Rgba&, const Rgba&) = default;
};

// What every lesson clears its image to: a dark blue-grey, so that black
// (unlit) surfaces still stand out from the background.
inline constexpr Rgba kBackground{16, 18, 24, 255};

// The largest image any part of rasterlab creates or reads: 2^28 pixels
// (16384 x 16384), 1 GiB of RGBA. Larger requests are refused, not attempted.
inline constexpr std::size_t kMaxPixels = std::size_t{1} << 28;

// Throws std::invalid_argument unless 0 < width, 0 < height and the pixel
// count is at most kMaxPixels.
void check_dimensions(int width, int height);

// A width x height grid of T stored row by row, bottom row first.
// at() checks bounds in debug builds only; contains() is the check callers
// use when a coordinate may legitimately fall outside.
template <typename T>
class Grid {
  public:
    Grid() = default;
    Grid(int width, int height, T value = T{}) : width_(width), height_(height) {
        check_dimensions(width, height);
        pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), value);
    }

    int width() const { return width_; }
    int height() const { return height_; }
    bool empty() const { return pixels_.empty(); }
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

    T& at(int x, int y) { return pixels_[index(x, y)]; }
    const T& at(int x, int y) const { return pixels_[index(x, y)]; }
    T get(int x, int y) const { return at(x, y); }
    void set(int x, int y, T value) { at(x, y) = value; }

    void fill(T value) { pixels_.assign(pixels_.size(), value); }

    // Mirror top to bottom: turns a bottom-first image into a top-first one and back.
    void flip_vertically() {
        for (int y = 0; y < height_ / 2; ++y)
            for (int x = 0; x < width_; ++x) std::swap(at(x, y), at(x, height_ - 1 - y));
    }
    void flip_horizontally() {
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_ / 2; ++x) std::swap(at(x, y), at(width_ - 1 - x, y));
    }

    // Raw access, row by row from the bottom row.
    std::vector<T>& pixels() { return pixels_; }
    const std::vector<T>& pixels() const { return pixels_; }

    friend bool operator==(const Grid&, const Grid&) = default;

  private:
    std::size_t index(int x, int y) const {
#ifndef NDEBUG
        if (!contains(x, y))
            throw std::out_of_range("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                    ") outside a " + std::to_string(width_) + "x" +
                                    std::to_string(height_) + " image");
#endif
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
               static_cast<std::size_t>(x);
    }

    int width_ = 0;
    int height_ = 0;
    std::vector<T> pixels_;
};

using Image = Grid<Rgba>;        // colour: what the lessons draw and write
using FloatImage = Grid<float>;  // depth buffers, error maps and other lab data

}  // namespace rl
