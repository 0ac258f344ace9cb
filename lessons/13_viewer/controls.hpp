// The viewer's controls as plain data: what is on screen (the renderer's
// path and the shading options), where the camera is (an orbit about the
// target), and how each key changes them. No window here, so the tests can
// drive it without one; main.cpp maps SDL's keys and mouse onto it.
//
//   viewer::Settings settings;
//   viewer::Orbit orbit = viewer::orbit_of(camera);
//   viewer::apply(viewer::Key::next_path, settings, orbit, first, first_orbit);  // fast -> 07
//   const pipeline::Camera seen = viewer::camera_of(orbit, camera, view, box, aspect);
#pragma once

#include <array>
#include <optional>
#include <string>

#include "05_perspective/camera.hpp"
#include "05_perspective/view_options.hpp"
#include "06_shading/lighting.hpp"
#include "07_normal_mapping/normal_mapped.hpp"
#include "rasterlab/named_enum.hpp"

namespace viewer {

// Which renderer draws the frame: lesson 12's fast path, lesson 07's clear
// one, or the fast path with lesson 08's shadows (the shadows key).
enum class Path { fast, lesson07, shadows };
RASTERLAB_NAMED_ENUM(Path, kPaths, {Path::fast, "fast"}, {Path::lesson07, "lesson07"},
                     {Path::shadows, "shadows"});

struct Settings {
    Path path = Path::fast;
    shading::Specular specular = shading::Specular::blinn_phong;
    textures::Filter filter = textures::Filter::trilinear;
    normal_mapping::NormalMap normal_map = normal_mapping::NormalMap::tangent;
    bool wireframe = false;
    int scale = 1;  // the framebuffer is the window's size divided by this (1, 2 or 4)
    // Towards the light, in world space: --light at first, then as J, L, I,
    // K and a right-button drag turn it.
    rl::vec3 light{0.3f, 0.5f, 1.0f};
    friend bool operator==(const Settings&, const Settings&) = default;
};

// The camera as an orbit: the eye at `distance` from the target, turned
// `yaw` degrees about the up axis (from where the first camera stood) and
// `pitch` degrees above the plane square to it. The distance stays within
// [nearest, farthest], a thousand times either way of the first one, so that
// zooming can neither put the eye on the target nor past a float's range.
struct Orbit {
    float yaw = 0, pitch = 0, distance = 1;
    float nearest = 1e-3f, farthest = 1e3f;
};

enum class Key {
    turn_left,
    turn_right,  // arrows: turn the camera about the target
    move_closer,
    move_away,   // arrows: move towards or away from the target
    next_path,   // P: fast -> lesson 07 -> fast
    shadows,     // S: shadows on (lesson 08's two passes, on the fast path) or off
    specular,    // M: Blinn-Phong <-> Phong
    filter,      // F: trilinear -> nearest -> bilinear -> trilinear
    normal_map,  // N: tangent -> object -> none -> tangent
    wireframe,   // W: lesson 01's lines over the picture
    finer,
    coarser,  // + and -: the framebuffer's scale, 1, 1/2, 1/4 of the window
    reset,    // R: the first view and settings again (those the command line gave)
    light_left,
    light_right,  // J and L: turn the light about the vertical
    light_up,
    light_down,  // I and K: raise or lower the light
};

// The key named by one character of the --keys script and of --help's list
// ('<' '>' '^' 'v' for the arrows), or none.
std::optional<Key> key_named(char c);

// The key a letter key gives ('p' for P), or none (V, say: in a script 'v'
// names the down arrow, but the letter V does nothing).
std::optional<Key> key_of_letter(char c);

// The lines --help prints: every key and what it does.
std::string key_help();

// Changes the settings or the orbit as `key` says; reset goes back to
// `first` and `first_orbit` (what the command line asked for).
void apply(Key key, Settings& settings, Orbit& orbit, const Settings& first,
           const Orbit& first_orbit);

// Drags and wheel steps: degrees per pixel dragged, and the distance's
// factor per wheel step.
void drag(Orbit& orbit, int dx, int dy);
void zoom(Orbit& orbit, int steps);

// A drag with the right button moves the light: across turns it about the
// vertical, up and down raises and lowers it.
void drag_light(Settings& settings, int dx, int dy);

// `light` turned `yaw` degrees about the vertical (world y) and raised
// `raise` degrees, its elevation kept within 85 degrees of the horizon; a
// unit vector.
rl::vec3 turned_light(rl::vec3 light, float yaw, float raise);

// The orbit of a camera about its target, measured about its own up axis:
// yaw 0 where it stands.
Orbit orbit_of(const pipeline::Camera& camera);

// The camera of an orbit about `start` (the first camera: its target, up and
// field of view): the eye on the orbit, near and far as `view` gives them
// (--near, --far) or fitted to `box`, as the programs frame them.
pipeline::Camera camera_of(const Orbit& orbit, const pipeline::Camera& start,
                           const pipeline::ViewOptions& view, const pipeline::Box& box,
                           float aspect);

// One line of the current settings, for the title bar and the tests.
std::string describe(const Settings& settings);

}  // namespace viewer
