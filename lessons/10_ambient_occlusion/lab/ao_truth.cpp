#include "ao_truth.hpp"

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "05_perspective/lab/ray_truth.hpp"
#include "09_environment/sphere_sampling.hpp"

namespace occlusion {

struct RayTracedAo::Scene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<rl::dvec3> normals;  // 3 per triangle, world space
    double offset = 1e-6;            // off the surface, for rays leaving it
};

RayTracedAo::RayTracedAo(const std::vector<normal_mapping::MappedModel>& models)
    : scene_(std::make_unique<Scene>()) {
    Scene& s = *scene_;
    std::vector<float> positions;
    for (const normal_mapping::MappedModel& m : models) {
        const rl::Mesh& mesh = m.lit.model.mesh;
        const rl::mat4& transform = m.lit.model.transform;
        const rl::mat3 to_world = shading::normal_matrix(transform).value_or(rl::mat3::identity());
        for (std::size_t f = 0; f < mesh.faces.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                const rl::vec3 p =
                    (transform * rl::extend(mesh.position(mesh.faces[f], k), 1.0f)).xyz();
                positions.insert(positions.end(), {p.x, p.y, p.z});
                s.normals.push_back(rl::normalize(rl::cast<double>(
                    to_world * m.lit.normals[3 * f + static_cast<std::size_t>(k)])));
            }
    }
    const perspective::Box box = normal_mapping::scene_box(models);
    if (!box.empty())
        s.offset = 1e-6 * std::max(1.0, static_cast<double>(rl::length(box.max - box.min)));
    s.device = rtcNewDevice(nullptr);
    if (!s.device) throw std::runtime_error("Embree could not start a device");
    s.scene = rtcNewScene(s.device);
    const std::size_t corners = positions.size() / 3;
    if (corners > 0) {
        RTCGeometry geometry = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), corners));
        auto* indices = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), corners / 3));
        std::copy(positions.begin(), positions.end(), vertices);
        for (std::size_t i = 0; i < corners; ++i) indices[i] = static_cast<unsigned>(i);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(s.scene, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(s.scene);
}

RayTracedAo::~RayTracedAo() {
    if (scene_->scene) rtcReleaseScene(scene_->scene);
    if (scene_->device) rtcReleaseDevice(scene_->device);
}

namespace {

RTCRay ray_of(rl::dvec3 origin, rl::dvec3 d, double t_near, double t_far) {
    RTCRay r{};
    r.org_x = static_cast<float>(origin.x), r.org_y = static_cast<float>(origin.y);
    r.org_z = static_cast<float>(origin.z);
    r.dir_x = static_cast<float>(d.x), r.dir_y = static_cast<float>(d.y);
    r.dir_z = static_cast<float>(d.z);
    r.tnear = static_cast<float>(t_near), r.tfar = static_cast<float>(t_far);
    r.mask = 0xFFFFFFFFu;
    return r;
}

}  // namespace

// [doc:ao-truth]
double RayTracedAo::at(rl::dvec3 p, rl::dvec3 n, double radius, int rays,
                       std::uint32_t seed) const {
    const environment::Frame frame(n);
    const rl::dvec3 origin = p + n * scene_->offset;
    // One random shift of the whole stratified set per point (Cranley and
    // Patterson): no two points share their directions.
    const rl::dvec2 shift{environment::unit_interval(environment::hash(seed)),
                          environment::unit_interval(environment::hash(seed ^ 0x9e3779b9u))};
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    int open = 0;
    const auto count = static_cast<std::uint32_t>(std::max(rays, 1));
    for (std::uint32_t i = 0; i < count; ++i) {
        rl::dvec2 u = environment::hammersley(i, count) + shift;
        u = {u.x - std::floor(u.x), u.y - std::floor(u.y)};
        // Cosine-weighted: a point of the unit disc lifted onto the hemisphere.
        const double r = std::sqrt(u.x), phi = 2 * std::numbers::pi * u.y;
        const rl::dvec3 d = frame.to_world(
            {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u.x))});
        RTCRay ray = ray_of(origin, d, 0, radius);
        rtcOccluded1(scene_->scene, &context, &ray);
        if (ray.tfar >= 0) ++open;  // Embree sets tfar to -inf when something is in the way
    }
    return static_cast<double>(open) / count;
}

TruthFrame RayTracedAo::frame(const perspective::Camera& camera, int width, int height,
                              double radius, int rays) const {
    TruthFrame out{rl::FloatImage(width, height, NAN), rl::FloatImage(width, height, NAN)};
    const perspective::RayCamera eye(camera, width, height);
    tbb::parallel_for(0, height, [&](int y) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        for (int x = 0; x < width; ++x) {
            const rl::dvec3 d = eye.direction(x + 0.5, y + 0.5);  // t along it is view depth
            RTCRayHit hit{};
            hit.ray = ray_of(eye.eye(), d, eye.near(), eye.far());
            hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene_->scene, &context, &hit);
            if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
            const std::size_t t = hit.hit.primID;
            const double u = hit.hit.u, v = hit.hit.v;
            rl::dvec3 n =
                rl::normalize(scene_->normals[3 * t] * (1 - u - v) +
                              scene_->normals[3 * t + 1] * u + scene_->normals[3 * t + 2] * v);
            if (rl::dot(n, d) > 0) n = -n;  // the side the eye sees
            const rl::dvec3 p = eye.eye() + d * static_cast<double>(hit.ray.tfar);
            out.depth.at(x, y) = hit.ray.tfar;
            out.ao.at(x, y) = static_cast<float>(
                at(p, n, radius, rays, static_cast<std::uint32_t>(y * width + x)));
        }
    });
    return out;
}
// [/doc:ao-truth]

AoError compare(const TruthFrame& truth, const rl::FloatImage& ao, const GBuffer& g,
                const Screen& screen, double radius) {
    const int w = g.width(), h = g.height();
    // Depth edges: a neighbour (4-connected) with no model, or nearer or
    // farther by more than half the radius; then every pixel within 3 of one.
    rl::Grid<int> edge(w, h, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float d = truth.depth.get(x, y);
            for (auto [i, j] : {std::pair{x + 1, y}, {x, y + 1}}) {
                if (i >= w || j >= h) continue;
                const float e = truth.depth.get(i, j);
                if (std::isnan(d) != std::isnan(e) ||
                    (!std::isnan(d) && std::fabs(d - e) > 0.5 * radius)) {
                    for (int b = std::max(0, y - 3); b <= std::min(h - 1, j + 3); ++b)
                        for (int a = std::max(0, x - 3); a <= std::min(w - 1, i + 3); ++a)
                            edge.at(a, b) = 1;
                }
            }
        }
    std::vector<double> inner;
    AoError out;
    double edge_sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float t = truth.ao.get(x, y), d = truth.depth.get(x, y);
            const float z = g.depth()->get(x, y);
            if (std::isnan(t) || !(z < g.depth_state.clear)) continue;
            if (std::fabs(screen.view_depth(z) - d) > 0.01f * d) continue;  // another surface
            const double e = std::fabs(static_cast<double>(ao.get(x, y)) - t);
            if (edge.get(x, y)) {
                edge_sum += e;
                ++out.edge_pixels;
            } else {
                inner.push_back(e);
            }
        }
    out.pixels = static_cast<long>(inner.size());
    if (!inner.empty()) {
        double sum = 0;
        for (double e : inner) sum += e;
        out.mean = sum / static_cast<double>(inner.size());
        const auto at95 = inner.begin() +
                          static_cast<std::ptrdiff_t>(0.95 * static_cast<double>(inner.size() - 1));
        std::nth_element(inner.begin(), at95, inner.end());
        out.p95 = *at95;
    }
    if (out.edge_pixels > 0) out.edge_mean = edge_sum / static_cast<double>(out.edge_pixels);
    return out;
}

}  // namespace occlusion
