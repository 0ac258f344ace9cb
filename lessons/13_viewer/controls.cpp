#include "controls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "05_perspective/view_options.hpp"

namespace viewer {

namespace {

struct KeyName {
    char name;    // in a --keys script
    char letter;  // the letter key that gives it, lower case ('\0': an arrow, + or -)
    Key key;
    const char* what;
};
constexpr KeyName kKeys[] = {
    {'<', '\0', Key::turn_left, "left arrow: turn the camera left about the target"},
    {'>', '\0', Key::turn_right, "right arrow: turn the camera right about the target"},
    {'^', '\0', Key::move_closer, "up arrow: move towards the target"},
    {'v', '\0', Key::move_away, "down arrow: move away from the target"},
    {'p', 'p', Key::next_path, "P: the renderer, lesson 12's fast path or lesson 07's"},
    {'s', 's', Key::shadows,
     "S: shadows on or off (lesson 08's two passes, drawn by the fast path)"},
    {'m', 'm', Key::specular, "M: the highlight, Blinn-Phong or Phong"},
    {'f', 'f', Key::filter, "F: the texture filter, trilinear, nearest, bilinear"},
    {'n', 'n', Key::normal_map, "N: the normal map, tangent, object or none"},
    {'w', 'w', Key::wireframe, "W: the wireframe (lesson 01's lines) over the picture"},
    {'+', '\0', Key::finer, "+: a finer framebuffer (up to the window's size)"},
    {'-', '\0', Key::coarser, "-: a coarser framebuffer (1/2, then 1/4 of the window)"},
    {'r', 'r', Key::reset, "R: the first view and settings again"},
    {'j', 'j', Key::light_left, "J: turn the light left about the vertical"},
    {'l', 'l', Key::light_right, "L: turn the light right about the vertical"},
    {'i', 'i', Key::light_up, "I: raise the light"},
    {'k', 'k', Key::light_down, "K: lower the light"},
};

constexpr float kTurnDegrees = 5, kMoveFactor = 0.9f, kDegreesPerPixel = 0.4f;
constexpr float kLightTurnDegrees = 15, kLightRaiseDegrees = 5;
constexpr float kMostPitch = 85;  // short of the poles, where up and the view align

template <class E, std::size_t N>
E next(E value, const std::array<E, N>& order) {
    const auto at = std::find(order.begin(), order.end(), value);
    return at == order.end() || at + 1 == order.end() ? order.front() : *(at + 1);
}

}  // namespace

std::optional<Key> key_of_letter(char c) {
    for (const KeyName& k : kKeys)
        if (k.letter != '\0' && k.letter == c) return k.key;
    return std::nullopt;
}

std::optional<Key> key_named(char c) {
    for (const KeyName& k : kKeys)
        if (k.name == c) return k.key;
    return std::nullopt;
}

std::string key_help() {
    std::string text = "Keys (and, in a --keys script, the character in brackets):\n";
    for (const KeyName& k : kKeys) text += std::string("  [") + k.name + "] " + k.what + "\n";
    text += "  mouse drag: orbit; right-button drag: move the light; wheel: zoom; Esc or Q: quit\n";
    return text;
}

void apply(Key key, Settings& s, Orbit& orbit, const Settings& first, const Orbit& first_orbit) {
    using normal_mapping::NormalMap;
    using textures::Filter;
    switch (key) {
        case Key::turn_left:
            orbit.yaw -= kTurnDegrees;
            break;
        case Key::turn_right:
            orbit.yaw += kTurnDegrees;
            break;
        case Key::move_closer:
            zoom(orbit, 1);
            break;
        case Key::move_away:
            zoom(orbit, -1);
            break;
        case Key::next_path:
            s.path = s.path == Path::fast ? Path::lesson07 : Path::fast;
            break;
        case Key::shadows:
            s.path = s.path == Path::shadows ? Path::fast : Path::shadows;
            break;
        case Key::specular:
            s.specular = next(s.specular, shading::kSpeculars);
            break;
        case Key::filter:
            s.filter =
                next(s.filter, std::array{Filter::trilinear, Filter::nearest, Filter::bilinear});
            break;
        case Key::normal_map:
            s.normal_map = next(s.normal_map,
                                std::array{NormalMap::tangent, NormalMap::object, NormalMap::none});
            break;
        case Key::wireframe:
            s.wireframe = !s.wireframe;
            break;
        case Key::finer:
            s.scale = std::max(1, s.scale / 2);
            break;
        case Key::coarser:
            s.scale = std::min(4, s.scale * 2);
            break;
        case Key::reset:
            s = first;
            orbit = first_orbit;
            break;
        case Key::light_left:
            s.light = turned_light(s.light, -kLightTurnDegrees, 0);
            break;
        case Key::light_right:
            s.light = turned_light(s.light, kLightTurnDegrees, 0);
            break;
        case Key::light_up:
            s.light = turned_light(s.light, 0, kLightRaiseDegrees);
            break;
        case Key::light_down:
            s.light = turned_light(s.light, 0, -kLightRaiseDegrees);
            break;
    }
}

void drag_light(Settings& s, int dx, int dy) {
    if (dx == 0 && dy == 0) return;  // a still light stays the --light direction to the bit
    // Dragging up raises the light.
    s.light = turned_light(s.light, kDegreesPerPixel * static_cast<float>(dx),
                           -kDegreesPerPixel * static_cast<float>(dy));
}

rl::vec3 turned_light(rl::vec3 light, float yaw, float raise) {
    constexpr float radians = std::numbers::pi_v<float> / 180;
    const rl::vec3 d = rl::normalize(light);
    // Azimuth about y from +z towards +x, elevation above the floor's plane.
    const float azimuth = std::atan2(d.x, d.z) + yaw * radians;
    const float elevation = std::clamp(std::asin(std::clamp(d.y, -1.0f, 1.0f)) + raise * radians,
                                       -kMostPitch * radians, kMostPitch * radians);
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
            std::cos(elevation) * std::cos(azimuth)};
}

void drag(Orbit& orbit, int dx, int dy) {
    orbit.yaw -= kDegreesPerPixel * static_cast<float>(dx);
    orbit.pitch = std::clamp(orbit.pitch + kDegreesPerPixel * static_cast<float>(dy), -kMostPitch,
                             kMostPitch);
}

void zoom(Orbit& orbit, int steps) {
    orbit.distance = std::clamp(orbit.distance * std::pow(kMoveFactor, static_cast<float>(steps)),
                                orbit.nearest, orbit.farthest);
}

namespace {

// The orbit's frame: `up` (unit), and the directions of yaw 0 and yaw 90
// square to it, yaw 0 pointing from the target to the first camera's eye.
struct Frame {
    rl::vec3 up, ahead, side;
};
Frame frame_of(const pipeline::Camera& start) {
    Frame f;
    f.up = rl::normalize(start.up);
    const rl::vec3 offset = start.eye - start.target;
    rl::vec3 level = offset - f.up * rl::dot(offset, f.up);
    if (!(rl::length(level) > 1e-6f * rl::length(offset)))  // looking straight along up
        level = std::abs(f.up.x) < 0.9f ? rl::cross(f.up, rl::vec3{1, 0, 0})
                                        : rl::cross(f.up, rl::vec3{0, 1, 0});
    f.ahead = rl::normalize(level);
    f.side = rl::cross(f.up, f.ahead);
    return f;
}

}  // namespace

Orbit orbit_of(const pipeline::Camera& camera) {
    const rl::vec3 offset = camera.eye - camera.target;
    Orbit orbit;
    orbit.distance = rl::length(offset);
    if (!(orbit.distance > 0)) return orbit;
    orbit.nearest = orbit.distance / 1000, orbit.farthest = orbit.distance * 1000;
    constexpr float degrees = 180 / std::numbers::pi_v<float>;
    const float along_up = rl::dot(offset, frame_of(camera).up) / orbit.distance;
    orbit.pitch =
        std::clamp(std::asin(std::clamp(along_up, -1.0f, 1.0f)) * degrees, -kMostPitch, kMostPitch);
    return orbit;
}

pipeline::Camera camera_of(const Orbit& orbit, const pipeline::Camera& start,
                           const pipeline::ViewOptions& view, const pipeline::Box& box,
                           float aspect) {
    constexpr float radians = std::numbers::pi_v<float> / 180;
    const float yaw = orbit.yaw * radians, pitch = orbit.pitch * radians;
    const Frame f = frame_of(start);
    const rl::vec3 offset = (f.ahead * std::cos(yaw) + f.side * std::sin(yaw)) * std::cos(pitch) +
                            f.up * std::sin(pitch);
    const rl::vec3 eye = start.target + offset * orbit.distance;
    pipeline::ViewOptions v = view;  // --near, --far as given; up as the first camera's
    v.models.clear();
    v.eye = {eye.x, eye.y, eye.z};
    v.target = {start.target.x, start.target.y, start.target.z};
    v.up = {start.up.x, start.up.y, start.up.z};
    v.camera.fov_y = start.fov_y;
    return pipeline::resolve_camera(v, box, aspect);
}

std::string describe(const Settings& s) {
    std::string text = std::string("path ") + name(s.path) + ", " + shading::name(s.specular) +
                       ", " + textures::name(s.filter) + " filter, " +
                       normal_mapping::name(s.normal_map) + " normal map, wireframe " +
                       (s.wireframe ? "on" : "off") + ", scale 1/" + std::to_string(s.scale);
    const rl::vec3 light = rl::normalize(s.light);
    char towards[64];
    std::snprintf(towards, sizeof towards, ", light towards (%.2f, %.2f, %.2f)", light.x, light.y,
                  light.z);
    text += towards;
    return text;
}

}  // namespace viewer
