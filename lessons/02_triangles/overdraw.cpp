#include "overdraw.hpp"

#include "fans.hpp"

namespace triangles {

rl::Image overdraw_fan(RasterMethod method, int size, int slices) {
    rl::Grid<int> count(size, size, 0);
    const float hub = size / 2 + 0.5f;
    for (const ScreenTriangle& t : disc_fan({hub, hub}, size * 0.42f, slices))
        rasterize(method, t, size, size, [&](int x, int y, rl::vec3) { ++count.at(x, y); });
    rl::Image image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const int n = count.get(x, y);
            image.set(x, y,
                      n == 0   ? rl::Rgba{0, 0, 0, 255}
                      : n == 1 ? rl::Rgba{150, 150, 150, 255}
                               : rl::Rgba{230, 30, 30, 255});
        }
    return image;
}

rl::Image edge_owners(RasterMethod method, int size) {
    return fan_owners(covered_by(method, size, size), size, 4);
}

CoveredPixels covered_by(RasterMethod method, int width, int height) {
    return [=](const ScreenTriangle& t) {
        std::vector<std::pair<int, int>> pixels;
        rasterize(method, t, width, height, [&](int x, int y, rl::vec3) {
            pixels.push_back({x, y});
        });
        return pixels;
    };
}

rl::Image fan_owners(const CoveredPixels& covered, int size, int slices) {
    const rl::Rgba colours[4] = {
        {60, 110, 220, 255}, {70, 170, 90, 255}, {230, 150, 40, 255}, {150, 80, 190, 255}};
    const rl::Rgba none{0, 0, 0, 255}, twice{230, 30, 30, 255};
    rl::Image image(size, size, none);
    rl::Grid<int> owner(size, size, -1);
    const float hub = size / 2 + 0.5f;
    const std::vector<ScreenTriangle> fan = disc_fan({hub, hub}, size * 0.42f, slices);
    for (int i = 0; i < slices; ++i)
        for (const auto& [x, y] : covered(fan[static_cast<std::size_t>(i)])) {
            image.at(x, y) = owner.get(x, y) >= 0 ? twice : colours[i % 4];
            owner.at(x, y) = i;
        }
    return image;
}

}  // namespace triangles
