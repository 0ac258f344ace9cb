#include "visibility_truth.hpp"

#include <array>
#include <cmath>

namespace shadows {

std::vector<pipeline::WorldTriangle> world_triangles(
    const std::vector<normal_mapping::MappedModel>& models) {
    std::vector<pipeline::WorldTriangle> out;
    for (const normal_mapping::MappedModel& m : models) {
        const rl::Mesh& mesh = m.lit.model.mesh;
        const rl::dmat4 transform = rl::cast<double>(m.lit.model.transform);
        for (const rl::Face& face : mesh.faces) {
            pipeline::WorldTriangle t{};
            for (int k = 0; k < 3; ++k)
                t.p[k] =
                    (transform * rl::extend(rl::cast<double>(mesh.position(face, k)), 1.0)).xyz();
            out.push_back(t);
        }
    }
    return out;
}

SceneRays::SceneRays(const std::vector<normal_mapping::MappedModel>& models)
    : bvh_(world_triangles(models)) {
    const pipeline::Box box = scene_box(models);
    scale_ = box.empty() ? 1 : std::max(static_cast<double>(rl::length(box.max - box.min)), 1e-30);
}

// [doc:visibility-truth]
TruthFrame SceneRays::truth(const pipeline::Camera& camera, int width, int height,
                            const LightView& light, float cone_degrees) const {
    TruthFrame out{rl::Grid<int>(width, height, -1), rl::FloatImage(width, height, NAN)};
    const pipeline::RayCamera rays(camera, width, height);
    const rl::dvec3 towards = -rl::normalize(rl::cast<double>(light.direction));
    const rl::dvec3 spot = rl::cast<double>(light.position);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const rl::dvec3 d = rays.direction(x + 0.5, y + 0.5);  // t along it is view depth
            const RayHit hit = bvh_.nearest(rays.eye(), d, rays.near(), rays.far());
            if (hit.triangle < 0) continue;
            out.triangle.at(x, y) = hit.triangle;
            const pipeline::WorldTriangle& t =
                bvh_.triangles()[static_cast<std::size_t>(hit.triangle)];
            rl::dvec3 normal = rl::normalize(rl::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
            if (rl::dot(normal, d) > 0) normal = -normal;  // the side the eye sees
            const rl::dvec3 point = rays.eye() + d * hit.t;
            const rl::dvec3 to_light =
                light.type == LightType::directional ? towards : spot - point;
            if (!(rl::dot(normal, to_light) > 0)) continue;  // faces away: no direct light
            if (light.type == LightType::spot &&
                !(cone_factor(light, cone_degrees, rl::cast<float>(-to_light)) > 0))
                continue;  // outside the spot's cone: no direct light either
            // Off the surface by a billionth of the scene, so that the ray
            // does not meet the triangle it starts on.
            const rl::dvec3 origin = point + normal * (scale_ * 1e-9);
            const double t_max = light.type == LightType::directional ? HUGE_VAL : 1.0;
            out.lit.at(x, y) = bvh_.any(origin, to_light, 0, t_max) ? 0.0f : 1.0f;
        }
    return out;
}
// [/doc:visibility-truth]

rl::FloatImage SceneRays::soft(const TruthFrame& hard, const pipeline::Camera& camera,
                               const LightView& light, double radius_degrees) const {
    const int width = hard.lit.width(), height = hard.lit.height();
    rl::FloatImage out(width, height, NAN);
    const pipeline::RayCamera rays(camera, width, height);
    const rl::dvec3 towards = -rl::normalize(rl::cast<double>(light.direction));
    // Two axes across the light's direction, and 16 points of the unit disc
    // (4 rings of 4, the rings at equal areas, each turned a quarter step).
    const rl::dvec3 a = rl::normalize(
        rl::cross(towards, std::abs(towards.y) > 0.9 ? rl::dvec3{1, 0, 0} : rl::dvec3{0, 1, 0}));
    const rl::dvec3 b = rl::cross(towards, a);
    const double spread = std::tan(radius_degrees * M_PI / 180);
    std::array<rl::dvec3, 16> directions{};
    for (int ring = 0; ring < 4; ++ring)
        for (int k = 0; k < 4; ++k) {
            const double r = std::sqrt((ring + 0.5) / 4), angle = (k + ring * 0.25) * M_PI / 2;
            directions[static_cast<std::size_t>(4 * ring + k)] =
                towards + (a * std::cos(angle) + b * std::sin(angle)) * (r * spread);
        }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (std::isnan(hard.lit.at(x, y))) continue;
            const rl::dvec3 d = rays.direction(x + 0.5, y + 0.5);
            const RayHit hit = bvh_.nearest(rays.eye(), d, rays.near(), rays.far());
            const pipeline::WorldTriangle& t =
                bvh_.triangles()[static_cast<std::size_t>(hit.triangle)];
            rl::dvec3 normal = rl::normalize(rl::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
            if (rl::dot(normal, d) > 0) normal = -normal;
            const rl::dvec3 origin = rays.eye() + d * hit.t + normal * (scale_ * 1e-9);
            int passed = 0;
            for (const rl::dvec3& to_light : directions)
                passed += rl::dot(normal, to_light) > 0 && !bvh_.any(origin, to_light, 0, HUGE_VAL);
            out.at(x, y) = static_cast<float>(passed) / static_cast<float>(directions.size());
        }
    return out;
}

namespace {

// The probe: the second pass's shader, writing its map answer and the
// shaded triangle's number instead of a colour.
struct ProbeShader {
    ShadowedShader shaded;
    int first_triangle;  // the model's first triangle in world_triangles()' numbering
    using Varyings = ShadowedShader::Varyings;
    pipeline::ClipVertex<Varyings> vertex(const shading::SurfaceCorner& in) const {
        return shaded.vertex(in);
    }
    std::tuple<float, int> fragment(const pipeline::Fragment<Varyings>& f) const {
        return {shaded.light_reaching(f.varyings), first_triangle + f.face()};
    }
};

}  // namespace

ProbeFrame probe(const std::vector<normal_mapping::MappedModel>& models,
                 const pipeline::Camera& camera, int width, int height,
                 const ShadowOptions& options, const ShadowMap& map) {
    pipeline::RenderTarget<float, int> target(width, height, {}, NAN, -1);
    // Each model's first triangle in world_triangles()' numbering.
    std::vector<int> first(models.size() + 1, 0);
    for (std::size_t i = 0; i < models.size(); ++i)
        first[i + 1] = first[i] + static_cast<int>(models[i].lit.model.mesh.faces.size());
    draw_shadowed(models, camera, static_cast<float>(width) / static_cast<float>(height), options,
                  map,
                  [&](const normal_mapping::MappedModel& m, const shading::Surface& surface,
                      const ShadowedShader& shader) {
                      const auto index = static_cast<std::size_t>(&m - models.data());
                      return pipeline::draw(surface, ProbeShader{shader, first[index]}, target,
                                            options.render.pipeline);
                  });
    return {std::move(target.colour<0>()), std::move(target.colour<1>())};
}

ShadowError compare(const TruthFrame& truth, const ProbeFrame& probe) {
    ShadowError e;
    for (int y = 0; y < truth.lit.height(); ++y)
        for (int x = 0; x < truth.lit.width(); ++x) {
            const float want = truth.lit.at(x, y), got = probe.lit.at(x, y);
            if (std::isnan(want) || truth.triangle.at(x, y) != probe.triangle.at(x, y)) continue;
            ++e.scored;
            e.wrongly_lit += want == 0 && got >= 0.5f;
            e.wrongly_shadowed += want == 1 && got < 0.5f;
            e.mean_error += std::abs(got - want);
        }
    if (e.scored > 0) {
        const double n = static_cast<double>(e.scored);
        e.wrongly_lit /= n;
        e.wrongly_shadowed /= n;
        e.mean_error /= n;
    }
    return e;
}

double soft_error(const TruthFrame& truth, const rl::FloatImage& soft, const ProbeFrame& probe) {
    double sum = 0;
    long count = 0;
    for (int y = 0; y < soft.height(); ++y)
        for (int x = 0; x < soft.width(); ++x) {
            if (std::isnan(soft.at(x, y)) || truth.triangle.at(x, y) != probe.triangle.at(x, y))
                continue;
            sum += std::abs(probe.lit.at(x, y) - soft.at(x, y));
            ++count;
        }
    return count > 0 ? sum / static_cast<double>(count) : 0;
}

}  // namespace shadows
