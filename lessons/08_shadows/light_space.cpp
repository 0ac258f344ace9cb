#include "light_space.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "rasterlab/transform.hpp"

namespace shadows {
namespace {

// Any up vector for a look-at along `forward`, not parallel to it.
rl::vec3 up_for(rl::vec3 forward) {
    return std::abs(forward.y) > 0.99f ? rl::vec3{0, 0, 1} : rl::vec3{0, 1, 0};
}

// The light's look-at; a direction that is not finite has none.
rl::mat4 light_look_at(rl::vec3 eye, rl::vec3 target, rl::vec3 forward) {
    const std::optional<rl::mat4> view = rl::look_at(eye, target, up_for(forward));
    if (!view) throw std::invalid_argument("--light: the light's direction is not usable");
    return *view;
}

rl::vec3 componentwise(rl::vec3 a, rl::vec3 b, const float& (*pick)(const float&, const float&)) {
    return {pick(a.x, b.x), pick(a.y, b.y), pick(a.z, b.z)};
}

rl::vec3 transform_point(const rl::mat4& m, rl::vec3 p) {
    return (m * rl::extend(p, 1.0f)).xyz();
}

}  // namespace

float LightView::texel_size(rl::vec3 world_point, int map_size) const {
    if (type == LightType::directional) return width / static_cast<float>(map_size);
    const float distance = std::max(rl::dot(world_point - position, direction), 0.0f);
    return 2 * distance * tan_half_angle / static_cast<float>(map_size);
}

rl::mat4 orthographic(float left, float right, float bottom, float top, float near, float far) {
    return rl::mat4{{rl::vec4{2 / (right - left), 0, 0, -(right + left) / (right - left)},
                     rl::vec4{0, 2 / (top - bottom), 0, -(top + bottom) / (top - bottom)},
                     rl::vec4{0, 0, -2 / (far - near), -(far + near) / (far - near)},
                     rl::vec4{0, 0, 0, 1}}};
}

pipeline::Box visible_box(const pipeline::Camera& camera, float aspect,
                          const pipeline::Box& scene) {
    const rl::vec3 forward = rl::normalize(camera.target - camera.eye);
    const rl::vec3 right = rl::normalize(rl::cross(forward, camera.up));
    const rl::vec3 up = rl::cross(right, forward);
    const float tan_y = std::tan(0.5f * rl::radians(camera.fov_y)), tan_x = tan_y * aspect;
    pipeline::Box frustum;
    for (const float d : {camera.near, camera.far})
        for (const float sx : {-1.0f, 1.0f})
            for (const float sy : {-1.0f, 1.0f})
                frustum.add(camera.eye + forward * d + right * (sx * d * tan_x) +
                            up * (sy * d * tan_y));
    pipeline::Box out;
    out.min = componentwise(frustum.min, scene.min, std::max<float>);
    out.max = componentwise(frustum.max, scene.max, std::min<float>);
    return out;
}

LightView light_view(const ShadowLight& light, const pipeline::Box& covered,
                     const pipeline::Box& casters) {
    if (covered.empty()) throw std::invalid_argument("the shadow map has nothing to cover");
    if (!(rl::length(light.direction) > 0) || !std::isfinite(rl::length(light.direction)))
        throw std::invalid_argument("--light: the light needs a direction");
    const rl::vec3 towards = rl::normalize(light.direction);
    const rl::vec3 centre = covered.centre();
    const float radius = std::max(rl::length(covered.max - covered.min) * 0.5f, 1e-6f);
    LightView out;
    out.type = light.type;
    out.direction = -towards;
    if (light.type == LightType::directional) {
        out.position = centre + towards * (2 * radius);
        const rl::mat4 view = light_look_at(out.position, centre, out.direction);
        pipeline::Box in_light;  // the covered box's corners in the light's view space
        for (int i = 0; i < 8; ++i) in_light.add(transform_point(view, covered.corner(i)));
        // Casters nearer the light than the receivers (larger view-space z)
        // push the near plane out; the sides stay the receivers'.
        for (int i = 0; !casters.empty() && i < 8; ++i)
            in_light.max.z = std::max(in_light.max.z, transform_point(view, casters.corner(i)).z);
        // A square map: the larger side, centred, so that a texel is square in world units.
        out.width = std::max(
            {in_light.max.x - in_light.min.x, in_light.max.y - in_light.min.y, radius * 1e-4f});
        // Near and far a ten-thousandth of the depth range outside the box:
        // a face lying on the box's side (a crate's top under a light
        // straight above) would otherwise sit on the near plane, a rounding
        // away from being clipped.
        const float depth_margin =
            std::max((in_light.max.z - in_light.min.z) * 1e-4f, radius * 1e-6f);
        const rl::vec3 mid = in_light.centre();
        out.view_projection =
            orthographic(mid.x - out.width / 2, mid.x + out.width / 2, mid.y - out.width / 2,
                         mid.y + out.width / 2, -in_light.max.z - depth_margin,
                         -in_light.min.z + depth_margin) *
            view;
        return out;
    }
    out.position = light.position;
    const rl::vec3 target = rl::length(centre - light.position) > radius * 1e-4f
                                ? centre
                                : light.position + out.direction;
    out.direction = rl::normalize(target - light.position);
    const rl::mat4 view = light_look_at(light.position, target, out.direction);
    float far = 0;
    for (int i = 0; i < 8; ++i) far = std::max(far, -transform_point(view, covered.corner(i)).z);
    far = std::max(far, radius * 1e-3f);
    float near = far;
    for (int i = 0; i < 8; ++i) near = std::min(near, -transform_point(view, covered.corner(i)).z);
    for (int i = 0; !casters.empty() && i < 8; ++i)  // casters nearer the light than the receivers
        near = std::min(near, -transform_point(view, casters.corner(i)).z);
    near = std::max(near, far / 1000);
    out.tan_half_angle = std::tan(0.5f * rl::radians(light.cone_degrees));
    out.view_projection = rl::perspective(light.cone_degrees, 1, near, far * 1.0001f) * view;
    return out;
}

}  // namespace shadows
