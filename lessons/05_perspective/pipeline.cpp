#include "pipeline.hpp"

#include <cstdio>

namespace pipeline {

PipelineCounts& PipelineCounts::operator+=(const PipelineCounts& o) {
    objects_culled += o.objects_culled;
    faces += o.faces;
    culled += o.culled;
    outside += o.outside;
    clipped += o.clipped;
    drawn += o.drawn;
    refused += o.refused;
    visited += o.visited;
    shaded += o.shaded;
    stored += o.stored;
    return *this;
}

void throw_overdraw(double most) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "the triangles' bounding boxes cover more than %.3g samples, 1000 times the "
                  "image's: refusing to spend minutes on them (a scene's cover its image a few "
                  "times over; this many are the same faces repeated, or long thin faces)",
                  most);
    throw OverdrawError(text);
}

// [doc:outside-frustum]
bool outside_frustum(const Box& box, const rl::mat4& model_view_projection) {
    if (box.empty()) return true;
    rl::vec4 corners[8];
    for (int i = 0; i < 8; ++i)
        corners[i] = model_view_projection * rl::extend(box.corner(i), 1.0f);
    const ClipPlanes frustum = clip_planes(ClipMode::all, 1, 1);
    for (int k = 0; k < frustum.count; ++k) {
        int outside = 0;
        for (const rl::vec4& c : corners)
            outside += rl::dot(frustum.planes[static_cast<std::size_t>(k)], c) < 0;
        if (outside == 8) return true;  // every corner beyond the same plane
    }
    return false;
}
// [/doc:outside-frustum]

}  // namespace pipeline
