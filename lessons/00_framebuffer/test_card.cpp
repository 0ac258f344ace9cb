#include "test_card.hpp"

#include <utility>

#include <algorithm>

namespace lesson00 {
namespace {

void fill_rect(rl::Image& image, int x0, int y0, int x1, int y1, rl::Rgba colour) {
    for (int y = std::max(0, y0); y < std::min(image.height(), y1); ++y)
        for (int x = std::max(0, x0); x < std::min(image.width(), x1); ++x) image.set(x, y, colour);
}

std::uint8_t ramp(int i, int n) {
    return static_cast<std::uint8_t>(n > 1 ? (255 * i) / (n - 1) : 0);
}

}  // namespace

// [doc:test-card]
rl::Image make_test_card(int width, int height) {
    rl::Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.set(x, y, {ramp(x, width), ramp(y, height), 64, 255});

    const int s = std::max(1, std::min(width, height) / 8);                    // corner square size
    fill_rect(image, 0, 0, s, s, {255, 255, 255, 255});                        // origin
    fill_rect(image, width - s, 0, width, s, {255, 0, 0, 255});                // +x: red
    fill_rect(image, 0, height - s, s, height, {0, 255, 0, 255});              // +y: green
    fill_rect(image, width - s, height - s, width, height, {0, 0, 255, 255});  // blue

    const int band = height / 2;
    fill_rect(image, s, band, width - s, band + s / 2, {40, 40, 40, 255});
    for (int y = band - s / 2; y < band; ++y)
        for (int x = s; x < width - s; ++x)
            if ((x + y) % 2 == 0) image.set(x, y, {230, 230, 230, 255});
    return image;
}
// [/doc:test-card]

rl::Image misread(const rl::Image& image, Misreading mistake) {
    rl::Image out = image;
    if (mistake == Misreading::byte_order)
        for (rl::Rgba& p : out.pixels()) std::swap(p.r, p.b);
    if (mistake == Misreading::origin) out.flip_vertically();
    return out;
}

}  // namespace lesson00
