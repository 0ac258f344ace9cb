#include "irradiance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rasterlab/checkpoint.hpp"
#include "sphere_sampling.hpp"

namespace environment {

namespace {

constexpr double kPi = std::numbers::pi;

rl::dvec3 unit_or_up(rl::vec3 n) {
    const rl::dvec3 d = rl::cast<double>(n);
    const double length = rl::length(d);
    return length > 0 && std::isfinite(length) ? d / length : rl::dvec3{0, 1, 0};
}

// The area of the unit-distance face plane's rectangle [0, x] x [0, y] as
// seen from the cube's centre: atan(x y / sqrt(x^2 + y^2 + 1)).
double corner_angle(double x, double y) {
    return std::atan2(x * y, std::sqrt(x * x + y * y + 1));
}

}  // namespace

std::array<double, 9> sh_basis(rl::dvec3 d) {
    const double x = d.x, y = d.y, z = d.z;
    return {0.282094791773878,
            0.488602511902920 * y,
            0.488602511902920 * z,
            0.488602511902920 * x,
            1.092548430592079 * x * y,
            1.092548430592079 * y * z,
            0.315391565252520 * (3 * z * z - 1),
            1.092548430592079 * x * z,
            0.546274215296040 * (x * x - y * y)};
}

double texel_solid_angle(int i, int j, int size) {
    const double x0 = 2.0 * i / size - 1, x1 = 2.0 * (i + 1) / size - 1;
    const double y0 = 2.0 * j / size - 1, y1 = 2.0 * (j + 1) / size - 1;
    return corner_angle(x1, y1) - corner_angle(x0, y1) - corner_angle(x1, y0) +
           corner_angle(x0, y0);
}

ShLight project_sh(const CubeMap& cube, int order) {
    if (order < 1 || order > 3)
        throw std::invalid_argument("spherical harmonics of order " + std::to_string(order) +
                                    ": 1, 2 or 3");
    ShLight sh;
    sh.order = order;
    const int count = order * order, n = cube.size();
    for (Face f : kFaces) {
        const rl::HdrImage& image = cube.face(f).level(0);
        for (int j = 0; j < n; ++j) {
            rl::checkpoint();  // a host's Ctrl-C, between rows
            for (int i = 0; i < n; ++i) {
                const rl::dvec3 d = rl::normalize(face_direction(f, (i + 0.5) / n, (j + 0.5) / n));
                const rl::vec4 t = image.get(i, j);
                const rl::dvec3 light = rl::dvec3{t.x, t.y, t.z} * texel_solid_angle(i, j, n);
                const std::array<double, 9> y = sh_basis(d);
                for (int k = 0; k < count; ++k) sh.coefficients[k] += light * y[k];
            }
        }
    }
    return sh;
}

// [doc:sh-irradiance]
rl::vec3 irradiance(const ShLight& sh, rl::vec3 normal) {
    // The cosine window's band weights (Ramamoorthi and Hanrahan, 2001).
    constexpr double band[3] = {kPi, 2 * kPi / 3, kPi / 4};
    const std::array<double, 9> y = sh_basis(unit_or_up(normal));
    rl::dvec3 e{0, 0, 0};
    for (int k = 0; k < sh.order * sh.order; ++k) {
        const int l = k == 0 ? 0 : k < 4 ? 1 : 2;
        e += sh.coefficients[k] * (band[l] * y[k]);
    }
    return {static_cast<float>(std::max(e.x, 0.0)), static_cast<float>(std::max(e.y, 0.0)),
            static_cast<float>(std::max(e.z, 0.0))};
}
// [/doc:sh-irradiance]

CubeMap irradiance_map(const CubeMap& source, int size) {
    if (size < 1 || size > 256)
        throw std::invalid_argument("an irradiance map of " + std::to_string(size) +
                                    " texels a side (1 to 256)");
    int level = 0;
    while (source.face(Face::px).level(level).width() > 32 && level + 1 < source.levels()) ++level;
    const int n = source.face(Face::px).level(level).width();
    struct Texel {
        rl::dvec3 direction, light;  // light already times the texel's solid angle
    };
    std::vector<Texel> texels;
    texels.reserve(static_cast<std::size_t>(6 * n * n));
    for (Face f : kFaces) {
        const rl::HdrImage& image = source.face(f).level(level);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const rl::vec4 t = image.get(i, j);
                texels.push_back({rl::normalize(face_direction(f, (i + 0.5) / n, (j + 0.5) / n)),
                                  rl::dvec3{t.x, t.y, t.z} * texel_solid_angle(i, j, n)});
            }
    }
    std::array<rl::HdrImage, 6> faces;
    for (Face f : kFaces) {
        rl::HdrImage image(size, size);
        for (int j = 0; j < size; ++j) {
            rl::checkpoint();  // a host's Ctrl-C, between rows
            for (int i = 0; i < size; ++i) {
                const rl::dvec3 normal =
                    rl::normalize(face_direction(f, (i + 0.5) / size, (j + 0.5) / size));
                rl::dvec3 e{0, 0, 0};
                for (const Texel& t : texels) {
                    const double c = rl::dot(normal, t.direction);
                    if (c > 0) e += t.light * c;
                }
                image.set(
                    i, j,
                    {static_cast<float>(e.x), static_cast<float>(e.y), static_cast<float>(e.z), 1});
            }
        }
        faces[static_cast<std::size_t>(f)] = std::move(image);
    }
    return CubeMap(std::move(faces));
}

rl::vec3 irradiance_monte_carlo(const std::function<rl::vec3(rl::vec3)>& source, rl::vec3 normal,
                                int samples, std::uint32_t seed) {
    const rl::dvec3 n = unit_or_up(normal);
    const Frame frame(n);
    rl::dvec3 sum{0, 0, 0};
    const int count = std::max(samples, 1);
    for (int s = 0; s < count; ++s) {
        // [doc:cosine-sample]
        // Cosine-distributed: a uniform point on the unit disc, lifted onto
        // the hemisphere (Malley's method); its pdf cos / pi cancels the cosine.
        const std::uint32_t h = hash(seed ^ hash(static_cast<std::uint32_t>(s)));
        const double r = std::sqrt(unit_interval(h)), phi = 2 * kPi * unit_interval(hash(h));
        const double x = r * std::cos(phi), y = r * std::sin(phi);
        const rl::dvec3 d = frame.to_world({x, y, std::sqrt(std::max(0.0, 1 - x * x - y * y))});
        sum += rl::cast<double>(source(rl::cast<float>(d)));
    }
    return rl::cast<float>(sum * (kPi / count));  // each sample worth pi / N
    // [/doc:cosine-sample]
}

DiffuseLight::DiffuseLight(const std::function<rl::vec3(rl::vec3)>& environment, Irradiance method,
                           int samples)
    : method_(method), samples_(samples), environment_(environment) {
    if (samples < 1 || samples > kMaxIrradianceSamples)
        throw std::invalid_argument("--samples: " + std::to_string(samples) + " is outside 1 to " +
                                    std::to_string(kMaxIrradianceSamples));
    if (method == Irradiance::monte_carlo) return;
    const CubeMap cube = cube_map(
        [&](rl::dvec3 d) { return rl::cast<double>(environment(rl::cast<float>(d))); }, 64, 1);
    switch (method) {
        case Irradiance::sh1:
            sh_ = project_sh(cube, 1);
            break;
        case Irradiance::sh2:
            sh_ = project_sh(cube, 2);
            break;
        case Irradiance::sh3:
            sh_ = project_sh(cube, 3);
            break;
        case Irradiance::convolved:
            convolved_ = irradiance_map(cube, 16);
            break;
        case Irradiance::monte_carlo:
            break;
    }
}

rl::vec3 DiffuseLight::at(rl::vec3 normal, std::uint32_t seed) const {
    switch (method_) {
        case Irradiance::convolved:
            return convolved_->sample(normal, MapFilter::seamless);
        case Irradiance::monte_carlo:
            return irradiance_monte_carlo(environment_, normal, samples_, seed);
        default:
            return irradiance(sh_, normal);
    }
}

}  // namespace environment
