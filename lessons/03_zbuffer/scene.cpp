#include "scene.hpp"

#include <cmath>
#include <numbers>

#include "02_triangles/flat_shading.hpp"
#include "05_perspective/pipeline.hpp"

namespace zbuffer {

// [doc:build-scene]
std::vector<SceneTriangle> build_scene(const std::vector<Placement>& placements, int width,
                                       int height, std::vector<std::string>* warnings,
                                       std::size_t* culled) {
    std::vector<SceneTriangle> scene;
    perspective::PipelineOptions pipeline;
    pipeline.clip = perspective::ClipMode::none;  // orthographic: w = 1, nothing to cut
    pipeline.interpolation = perspective::Interpolation::affine;
    perspective::PipelineCounts counts;
    for (const Placement& placement : placements) {
        const rl::Mesh mesh = rl::load_obj(placement.model, warnings);
        int index = 0;
        for (const rl::Face& face : mesh.faces) {
            rl::vec3 world[3];
            std::array<perspective::ClipVertex<float>, 3> corners;
            for (int k = 0; k < 3; ++k) {
                world[k] = placement.rotation * mesh.position(face, k) * placement.scale +
                           placement.offset;
                corners[static_cast<std::size_t>(k)] = {perspective::orthographic_clip(world[k]),
                                                        0.0f};
            }
            const rl::Rgba colour = triangles::lit(
                triangles::kSurfaceColour,
                triangles::lambert(rl::cross(world[1] - world[0], world[2] - world[0]),
                                   triangles::kDefaultLight));
            // The pipeline's first half: cull, divide, viewport. The second
            // half (rasterize, depth test) is what this lesson's methods replace.
            perspective::assemble_triangle(
                corners, {}, pipeline, width, height, index++, counts,
                [&](const perspective::TriangleSetup<float>& t) {
                    scene.push_back({{t.window[0], t.window[1], t.window[2]},
                                     colour,
                                     static_cast<int>(scene.size())});
                });
        }
    }
    if (culled) *culled += counts.back_faces;
    return scene;
}
// [/doc:build-scene]

std::vector<Placement> default_placements() {
    return {{rl::project_model("rock"), rl::mat3::identity(), 0.75f, {0, 0, 0}},
            {rl::project_model("torus"),
             rl::rotation_y(25) * rl::rotation_x(-65),
             0.95f,
             {0.05f, -0.05f, 0}}};
}

}  // namespace zbuffer
