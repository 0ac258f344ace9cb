#include "sphere_truth.hpp"

#include "05_perspective/truths/ray_truth.hpp"

#include <cmath>
#include <numbers>

namespace shading {

rl::Mesh uv_sphere(int segments) {
    rl::Mesh mesh;
    segments = std::max(3, segments);
    const int rings = std::max(2, segments / 2);
    // Positions (and their exact normals) are shared around the seam and at
    // the poles, as in an OBJ file; texture coordinates are not.
    const auto position = [&](int i, int j) {
        if (j == 0) return 0;
        if (j == rings) return 1 + (rings - 1) * segments;
        return 1 + (j - 1) * segments + i % segments;
    };
    for (int j = 0; j <= rings; ++j)
        for (int i = 0; i < ((j == 0 || j == rings) ? 1 : segments); ++i) {
            const double theta = std::numbers::pi * j / rings;  // from the north pole
            const double phi = 2 * std::numbers::pi * i / segments;
            const rl::vec3 p{static_cast<float>(std::sin(theta) * std::cos(phi)),
                             static_cast<float>(std::cos(theta)),
                             static_cast<float>(-std::sin(theta) * std::sin(phi))};
            mesh.positions.push_back(p);
            mesh.normals.push_back(p);
        }
    for (int j = 0; j <= rings; ++j)
        for (int i = 0; i <= segments; ++i)
            mesh.uvs.push_back({float(i) / segments, 1.0f - float(j) / rings});
    const auto corner = [&](int i, int j) {
        const int p = position(i, j);
        return rl::Corner{p, j * (segments + 1) + i, p};
    };
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const rl::Corner a = corner(i, j), b = corner(i, j + 1), c = corner(i + 1, j + 1),
                             d = corner(i + 1, j);
            // Counter-clockwise seen from outside; the poles' degenerate halves are left out.
            if (j != 0) mesh.faces.push_back({{a, b, d}, -1});
            if (j != rings - 1) mesh.faces.push_back({{b, c, d}, -1});
        }
    return mesh;
}

NormalError sphere_normal_error(const rl::Mesh& sphere, const std::vector<rl::vec3>& normals) {
    NormalError e;
    for (std::size_t i = 0; i < normals.size(); ++i) {
        const rl::dvec3 truth = rl::normalize(rl::cast<double>(sphere.positions[i]));
        const double c =
            std::clamp(rl::dot(truth, rl::normalize(rl::cast<double>(normals[i]))), -1.0, 1.0);
        const double degrees = std::acos(c) * 180 / std::numbers::pi;
        e.mean += degrees;
        e.max = std::max(e.max, degrees);
    }
    if (!normals.empty()) e.mean /= static_cast<double>(normals.size());
    return e;
}

rl::Image sphere_truth(const pipeline::Camera& camera, int width, int height,
                       const Lighting<float>& lighting, rl::vec3 albedo, Specular specular,
                       rl::Rgba background) {
    Lighting<double> l;
    for (const Light<float>& light : lighting.lights)
        l.lights.push_back({rl::cast<double>(light.direction), rl::cast<double>(light.colour)});
    l.ambient = rl::cast<double>(lighting.ambient);
    l.specular = rl::cast<double>(lighting.specular);
    l.shininess = lighting.shininess;
    const pipeline::RayCamera rays(camera, width, height);  // lesson 05's pixel rays
    const rl::dvec3 eye = rays.eye();
    rl::Image out(width, height, background);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const rl::dvec3 d = rl::normalize(rays.direction(x + 0.5, y + 0.5));
            // |eye + t d|^2 = 1: t^2 + 2 (eye . d) t + |eye|^2 - 1 = 0.
            const double b = rl::dot(eye, d), c = rl::dot(eye, eye) - 1;
            const double disc = b * b - c;
            if (disc < 0) continue;
            const double t = -b - std::sqrt(disc);
            if (t <= 0) continue;
            const rl::dvec3 p = eye + d * t;  // on the unit sphere: the normal is p
            const Colour<double> c_lin =
                reflected(l, rl::normalize(p), -d, rl::cast<double>(albedo), specular);
            const auto byte = [](double v) {
                return static_cast<std::uint8_t>(std::lround(linear_to_srgb(v) * 255));
            };
            out.at(x, y) = {byte(c_lin.x), byte(c_lin.y), byte(c_lin.z), 255};
        }
    return out;
}

SphereError compare_spheres(const rl::Image& truth, const rl::Image& image, rl::Rgba background) {
    SphereError e;
    double all = 0, inside = 0;
    for (int y = 0; y < truth.height(); ++y)
        for (int x = 0; x < truth.width(); ++x) {
            const rl::Rgba a = truth.get(x, y), b = image.get(x, y);
            const bool in_a = !(a == background), in_b = !(b == background);
            if (!in_a && !in_b) continue;
            double sq = 0;
            for (int d : {a.r - b.r, a.g - b.g, a.b - b.b}) sq += double(d) * d;
            all += sq;
            ++e.pixels;
            if (in_a && in_b) {
                inside += sq;
                ++e.interior;
            }
        }
    e.rmse = e.pixels ? std::sqrt(all / (3.0 * e.pixels)) : 0.0;
    e.interior_rmse = e.interior ? std::sqrt(inside / (3.0 * e.interior)) : 0.0;
    return e;
}

}  // namespace shading
