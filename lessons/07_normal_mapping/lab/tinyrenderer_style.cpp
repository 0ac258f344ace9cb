#include "tinyrenderer_style.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rasterlab/transform.hpp"

namespace tinyrenderer_style {

namespace {

struct IShader {
    virtual ~IShader() = default;
    virtual rl::vec4 vertex(int face, int corner) = 0;
    virtual bool fragment(rl::vec3 bar, rl::Rgba& colour) = 0;  // true: discard
    rl::vec3 last_normal{};                                     // for the lab's probe
};

rl::vec3 barycentric(const rl::vec2 p[3], rl::vec2 q) {
    const rl::vec3 u = rl::cross(rl::vec3{p[2].x - p[0].x, p[1].x - p[0].x, p[0].x - q.x},
                                 rl::vec3{p[2].y - p[0].y, p[1].y - p[0].y, p[0].y - q.y});
    if (std::abs(u.z) < 1e-2f) return {-1, 1, 1};  // degenerate
    return {1 - (u.x + u.y) / u.z, u.y / u.z, u.x / u.z};
}

void triangle(const rl::vec4 clip[3], IShader& shader, rl::Image& image, rl::FloatImage& depth,
              rl::Grid<rl::vec3>* normals) {
    rl::vec2 pts[3];
    for (int k = 0; k < 3; ++k) {
        const rl::vec3 w =
            rl::ndc_to_window(clip[k].xyz() / clip[k].w, image.width(), image.height());
        pts[k] = w.xy();
    }
    const float x0 = std::max(0.0f, std::min({pts[0].x, pts[1].x, pts[2].x}));
    const float y0 = std::max(0.0f, std::min({pts[0].y, pts[1].y, pts[2].y}));
    const float x1 = std::min(image.width() - 1.0f, std::max({pts[0].x, pts[1].x, pts[2].x}));
    const float y1 = std::min(image.height() - 1.0f, std::max({pts[0].y, pts[1].y, pts[2].y}));
    for (int x = static_cast<int>(x0); x <= static_cast<int>(x1); ++x)
        for (int y = static_cast<int>(y0); y <= static_cast<int>(y1); ++y) {
            const rl::vec3 screen = barycentric(pts, {x + 0.5f, y + 0.5f});
            rl::vec3 bc{screen.x / clip[0].w, screen.y / clip[1].w, screen.z / clip[2].w};
            bc = bc / (bc.x + bc.y + bc.z);
            const float z = (clip[0].z / clip[0].w * screen.x + clip[1].z / clip[1].w * screen.y +
                             clip[2].z / clip[2].w * screen.z) *
                                0.5f +
                            0.5f;
            if (screen.x < 0 || screen.y < 0 || screen.z < 0 || !(z < depth.at(x, y))) continue;
            rl::Rgba colour;
            if (shader.fragment(bc, colour)) continue;
            depth.at(x, y) = z;
            image.at(x, y) = colour;
            if (normals) normals->at(x, y) = shader.last_normal;
        }
}

rl::vec3 texel(const rl::Image& image, rl::vec2 uv) {
    const int x = std::clamp(static_cast<int>(uv.x * image.width()), 0, image.width() - 1);
    const int y = std::clamp(static_cast<int>(uv.y * image.height()), 0, image.height() - 1);
    const rl::Rgba c = image.get(x, y);
    return rl::vec3{float(c.r), float(c.g), float(c.b)} / 255.0f;
}

struct PhongShader : IShader {
    const rl::Mesh& mesh;
    const Textures& textures;
    rl::mat4 view_projection;
    rl::vec3 eye, light;
    rl::vec3 varying_position[3], varying_normal[3];
    rl::vec2 varying_uv[3];

    PhongShader(const rl::Mesh& m, const Textures& t, rl::mat4 vp, rl::vec3 e, rl::vec3 l)
        : mesh(m), textures(t), view_projection(vp), eye(e), light(rl::normalize(l)) {}

    rl::vec4 vertex(int face, int corner) override {
        const rl::Face& f = mesh.faces[static_cast<std::size_t>(face)];
        const rl::Corner& c = f.corners[static_cast<std::size_t>(corner)];
        varying_position[corner] = mesh.positions[static_cast<std::size_t>(c.position)];
        varying_normal[corner] = mesh.normals[static_cast<std::size_t>(c.normal)];
        varying_uv[corner] = mesh.uvs[static_cast<std::size_t>(c.uv)];
        return view_projection * rl::extend(varying_position[corner], 1.0f);
    }

    bool fragment(rl::vec3 bar, rl::Rgba& colour) override {
        const rl::vec3 n = rl::normalize(varying_normal[0] * bar.x + varying_normal[1] * bar.y +
                                         varying_normal[2] * bar.z);
        const rl::vec2 uv = varying_uv[0] * bar.x + varying_uv[1] * bar.y + varying_uv[2] * bar.z;
        const rl::vec3 p =
            varying_position[0] * bar.x + varying_position[1] * bar.y + varying_position[2] * bar.z;
        // The tangent frame, solved here from the triangle's edges and UVs.
        rl::mat3 a;
        a[0] = varying_position[1] - varying_position[0];
        a[1] = varying_position[2] - varying_position[0];
        a[2] = n;
        const std::optional<rl::mat3> ai = rl::inverse(a);
        rl::vec3 mapped = n;
        if (ai) {
            const rl::vec3 i = *ai * rl::vec3{varying_uv[1].x - varying_uv[0].x,
                                              varying_uv[2].x - varying_uv[0].x, 0};
            const rl::vec3 j = *ai * rl::vec3{varying_uv[1].y - varying_uv[0].y,
                                              varying_uv[2].y - varying_uv[0].y, 0};
            const rl::vec3 m = texel(*textures.normals, uv) * 2.0f - rl::vec3{1, 1, 1};
            mapped = rl::normalize(rl::normalize(i) * m.x + rl::normalize(j) * m.y + n * m.z);
        }
        last_normal = mapped;
        const rl::vec3 r = rl::normalize(mapped * (2 * rl::dot(mapped, light)) - light);
        const float spec = std::pow(std::max(rl::dot(r, rl::normalize(eye - p)), 0.0f), 32.0f);
        const float diffuse = std::max(0.0f, rl::dot(mapped, light));
        const rl::vec3 c = texel(*textures.diffuse, uv) * (0.05f + diffuse + 0.35f * spec);
        const auto byte = [](float v) {
            return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f);
        };
        colour = {byte(c.x), byte(c.y), byte(c.z), 255};
        return false;
    }
};

}  // namespace

rl::Image render(const rl::Mesh& mesh, const Textures& textures, const perspective::Camera& camera,
                 rl::vec3 light, int width, int height, rl::Grid<rl::vec3>* normals) {
    rl::Image image(width, height, rl::kBackground);
    rl::FloatImage depth(width, height, std::numeric_limits<float>::max());
    PhongShader shader(mesh, textures,
                       perspective::view_projection(camera, float(width) / float(height)),
                       camera.eye, light);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        rl::vec4 clip[3];
        for (int k = 0; k < 3; ++k) clip[k] = shader.vertex(static_cast<int>(f), k);
        // tinyrenderer culls nothing and clips nothing; a vertex behind the
        // eye is skipped here only so that the comparison scene stays valid.
        if (clip[0].w <= 0 || clip[1].w <= 0 || clip[2].w <= 0) continue;
        triangle(clip, shader, image, depth, normals);
    }
    return image;
}

}  // namespace tinyrenderer_style
