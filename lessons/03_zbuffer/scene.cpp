#include "scene.hpp"

#include <cmath>
#include <numbers>

#include "02_triangles/flat_shading.hpp"

namespace zbuffer {

rl::vec3 to_window(rl::vec3 p, int width, int height) {
    return {(p.x + 1.0f) * 0.5f * static_cast<float>(width),
            (p.y + 1.0f) * 0.5f * static_cast<float>(height), (1.0f - p.z) * 0.5f};
}

std::vector<SceneTriangle> build_scene(const std::vector<Placement>& placements, int width,
                                       int height, std::vector<std::string>* warnings,
                                       std::size_t* culled) {
    std::vector<SceneTriangle> scene;
    for (const Placement& placement : placements) {
        const rl::Mesh mesh = rl::load_obj(placement.model, warnings);
        for (const rl::Triangle& face : mesh.triangles) {
            rl::vec3 world[3];
            SceneTriangle t;
            for (int k = 0; k < 3; ++k) {
                world[k] = placement.rotation * mesh.position(face, k) * placement.scale +
                           placement.offset;
                t.v[k] = to_window(world[k], width, height);
            }
            if (triangles::signed_area2(screen(t)) <= 0) {  // back face
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

std::vector<Placement> default_placements() {
    return {{rl::project_model("rock"), rl::mat3::identity(), 0.75f, {0, 0, 0}},
            {rl::project_model("torus"),
             rl::rotation_y(25) * rl::rotation_x(-65),
             0.95f,
             {0.05f, -0.05f, 0}}};
}

}  // namespace zbuffer
