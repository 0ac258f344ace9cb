// Lesson 02's draw loop: every face of a mesh, from its corners' places in
// the window to the pixels it covers. The vertex stage places each corner
// (x, y in pixels; z a depth, for lesson 03); a face that turns clockwise on
// screen shows its back and is culled; the rest go to the rasterizer, which
// hands every covered pixel, with its barycentric weights, to the fragment
// stage. Lesson 04 puts lesson 03's depth test and its own texture lookup in
// the fragment stage; lesson 05 replaces the loop by the full pipeline
// (clip space, clipping, perspective). Derivation: docs/02_triangles.md.
//
//   triangles::draw_faces(mesh, 800, 800, {},
//       [&](const rl::Face& face, int corner) { return window_of(face, corner); },
//       [&](const triangles::WindowTriangle& t, int x, int y, rl::vec3 weights) {
//           image.at(x, y) = colours[t.face];
//       });
#pragma once

#include "bands.hpp"
#include "raster.hpp"
#include "rasterlab/mesh.hpp"

namespace triangles {

// A face placed in the window: x, y in pixels, z whatever depth the vertex
// stage gave, and the index of the mesh face it came from.
struct WindowTriangle {
    rl::vec3 window[3];
    int face;
    ScreenTriangle screen() const { return {{window[0].xy(), window[1].xy(), window[2].xy()}}; }
};

struct DrawOptions {
    RasterMethod method = RasterMethod::edge;
    bool cull_back_faces = true;
};

// Counter-clockwise on screen means facing the viewer, who looks down -z.
// Not "culled unless > 0": a face whose area is NaN goes on, for the
// rasterizer to refuse and count.
inline bool is_back_face(const ScreenTriangle& t) {
    return signed_area2(t) <= 0;
}

// [doc:draw-faces]
template <class VertexStage, class FragmentStage>
DrawCounts draw_faces(const rl::Mesh& mesh, int width, int height, const DrawOptions& options,
                      VertexStage&& vertex_stage, FragmentStage&& fragment_stage) {
    DrawCounts counts;
    for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
        const rl::Face& face = mesh.faces[i];
        const WindowTriangle t{
            {vertex_stage(face, 0), vertex_stage(face, 1), vertex_stage(face, 2)},
            static_cast<int>(i)};
        if (options.cull_back_faces && is_back_face(t.screen())) {
            ++counts.culled;
            continue;
        }
        bool ok = true;
        for (const PixelRect band : Bands(t.screen(), {0, 0, width, height}, 0)) {
            rl::checkpoint();  // in bands of rows, so that a host (the Python module) can stop
            ok &= rasterize(options.method, t.screen(), band,
                            [&](int x, int y, rl::vec3 b) { fragment_stage(t, x, y, b); });
        }
        ++(ok ? counts.drawn : counts.refused);
    }
    return counts;
}
// [/doc:draw-faces]

}  // namespace triangles
