#include "cube_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rasterlab/checkpoint.hpp"
#include "rasterlab/workers.hpp"

namespace environment {

// [doc:face-selection]
FacePoint face_point(rl::dvec3 d) {
    const double ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
    if (!(ax + ay + az > 0) || !std::isfinite(ax + ay + az)) return {Face::px, 0.5, 0.5};
    // (s, t): the other two components along the face's right and up, as
    // seen from inside the cube; m: the largest component's size.
    double s, t, m;
    Face face;
    if (ax >= ay && ax >= az) {
        face = d.x > 0 ? Face::px : Face::nx;
        s = d.x > 0 ? d.z : -d.z, t = d.y, m = ax;
    } else if (ay >= az) {
        face = d.y > 0 ? Face::py : Face::ny;
        s = d.x, t = d.y > 0 ? d.z : -d.z, m = ay;
    } else {
        face = d.z > 0 ? Face::pz : Face::nz;
        s = d.z > 0 ? -d.x : d.x, t = d.y, m = az;
    }
    return {face, 0.5 * (s / m + 1), 0.5 * (t / m + 1)};
}
// [/doc:face-selection]

rl::dvec3 face_direction(Face face, double u, double v) {
    const double a = 2 * u - 1, b = 2 * v - 1;
    switch (face) {
        case Face::px:
            return {1, b, a};
        case Face::nx:
            return {-1, b, -a};
        case Face::py:
            return {a, 1, b};
        case Face::ny:
            return {a, -1, -b};
        case Face::pz:
            return {-a, b, 1};
        case Face::nz:
            return {a, b, -1};
    }
    return {1, 0, 0};
}

namespace {

int square_size(const std::array<rl::HdrImage, 6>& faces) {
    const int size = faces[0].width();
    for (const rl::HdrImage& f : faces)
        if (f.width() != size || f.height() != size || size < 1)
            throw std::invalid_argument("a cube map's six faces must be squares of one size, not " +
                                        std::to_string(f.width()) + "x" +
                                        std::to_string(f.height()) + " beside " +
                                        std::to_string(size));
    return size;
}

std::array<textures::HdrMipChain, 6> chains(std::array<rl::HdrImage, 6> faces) {
    return {textures::HdrMipChain(std::move(faces[0])), textures::HdrMipChain(std::move(faces[1])),
            textures::HdrMipChain(std::move(faces[2])), textures::HdrMipChain(std::move(faces[3])),
            textures::HdrMipChain(std::move(faces[4])), textures::HdrMipChain(std::move(faces[5]))};
}

rl::vec3 rgb(rl::vec4 texel) {
    return {texel.x, texel.y, texel.z};
}

}  // namespace

CubeMap::CubeMap(std::array<rl::HdrImage, 6> faces)
    : size_(square_size(faces)), faces_(chains(std::move(faces))) {}

rl::vec3 CubeMap::nearest(Face f, int level, double u, double v) const {
    const rl::HdrImage& image = face(f).level(level);
    const int n = image.width();
    const int i = std::clamp(static_cast<int>(std::floor(u * n)), 0, n - 1);
    const int j = std::clamp(static_cast<int>(std::floor(v * n)), 0, n - 1);
    return rgb(image.get(i, j));
}

rl::vec3 CubeMap::per_face(Face f, int level, double u, double v) const {
    textures::SamplerState clamped;
    clamped.wrap = textures::Wrap::clamp;
    return rgb(textures::sample_level(
        face(f).level(level), {static_cast<float>(u), static_cast<float>(v)}, true, clamped));
}

// Bilinear across the faces' edges: a tap that falls off the face is the
// texel of the neighbouring face that its centre's direction points into.
// [doc:seamless]
rl::vec3 CubeMap::seamless(Face f, int level, double u, double v) const {
    const rl::HdrImage& image = face(f).level(level);
    const int n = image.width();
    const double x = u * n - 0.5, y = v * n - 0.5;
    const int i0 = static_cast<int>(std::floor(x)), j0 = static_cast<int>(std::floor(y));
    const double fx = x - i0, fy = y - j0;
    rl::dvec3 sum{0, 0, 0};
    for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
            const int i = i0 + di, j = j0 + dj;
            const double weight = (di ? fx : 1 - fx) * (dj ? fy : 1 - fy);
            rl::vec3 texel;
            if (i >= 0 && i < n && j >= 0 && j < n) {
                texel = rgb(image.get(i, j));
            } else {
                const FacePoint p = face_point(face_direction(f, (i + 0.5) / n, (j + 0.5) / n));
                texel = nearest(p.face, level, p.u, p.v);
            }
            sum += rl::cast<double>(texel) * weight;
        }
    return rl::cast<float>(sum);
}
// [/doc:seamless]

rl::vec3 CubeMap::sample(rl::vec3 direction, MapFilter filter, float level) const {
    const FacePoint p = face_point(rl::cast<double>(direction));
    switch (filter) {
        case MapFilter::nearest:
            return nearest(p.face, 0, p.u, p.v);
        case MapFilter::bilinear:
            return per_face(p.face, 0, p.u, p.v);
        case MapFilter::seamless:
            return seamless(p.face, 0, p.u, p.v);
        case MapFilter::trilinear: {
            const float top = static_cast<float>(levels() - 1);
            const float l = std::isfinite(level) ? std::clamp(level, 0.0f, top) : 0.0f;
            const int l0 = static_cast<int>(l);
            const float t = l - static_cast<float>(l0);
            const rl::vec3 a = seamless(p.face, l0, p.u, p.v);
            if (t == 0) return a;
            return a * (1 - t) + seamless(p.face, l0 + 1, p.u, p.v) * t;
        }
    }
    return {0, 0, 0};
}

CubeMap cube_map(const std::function<rl::dvec3(rl::dvec3)>& radiance, int size, int samples) {
    if (size < 1 || size > 8192 || samples < 1 || samples > 64)
        throw std::invalid_argument("a cube map face of " + std::to_string(size) +
                                    " texels (1 to 8192), " + std::to_string(samples) +
                                    " samples a side (1 to 64)");
    std::array<rl::HdrImage, 6> faces;
    for (rl::HdrImage& face : faces) face = rl::HdrImage(size, size);
    // Every texel is its own sum, so rows go to both cores in any order and
    // the map is the same: `radiance` must be safe to call from two threads.
    // A checkpoint a row: a host's Ctrl-C stops a 2048² map within a row.
    rl::parallel_for(0, 6 * size, [&](int row) {
        rl::checkpoint();
        const Face f = kFaces[static_cast<std::size_t>(row / size)];
        const int j = row % size;
        rl::HdrImage& image = faces[static_cast<std::size_t>(f)];
        for (int i = 0; i < size; ++i) {
            rl::dvec3 sum{0, 0, 0};
            for (int b = 0; b < samples; ++b)
                for (int a = 0; a < samples; ++a)
                    sum += radiance(face_direction(f, (i + (a + 0.5) / samples) / size,
                                                   (j + (b + 0.5) / samples) / size));
            const rl::vec3 mean = rl::cast<float>(sum / static_cast<double>(samples * samples));
            image.set(i, j, {mean.x, mean.y, mean.z, 1});
        }
    });
    return CubeMap(std::move(faces));
}

CubeMap cube_map(Analytic which, int size, int samples) {
    return cube_map([which](rl::dvec3 d) { return radiance(which, d); }, size, samples);
}

}  // namespace environment
