#include "clipping.hpp"

#include <algorithm>

namespace pipeline {

float guard_band(int width, int height) {
    // |window x| <= (g + 1) / 2 * size <= 2^21  <=>  g <= 2^22 / size - 1.
    const float size = static_cast<float>(std::max(width, height));
    return 4194304.0f / size - 1.0f;
}

// [doc:clip-planes]
ClipPlanes clip_planes(ClipMode mode, int width, int height) {
    const ClipPlane near{0, 0, 1, 1};  // z >= -w
    const ClipPlane far{0, 0, -1, 1};  // z <= w
    const float g = mode == ClipMode::all ? 1.0f : guard_band(width, height);
    const ClipPlane left{1, 0, 0, g}, right{-1, 0, 0, g};  // -g w <= x <= g w
    const ClipPlane bottom{0, 1, 0, g}, top{0, -1, 0, g};  // -g w <= y <= g w
    switch (mode) {
        case ClipMode::none:
            return {};
        case ClipMode::near:
            return {{near}, 1};
        case ClipMode::guard_band:
        case ClipMode::all:
            return {{near, far, left, right, bottom, top}, 6};
    }
    return {};
}
// [/doc:clip-planes]

}  // namespace pipeline
