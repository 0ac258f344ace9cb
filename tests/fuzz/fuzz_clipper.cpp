// libFuzzer target: lesson 05's clipper on clip-space triangles of any
// floats (the input's bytes, 12 floats a triangle), against the planes of
// every clip mode. The polygon must stay within its slots for every input,
// and its vertices must be finite. (Before the cut was computed in the clip
// positions' double, a plane's distance overflowed a float past 1e34 and
// the cut vertex was NaN: the first finding, now a seed.) Anything else, an
// ASan report included, is a finding.
// Run: build-fuzz/tests/fuzz/fuzz_clipper
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "05_perspective/clipping.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 12 * sizeof(float)) return 0;
    float f[12];
    std::memcpy(f, data, sizeof f);
    std::array<pipeline::ClipVertex<rl::vec2>, 3> triangle;
    for (std::size_t k = 0; k < 3; ++k)
        triangle[k] = {
            rl::cast<double>(rl::vec4{f[4 * k], f[4 * k + 1], f[4 * k + 2], f[4 * k + 3]}),
            {static_cast<float>(k), 1.0f}};
    for (pipeline::ClipMode mode : pipeline::kClipModes) {
        const pipeline::ClipPolygon<rl::vec2> polygon =
            pipeline::clip_triangle(triangle, pipeline::clip_planes(mode, 800, 600));
        if (polygon.size < 0 || polygon.size > pipeline::ClipPolygon<rl::vec2>::kCapacity)
            std::abort();
        for (int i = 0; i < polygon.size; ++i)
            if (!pipeline::finite(polygon.vertices[static_cast<std::size_t>(i)].position))
                std::abort();
    }
    return 0;
}
