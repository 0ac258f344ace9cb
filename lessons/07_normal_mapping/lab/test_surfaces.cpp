#include "test_surfaces.hpp"

#include "06_shading/truths/sphere_truth.hpp"

namespace normal_mapping {
namespace {

// The model's mesh replaced by `mesh`, with its texture and maps kept, and
// normals, box and tangent frames made anew.
void replace_mesh(MappedModel& m, rl::Mesh mesh, TangentMethod method) {
    m.lit.model.mesh = std::move(mesh);
    m.lit.normals = shading::corner_normals(m.lit.model.mesh, shading::Weighting::angle);
    m.lit.model.box = pipeline::bounds(m.lit.model.mesh, m.lit.model.transform);
    m.tangents = corner_tangents(m.lit.model.mesh, m.lit.normals, method);
}

}  // namespace

MappedModel mirrored_plane(TangentMethod method, std::vector<std::string>& warnings) {
    MappedModel plane =
        load_mapped_model(rl::project_model("crate"), rl::mat4::identity(), method, warnings);
    rl::Mesh square;
    square.source = plane.lit.model.mesh.source;
    square.materials = plane.lit.model.mesh.materials;
    square.normals = {{0, 0, 1}};
    const int n = 8;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = -1 + 2.0f * i / n, y = -1 + 2.0f * j / n;
            square.positions.push_back({x, y, 0});
            square.uvs.push_back({std::abs(x), (y + 1) / 2});
        }
    const auto corner = [&](int i, int j) {
        return rl::Corner{j * (n + 1) + i, j * (n + 1) + i, 0};
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            square.faces.push_back({{corner(i, j), corner(i + 1, j), corner(i + 1, j + 1)}, 0});
            square.faces.push_back({{corner(i, j), corner(i + 1, j + 1), corner(i, j + 1)}, 0});
        }
    replace_mesh(plane, std::move(square), method);
    return plane;
}

MappedModel low_poly_globe(int segments, TangentMethod method, std::vector<std::string>& warnings) {
    MappedModel globe =
        load_mapped_model(rl::project_model("globe"), rl::mat4::identity(), method, warnings);
    replace_mesh(globe, shading::uv_sphere(segments), method);
    return globe;
}

}  // namespace normal_mapping
