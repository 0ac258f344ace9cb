#include "ray_truth.hpp"

#include <cmath>
#include <limits>

#include "03_zbuffer/hidden_surfaces.hpp"
#include "rasterlab/random.hpp"

namespace pipeline {

namespace {

rl::dvec3 to_double(rl::vec3 v) {
    return rl::cast<double>(v);
}

}  // namespace

RayCamera::RayCamera(const Camera& camera, int width, int height)
    : eye_(to_double(camera.eye)),
      near_(camera.near),
      far_(camera.far),
      width_(width),
      height_(height) {
    forward_ = rl::normalize(to_double(camera.target) - eye_);
    right_ = rl::normalize(rl::cross(forward_, to_double(camera.up)));
    up_ = rl::cross(right_, forward_);
    tan_y_ = std::tan(static_cast<double>(camera.fov_y) * 3.14159265358979323846 / 360.0);
    tan_x_ = tan_y_ * static_cast<double>(width) / static_cast<double>(height);
}

rl::dvec3 RayCamera::direction(double x, double y) const {
    const double ndc_x = x / width_ * 2 - 1, ndc_y = y / height_ * 2 - 1;
    return forward_ + right_ * (ndc_x * tan_x_) + up_ * (ndc_y * tan_y_);
}

// [doc:ray-triangle]
// Moeller-Trumbore: solve eye + t d = p0 + b1 (p1 - p0) + b2 (p2 - p0).
std::optional<Hit> intersect(const WorldTriangle& t, rl::dvec3 eye, rl::dvec3 d) {
    const rl::dvec3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0];
    const rl::dvec3 q = rl::cross(d, e2);
    const double det = rl::dot(e1, q);
    if (det == 0) return std::nullopt;  // the ray runs along the plane
    const rl::dvec3 s = eye - t.p[0];
    const double b1 = rl::dot(s, q) / det;
    const rl::dvec3 r = rl::cross(s, e1);
    const double b2 = rl::dot(d, r) / det;
    if (b1 < 0 || b2 < 0 || b1 + b2 > 1) return std::nullopt;
    return Hit{rl::dot(e2, r) / det, {1 - b1 - b2, b1, b2}};
}
// [/doc:ray-triangle]

rl::Grid<int> exact_ids(const std::vector<WorldTriangle>& scene, const RayCamera& rays) {
    rl::Grid<int> ids(rays.width(), rays.height(), -1);
    for (int y = 0; y < rays.height(); ++y)
        for (int x = 0; x < rays.width(); ++x) {
            const rl::dvec3 d = rays.direction(x + 0.5, y + 0.5);
            double nearest = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < scene.size(); ++i) {
                const WorldTriangle& t = scene[i];
                const rl::dvec3 normal = rl::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
                if (!(rl::dot(normal, rays.eye() - t.p[0]) > 0)) continue;  // a back face
                const std::optional<Hit> hit = intersect(t, rays.eye(), d);
                if (hit && hit->depth >= rays.near() && hit->depth <= rays.far() &&
                    hit->depth < nearest) {
                    nearest = hit->depth;
                    ids.at(x, y) = static_cast<int>(i);
                }
            }
        }
    return ids;
}

WorldTarget world_target(int width, int height) {
    return WorldTarget(width, height, {}, -1, rl::vec2{NAN, NAN});
}

rl::Grid<int> pipeline_ids(const std::vector<WorldTriangle>& scene, const Camera& camera, int width,
                           int height, const PipelineOptions& options, PipelineCounts* counts) {
    WorldTarget target = world_target(width, height);
    const rl::mat4 vp =
        view_projection(camera, static_cast<float>(width) / static_cast<float>(height));
    const PipelineCounts local = draw(WorldScene{&scene}, WorldProgram{vp}, target, options);
    if (counts) *counts += local;
    return target.colour<0>();
}

IdDifference compare_ids(const rl::Grid<int>& truth, const rl::Grid<int>& ids) {
    IdDifference d;
    for (int y = 0; y < truth.height(); ++y)
        for (int x = 0; x < truth.width(); ++x) {
            const int a = truth.get(x, y), b = ids.get(x, y);
            d.covered += (a >= 0 || b >= 0);
            d.wrong += a != b;
        }
    return d;
}

std::vector<WorldTriangle> triangles_around(const Camera& camera, int count, unsigned seed,
                                            double extent) {
    rl::SplitMix64 random(seed);
    const rl::dvec3 eye = to_double(camera.eye);
    std::vector<WorldTriangle> scene;
    while (static_cast<int>(scene.size()) < count) {
        WorldTriangle t;
        const rl::dvec3 centre{random.uniform(-extent, extent), random.uniform(-extent, extent),
                               random.uniform(-extent, extent)};
        for (int k = 0; k < 3; ++k) {
            t.p[k] =
                eye + centre +
                rl::dvec3{random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)} *
                    (extent * 0.6);
            t.uv[k] = {random.uniform(), random.uniform()};
        }
        const rl::dvec3 normal = rl::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
        const double facing = rl::dot(normal, eye - t.p[0]);
        if (std::abs(facing) < 1e-6) continue;
        if (facing < 0) {  // turn it to face the eye
            std::swap(t.p[1], t.p[2]);
            std::swap(t.uv[1], t.uv[2]);
        }
        scene.push_back(t);
    }
    return scene;
}

}  // namespace pipeline
