#include "orbit.hpp"

#include <algorithm>

#include "rasterlab/transform.hpp"

namespace fast {

perspective::Camera orbit(const perspective::Camera& camera, int frame, int frames) {
    if (frame >= frames - 1) return camera;  // the last frame: exactly the camera given
    const float degrees = 360.0f * static_cast<float>(frame + 1) / static_cast<float>(frames);
    const rl::mat3 turn = rl::to_matrix(rl::axis_angle(camera.up, degrees));
    perspective::Camera out = camera;
    out.eye = camera.target + turn * (camera.eye - camera.target);
    return out;
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
