#include "sphere_truth.hpp"

#include <cmath>
#include <numbers>

namespace shading {

rl::Mesh uv_sphere(int segments) {
    rl::Mesh mesh;
    const int rings = std::max(2, segments / 2);
    segments = std::max(3, segments);
    for (int j = 0; j <= rings; ++j)
        for (int i = 0; i <= segments; ++i) {
            const double theta = std::numbers::pi * j / rings;  // from the north pole
            const double phi = 2 * std::numbers::pi * i / segments;
            const rl::vec3 p{static_cast<float>(std::sin(theta) * std::cos(phi)),
                             static_cast<float>(std::cos(theta)),
                             static_cast<float>(-std::sin(theta) * std::sin(phi))};
            mesh.positions.push_back(p);
            mesh.normals.push_back(p);
            mesh.uvs.push_back({float(i) / segments, 1.0f - float(j) / rings});
        }
    const auto at = [&](int i, int j) { return j * (segments + 1) + i; };
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const int a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
            const auto corner = [](int k) { return rl::Corner{k, k, k}; };
            // Counter-clockwise seen from outside; the pole rows' degenerate halves are left out.
            if (j != 0) mesh.faces.push_back({{corner(a), corner(b), corner(d)}, -1});
            if (j != rings - 1) mesh.faces.push_back({{corner(b), corner(c), corner(d)}, -1});
        }
    return mesh;
}

rl::Image sphere_truth(const perspective::Camera& camera, int width, int height,
                       const Lighting<float>& lighting, rl::vec3 albedo, Specular specular,
                       rl::Rgba background) {
    Lighting<double> l;
    for (const Light<float>& light : lighting.lights)
        l.lights.push_back({rl::cast<double>(light.direction), rl::cast<double>(light.colour)});
    l.ambient = rl::cast<double>(lighting.ambient);
    l.specular = rl::cast<double>(lighting.specular);
    l.shininess = lighting.shininess;
    const rl::dvec3 eye = rl::cast<double>(camera.eye);
    const rl::dvec3 forward = rl::normalize(rl::cast<double>(camera.target) - eye);
    const rl::dvec3 right = rl::normalize(rl::cross(forward, rl::cast<double>(camera.up)));
    const rl::dvec3 up = rl::cross(right, forward);
    const double tan_y = std::tan(camera.fov_y * std::numbers::pi / 360.0);
    const double tan_x = tan_y * width / height;
    rl::Image out(width, height, background);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double nx = (x + 0.5) / width * 2 - 1, ny = (y + 0.5) / height * 2 - 1;
            const rl::dvec3 d = rl::normalize(forward + right * (nx * tan_x) + up * (ny * tan_y));
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
