#include "ray_traced_ao.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

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
    const pipeline::Box box = normal_mapping::scene_box(models);
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

// [/doc:ao-truth]

std::optional<RayTracedAo::Hit> RayTracedAo::first_hit(rl::dvec3 origin, rl::dvec3 d, double near,
                                                       double far) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit hit{};
    hit.ray = ray_of(origin, d, near, far);
    hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_->scene, &context, &hit);
    if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    const std::size_t t = hit.hit.primID;
    const double u = hit.hit.u, v = hit.hit.v;
    rl::dvec3 n = rl::normalize(scene_->normals[3 * t] * (1 - u - v) +
                                scene_->normals[3 * t + 1] * u + scene_->normals[3 * t + 2] * v);
    if (rl::dot(n, d) > 0) n = -n;  // the side the ray came from
    return Hit{hit.ray.tfar, n};
}

}  // namespace occlusion
