#include "tinyrenderer_port.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "rasterlab/transform.hpp"

namespace tinyrenderer_port {

namespace {

using dvec2 = rl::dvec2;
using dvec3 = rl::dvec3;
using dvec4 = rl::Vec<4, double>;
using dmat3 = rl::Mat<3, double>;
using dmat4 = rl::Mat<4, double>;

dvec4 point(rl::vec3 p) {
    return {p.x, p.y, p.z, 1.0};
}

// The inverse transpose of a 3x3 by cofactors, as tinyrenderer computes it:
// the rows r1 x r2, r2 x r0, r0 x r1 over the determinant.
dmat3 inverse_transpose(const dmat3& m) {
    const double det = rl::determinant(m);
    dmat3 out;
    out[0] = rl::cross(m[1], m[2]) / det;
    out[1] = rl::cross(m[2], m[0]) / det;
    out[2] = rl::cross(m[0], m[1]) / det;
    return out;
}

struct IShader {
    virtual ~IShader() = default;
    virtual dvec4 vertex(int face, int corner) = 0;          // clip position
    virtual bool fragment(dvec3 bar, rl::Rgba& colour) = 0;  // true: discard
    dvec3 last_normal{};                                     // eye space, for the lab's probe
};

// tinyrenderer's rasterizer: for every pixel of the box, the weights
// from the inverse transpose of [x y 1] (recomputed at every pixel, as the
// original does), corrected for perspective, tested, depth-tested, shaded.
std::size_t rasterize(const dvec4 clip[3], IShader& shader, rl::Image& image,
                      std::vector<double>& zbuffer, rl::Grid<rl::vec3>* probe,
                      const dmat3& eye_to_world) {
    const int width = image.width(), height = image.height();
    dvec4 ndc[3];
    dvec2 screen[3];
    for (int k = 0; k < 3; ++k) {
        ndc[k] = clip[k] / clip[k].w;
        screen[k] = {(ndc[k].x + 1) * 0.5 * width, (ndc[k].y + 1) * 0.5 * height};
    }
    dmat3 abc;
    for (std::size_t k = 0; k < 3; ++k) abc[k] = {screen[k].x, screen[k].y, 1.0};
    if (rl::determinant(abc) < 1) return 0;  // a back face, or less than a pixel
    const auto [min_x, max_x] = std::minmax({screen[0].x, screen[1].x, screen[2].x});
    const auto [min_y, max_y] = std::minmax({screen[0].y, screen[1].y, screen[2].y});
    std::size_t fragments = 0;
    for (int x = std::max(static_cast<int>(min_x), 0);
         x <= std::min(static_cast<int>(max_x), width - 1); ++x)
        for (int y = std::max(static_cast<int>(min_y), 0);
             y <= std::min(static_cast<int>(max_y), height - 1); ++y) {
            const dmat3 weights = inverse_transpose(abc);
            const dvec3 bc_screen = weights * dvec3{x + 0.5, y + 0.5, 1.0};
            if (bc_screen.x < 0 || bc_screen.y < 0 || bc_screen.z < 0) continue;
            dvec3 bc_clip{bc_screen.x / clip[0].w, bc_screen.y / clip[1].w,
                          bc_screen.z / clip[2].w};
            bc_clip = bc_clip / (bc_clip.x + bc_clip.y + bc_clip.z);
            const double z = rl::dot(bc_screen, dvec3{ndc[0].z, ndc[1].z, ndc[2].z});
            double& nearest = zbuffer[static_cast<std::size_t>(x + y * width)];
            if (z >= nearest) continue;
            rl::Rgba colour;
            if (shader.fragment(bc_clip, colour)) continue;
            nearest = z;
            image.at(x, y) = colour;
            ++fragments;
            if (probe) probe->at(x, y) = rl::cast<float>(eye_to_world * shader.last_normal);
        }
    return fragments;
}

dvec3 texel(const rl::Image& image, dvec2 uv) {  // nearest
    const rl::Rgba c =
        image.get(std::clamp(static_cast<int>(uv.x * image.width()), 0, image.width() - 1),
                  std::clamp(static_cast<int>(uv.y * image.height()), 0, image.height() - 1));
    return {c.r / 255.0, c.g / 255.0, c.b / 255.0};
}

struct PhongShader : IShader {
    const rl::Mesh& mesh;
    const Textures& textures;
    dmat4 model_view, projection;
    dmat3 normal_matrix;                           // inverse transpose of model_view's 3x3
    dvec3 light;                                   // towards the light, eye space
    dvec3 varying_position[3], varying_normal[3];  // eye space
    dvec2 varying_uv[3];

    PhongShader(const rl::Mesh& m, const Textures& t, const dmat4& mv, const dmat4& p, dvec3 l)
        : mesh(m), textures(t), model_view(mv), projection(p) {
        dmat3 linear;
        for (std::size_t r = 0; r < 3; ++r) linear[r] = {mv[r][0], mv[r][1], mv[r][2]};
        normal_matrix = inverse_transpose(linear);
        light = rl::normalize(linear * l);
    }

    dvec4 vertex(int face, int corner) override {
        const rl::Corner& c =
            mesh.faces[static_cast<std::size_t>(face)].corners[static_cast<std::size_t>(corner)];
        const dvec4 eye = model_view * point(mesh.positions[static_cast<std::size_t>(c.position)]);
        varying_position[corner] = eye.xyz();
        varying_normal[corner] =
            normal_matrix * rl::cast<double>(mesh.normals[static_cast<std::size_t>(c.normal)]);
        varying_uv[corner] = rl::cast<double>(mesh.uvs[static_cast<std::size_t>(c.uv)]);
        return projection * eye;
    }

    bool fragment(dvec3 bar, rl::Rgba& colour) override {
        const dvec3 n = rl::normalize(varying_normal[0] * bar.x + varying_normal[1] * bar.y +
                                      varying_normal[2] * bar.z);
        const dvec2 uv = varying_uv[0] * bar.x + varying_uv[1] * bar.y + varying_uv[2] * bar.z;
        // The Darboux frame: T = U^-1 E from the triangle's edges E and UV
        // steps U, solved at every pixel as the original does.
        const dvec3 e1 = varying_position[1] - varying_position[0],
                    e2 = varying_position[2] - varying_position[0];
        const dvec2 u1 = varying_uv[1] - varying_uv[0], u2 = varying_uv[2] - varying_uv[0];
        const double det = u1.x * u2.y - u1.y * u2.x;
        dvec3 mapped = n;
        if (det != 0) {
            const dvec3 t = rl::normalize((e1 * u2.y - e2 * u1.y) / det);
            const dvec3 b = rl::normalize((e2 * u1.x - e1 * u2.x) / det);
            const dvec3 m = texel(*textures.normals, uv) * 2.0 - dvec3{1, 1, 1};
            mapped = rl::normalize(t * m.x + b * m.y + n * m.z);
        }
        last_normal = mapped;
        const dvec3 r = rl::normalize(mapped * (2 * rl::dot(mapped, light)) - light);
        const double diffuse = std::max(0.0, rl::dot(mapped, light));
        const double specular = std::pow(std::max(r.z, 0.0), 35);  // the viewer along +z
        const dvec3 albedo = texel(*textures.diffuse, uv);
        const double light_amount = 0.4 + diffuse + specular;
        const auto byte = [&](double c) {
            return static_cast<std::uint8_t>(std::min(255.0, c * 255.0 * light_amount));
        };
        colour = {byte(albedo.x), byte(albedo.y), byte(albedo.z), 255};
        return false;
    }
};

}  // namespace

Result render(const rl::Mesh& mesh, const Textures& textures, const pipeline::Camera& camera,
              rl::vec3 light, int width, int height, rl::Grid<rl::vec3>* normals) {
    Result out{rl::Image(width, height, rl::kBackground), 0};
    std::vector<double> zbuffer(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                                std::numeric_limits<double>::max());
    const dmat4 view = rl::cast<double>(*rl::look_at(camera.eye, camera.target, camera.up));
    const dmat4 projection = rl::cast<double>(
        rl::perspective(camera.fov_y, float(width) / float(height), camera.near, camera.far));
    PhongShader shader(mesh, textures, view, projection, rl::cast<double>(light));
    dmat3 eye_to_world;  // the view's rotation, undone (for the probe only)
    for (std::size_t r = 0; r < 3; ++r) eye_to_world[r] = {view[0][r], view[1][r], view[2][r]};
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        dvec4 clip[3];
        for (int k = 0; k < 3; ++k) clip[k] = shader.vertex(static_cast<int>(f), k);
        if (clip[0].w <= 0 || clip[1].w <= 0 || clip[2].w <= 0) continue;
        out.fragments += rasterize(clip, shader, out.image, zbuffer, normals, eye_to_world);
    }
    return out;
}

}  // namespace tinyrenderer_port
