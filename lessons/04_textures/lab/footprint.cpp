#include "footprint.hpp"

#include <cmath>
#include <numbers>

namespace textures {

AffineScene magnification_scene(const rl::Image& texture, int size) {
    const double angle = 20.0 * std::numbers::pi / 180.0, texels_per_pixel = 1.0 / 8.0;
    const double u = texels_per_pixel / texture.width(), v = texels_per_pixel / texture.height();
    return {{0.1f, 0.05f},
            {static_cast<float>(u * std::cos(angle)), static_cast<float>(v * std::sin(angle))},
            {static_cast<float>(-u * std::sin(angle)), static_cast<float>(v * std::cos(angle))},
            size};
}

AffineScene minification_scene(const rl::Image& texture, int size) {
    const double u = 24.0 / texture.width(),
                 v = 24.0 / texture.height();  // 24 texels per pixel ...
    return {
        {0.3f, 0.7f},
        {static_cast<float>(u), static_cast<float>(0.25 * v)},
        {static_cast<float>(0.6 * u), static_cast<float>(1.3 * v)},  // ... sheared and stretched
        size};
}

namespace {

// The texel under (u, v) with repeat wrap, texels taken as constant squares.
rl::Rgba square_texel(const rl::Image& texture, double u, double v) {
    const int w = texture.width(), h = texture.height();
    const int tx = static_cast<int>(std::floor((u - std::floor(u)) * w)) % w;
    const int ty = static_cast<int>(std::floor((v - std::floor(v)) * h)) % h;
    return texture.get(tx, ty);
}

}  // namespace

// [doc:footprint-average]
rl::Image footprint_average(const rl::Image& texture, const AffineScene& scene, int n) {
    rl::Image out(scene.size, scene.size);
    for (int y = 0; y < scene.size; ++y)
        for (int x = 0; x < scene.size; ++x) {
            double sum[3] = {0, 0, 0};
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const double px = x + (i + 0.5) / n, py = y + (j + 0.5) / n;
                    const double u = scene.origin.x + px * scene.du.x + py * scene.dv.x;
                    const double v = scene.origin.y + px * scene.du.y + py * scene.dv.y;
                    const rl::Rgba c = square_texel(texture, u, v);
                    sum[0] += c.r, sum[1] += c.g, sum[2] += c.b;
                }
            const double count = double(n) * n;
            auto byte = [&](double s) { return static_cast<std::uint8_t>(std::lround(s / count)); };
            out.set(x, y, {byte(sum[0]), byte(sum[1]), byte(sum[2]), 255});
        }
    return out;
}
// [/doc:footprint-average]

MeshFootprint mesh_footprint_average(const rl::Mesh& mesh, const rl::Image& texture,
                                     const TexturedOptions& options, int size, int n) {
    // Every face rasterized at n x n samples per pixel, depth-tested, keeping
    // the face and the (exactly affine) texture coordinate of each sample.
    const int fine = size * n;
    rl::FloatImage depth(fine, fine, 1.0f);
    rl::Grid<int> face_at(fine, fine, -1);
    rl::Grid<rl::vec2> uv_at(fine, fine, rl::vec2{});
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const TexturedFace face = textured_face(mesh, mesh.faces[f], options, size, size);
        if (!face.front) continue;
        triangles::ScreenTriangle sub_pixels = face.screen();
        for (rl::vec2& p : sub_pixels.v) p = p * static_cast<float>(n);
        triangles::rasterize_edge(sub_pixels, fine, fine, [&](int x, int y, rl::vec3 b) {
            const float z =
                zbuffer::interpolate_depth(b, face.window[0].z, face.window[1].z, face.window[2].z);
            if (!zbuffer::test_and_store_depth(depth, x, y, z)) return;
            face_at.at(x, y) = static_cast<int>(f);
            uv_at.at(x, y) = triangles::interpolate(b, face.uv[0], face.uv[1], face.uv[2]);
        });
    }
    MeshFootprint out{rl::Image(size, size), rl::Grid<std::uint8_t>(size, size, 0), 0};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const int first = face_at.get(x * n, y * n);
            bool one_face = first >= 0, any_face = false;
            double sum[3] = {0, 0, 0};
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const int f = face_at.get(x * n + i, y * n + j);
                    any_face |= f >= 0;
                    one_face &= f == first;
                    const rl::vec2 uv = uv_at.get(x * n + i, y * n + j);
                    const rl::Rgba c = square_texel(texture, uv.x, uv.y);
                    sum[0] += c.r, sum[1] += c.g, sum[2] += c.b;
                }
            out.covered += any_face;
            if (!one_face) continue;
            const double count = double(n) * n;
            auto byte = [&](double s) { return static_cast<std::uint8_t>(std::lround(s / count)); };
            out.average.set(x, y, {byte(sum[0]), byte(sum[1]), byte(sum[2]), 255});
            out.scored.at(x, y) = 1;
        }
    return out;
}

rl::Image render_scene(const MipChain& texture, const AffineScene& scene,
                       const SamplerState& state) {
    rl::Image out(scene.size, scene.size);
    const UvDerivatives d = scene.derivatives();
    for (int y = 0; y < scene.size; ++y)
        for (int x = 0; x < scene.size; ++x)
            out.set(x, y, to_rgba(sample(texture, scene.uv_at(x + 0.5, y + 0.5), d, state)));
    return out;
}

}  // namespace textures
