#include "orbit.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "rasterlab/transform.hpp"

namespace fast {

pipeline::Camera orbit(const pipeline::Camera& camera, int frame, int frames) {
    if (frame >= frames - 1) return camera;  // the last frame: exactly the camera given
    const float degrees = 360.0f * static_cast<float>(frame + 1) / static_cast<float>(frames);
    const rl::mat3 turn = rl::to_matrix(rl::axis_angle(camera.up, degrees));
    pipeline::Camera out = camera;
    out.eye = camera.target + turn * (camera.eye - camera.target);
    return out;
}

void check_frames(int frames, int width, int height) {
    const double pixels = static_cast<double>(frames) * width * height;
    if (pixels <= kMaxPixelFrames) return;
    char text[320];
    std::snprintf(text, sizeof text,
                  "--frames: %d frames of %dx%d are %.3g pixels, more than the cap of 2^32 "
                  "(4.3e9: 256 frames at 4096x4096, 16 at 16384x16384); draw fewer frames or a "
                  "smaller image",
                  frames, width, height, pixels);
    throw std::invalid_argument(text);
}

double median_after_first(std::vector<double> times) {
    if (times.size() > 1) times.erase(times.begin());
    return median(std::move(times));
}

double median(std::vector<double> times) {
    if (times.empty()) return 0;
    const auto middle = times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2);
    std::nth_element(times.begin(), middle, times.end());
    return *middle;
}

}  // namespace fast
