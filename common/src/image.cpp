#include "rasterlab/image.hpp"

namespace rl {

void check_dimensions(int width, int height) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("image size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " is not positive");
    const auto pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (pixels > kMaxPixels)
        throw std::invalid_argument("image size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " exceeds the limit of " +
                                    std::to_string(kMaxPixels) + " pixels");
}

}  // namespace rl
