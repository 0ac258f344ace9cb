#include "scene.hpp"

#include <cmath>
#include <numbers>

#include "02_triangles/draw_faces.hpp"
#include "02_triangles/flat_shading.hpp"

namespace zbuffer {

// [doc:build-scene]
std::vector<SceneTriangle> build_scene(const std::vector<Placement>& placements, int width,
                                       int height, std::vector<std::string>* warnings,
                                       std::size_t* culled) {
    std::vector<SceneTriangle> scene;
    for (const Placement& placement : placements) {
        const rl::Mesh mesh = rl::load_obj(placement.model, warnings);
        for (const rl::Face& face : mesh.faces) {
            rl::vec3 world[3];
            SceneTriangle t;
            for (int k = 0; k < 3; ++k) {
                world[k] = placement.rotation * mesh.position(face, k) * placement.scale +
                           placement.offset;
                t.v[k] = orthographic_to_window(world[k], width, height);
            }
            if (triangles::is_back_face(screen(t))) {  // lesson 02's culling
                if (culled) ++*culled;
                continue;
            }
            t.colour = triangles::lit(
                triangles::kSurfaceColour,
                triangles::lambert(rl::cross(world[1] - world[0], world[2] - world[0]),
                                   triangles::kDefaultLight));
            t.id = static_cast<int>(scene.size());
            scene.push_back(t);
        }
    }
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
