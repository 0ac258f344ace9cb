// Lesson 13 without a window: each key changes what it says, the orbit
// gives back the camera it came from, the frame renderer draws lesson 12's
// image (and lesson 07's), and the wireframe survives edges behind the eye.
#include <gtest/gtest.h>

#include <cmath>

#include "08_shadows/scene.hpp"
#include "12_fast/renderer.hpp"
#include "13_viewer/controls.hpp"
#include "13_viewer/frame_renderer.hpp"
#include "13_viewer/wire_overlay.hpp"
#include "rasterlab/image_metrics.hpp"

namespace {

using viewer::Key;

TEST(Keys, EachKeyChangesWhatItSays) {
    viewer::Settings first;
    first.filter = textures::Filter::bilinear;  // as if the command line asked for it
    const viewer::Orbit first_orbit{10, 20, 4, 0.1f, 40};
    viewer::Settings s = first;
    viewer::Orbit o = first_orbit;
    viewer::apply(Key::next_path, s, o, first, first_orbit);
    EXPECT_EQ(s.path, viewer::Path::lesson07);
    viewer::apply(Key::next_path, s, o, first, first_orbit);
    EXPECT_EQ(s.path, viewer::Path::fast);
    viewer::apply(Key::shadows, s, o, first, first_orbit);
    EXPECT_EQ(s.path, viewer::Path::shadows);
    viewer::apply(Key::specular, s, o, first, first_orbit);
    EXPECT_EQ(s.specular, shading::Specular::phong);
    viewer::apply(Key::filter, s, o, first, first_orbit);
    EXPECT_EQ(s.filter, textures::Filter::trilinear);  // bilinear -> trilinear
    viewer::apply(Key::normal_map, s, o, first, first_orbit);
    EXPECT_EQ(s.normal_map, normal_mapping::NormalMap::object);
    viewer::apply(Key::wireframe, s, o, first, first_orbit);
    EXPECT_TRUE(s.wireframe);
    viewer::apply(Key::coarser, s, o, first, first_orbit);
    viewer::apply(Key::coarser, s, o, first, first_orbit);
    viewer::apply(Key::coarser, s, o, first, first_orbit);
    EXPECT_EQ(s.scale, 4);  // no coarser than a quarter
    viewer::apply(Key::finer, s, o, first, first_orbit);
    EXPECT_EQ(s.scale, 2);
    viewer::apply(Key::turn_right, s, o, first, first_orbit);
    EXPECT_GT(o.yaw, 10);
    viewer::apply(Key::move_closer, s, o, first, first_orbit);
    EXPECT_LT(o.distance, 4);
    viewer::apply(Key::reset, s, o, first, first_orbit);
    EXPECT_EQ(s, first);  // the command line's settings, not the built-in ones
    EXPECT_EQ(o.yaw, first_orbit.yaw);
    EXPECT_EQ(o.distance, first_orbit.distance);
}

// Azimuth about y from +z towards +x, and elevation, in degrees.
float azimuth_of(rl::vec3 d) {
    return std::atan2(d.x, d.z) * 180 / 3.14159265f;
}
float elevation_of(rl::vec3 d) {
    return std::asin(rl::normalize(d).y) * 180 / 3.14159265f;
}

TEST(Keys, TheLightKeysTurnAndRaiseTheLight) {
    viewer::Settings first;
    first.light = {1, 1, 0};  // azimuth 90, elevation 45
    const viewer::Orbit first_orbit;
    viewer::Settings s = first;
    viewer::Orbit o = first_orbit;
    viewer::apply(Key::light_right, s, o, first, first_orbit);
    EXPECT_NEAR(azimuth_of(s.light), 105, 1e-3f);
    EXPECT_NEAR(elevation_of(s.light), 45, 1e-3f);
    viewer::apply(Key::light_left, s, o, first, first_orbit);
    viewer::apply(Key::light_left, s, o, first, first_orbit);
    EXPECT_NEAR(azimuth_of(s.light), 75, 1e-3f);
    viewer::apply(Key::light_up, s, o, first, first_orbit);
    EXPECT_NEAR(elevation_of(s.light), 50, 1e-3f);
    viewer::apply(Key::light_down, s, o, first, first_orbit);
    viewer::apply(Key::light_down, s, o, first, first_orbit);
    EXPECT_NEAR(elevation_of(s.light), 40, 1e-3f);
    EXPECT_NEAR(rl::length(s.light), 1, 1e-5f);
    for (int i = 0; i < 40; ++i) viewer::apply(Key::light_up, s, o, first, first_orbit);
    EXPECT_NEAR(elevation_of(s.light), 85, 1e-3f);  // short of overhead, where azimuth is lost
    viewer::apply(Key::light_down, s, o, first, first_orbit);
    EXPECT_NEAR(elevation_of(s.light), 80, 1e-3f);  // and one step down moves it at once
    viewer::drag_light(s, 25, 0);                   // 0.4 degrees a pixel
    EXPECT_NEAR(azimuth_of(s.light), 85, 1e-3f);
    viewer::drag_light(s, 0, -25);  // dragging up raises it
    EXPECT_NEAR(elevation_of(s.light), 85, 1e-3f);
    viewer::apply(Key::reset, s, o, first, first_orbit);
    EXPECT_EQ(s.light, first.light);
    viewer::drag_light(s, 0, 0);
    EXPECT_EQ(s.light, first.light);  // no drag: the --light direction to the bit
}

TEST(Keys, EveryKeyHasANameAndAHelpLine) {
    for (char c : std::string("<>^vpsmfnw+-rjlik")) {
        ASSERT_TRUE(viewer::key_named(c)) << c;
        EXPECT_NE(viewer::key_help().find(std::string("[") + c + "]"), std::string::npos) << c;
    }
    EXPECT_FALSE(viewer::key_named('x'));
    EXPECT_EQ(viewer::key_of_letter('p'), Key::next_path);
    EXPECT_FALSE(viewer::key_of_letter('v'));  // 'v' is the down arrow's name, not a letter key
}

TEST(Orbit, GivesBackTheCameraItCameFrom) {
    pipeline::Camera c;
    c.eye = {1.5f, 2.0f, -3.0f};
    c.target = {0.2f, 0.4f, 0.1f};
    pipeline::Box box;
    box.add(rl::vec3{-1, 0, -1});
    box.add(rl::vec3{1, 1, 1});
    const pipeline::Camera back = viewer::camera_of(viewer::orbit_of(c), c, {}, box, 1.0f);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(back.eye[k], c.eye[k], 1e-4f);
    EXPECT_GT(back.near, 0);
    EXPECT_LT(back.near, back.far);
}

TEST(Orbit, DraggingStopsShortOfThePoles) {
    viewer::Orbit o{0, 0, 3};
    viewer::drag(o, 0, 100000);
    EXPECT_LT(o.pitch, 90);
    pipeline::Camera c;
    pipeline::Box box;
    box.add(rl::vec3{-1, -1, -1});
    box.add(rl::vec3{1, 1, 1});
    EXPECT_NO_THROW(viewer::camera_of(o, c, {}, box, 1.0f));  // up is never the view direction
}

TEST(Orbit, ZoomingStopsBeforeTheTargetAndBeforeInfinity) {
    pipeline::Camera c;  // eye 3 from the target
    viewer::Orbit o = viewer::orbit_of(c);
    viewer::zoom(o, 100000);
    EXPECT_FLOAT_EQ(o.distance, 3.0f / 1000);
    pipeline::Box box;
    box.add(rl::vec3{-1, -1, -1});
    box.add(rl::vec3{1, 1, 1});
    EXPECT_NO_THROW(viewer::camera_of(o, c, {}, box, 1.0f));
    viewer::zoom(o, -100000);
    EXPECT_FLOAT_EQ(o.distance, 3.0f * 1000);
    EXPECT_NO_THROW(viewer::camera_of(o, c, {}, box, 1.0f));
}

TEST(Orbit, TurnsAboutTheCamerasOwnUp) {
    pipeline::Camera c;
    c.up = {0, 0, 1};  // z up
    c.eye = {3, 0, 1};
    c.target = {0, 0, 0};
    pipeline::Box box;
    box.add(rl::vec3{-1, -1, -1});
    box.add(rl::vec3{1, 1, 1});
    viewer::Orbit o = viewer::orbit_of(c);
    o.yaw += 90;
    const pipeline::Camera turned = viewer::camera_of(o, c, {}, box, 1.0f);
    EXPECT_NEAR(turned.eye.z, c.eye.z, 1e-4f);  // the height above the target kept
    EXPECT_NEAR(rl::length(turned.eye), rl::length(c.eye), 1e-4f);
}

struct Scene {
    normal_mapping::MappedView request;
    pipeline::ViewedScene<normal_mapping::MappedModel> scene;
    Scene() {
        request.every_normal_map = true;
        std::vector<std::string> warnings;
        scene = normal_mapping::load_scene(request, 96, 64, warnings);
    }
};

TEST(Frames, TheFastPathIsLessonTwelvesImage) {
    Scene s;
    viewer::FrameRenderer renderer(s.scene.models, s.request);
    const rl::Image& shown = renderer.render({}, s.scene.camera, 96, 64);
    fast::FastOptions o;
    o.render = s.request.options;
    fast::Renderer reference(s.scene.models, 96, 64, o);
    reference.render(s.scene.camera);
    EXPECT_EQ(shown, reference.frame());
    EXPECT_GT(renderer.stats().pixels_shaded, 0u);
}

// The S key: both of lesson 08's passes on the fast path: lesson 08's
// picture within a level, frame after frame and with the light moved.
TEST(Frames, TheShadowsAreLessonEightsPicture) {
    Scene s;
    viewer::FrameRenderer renderer(s.scene.models, s.request);
    viewer::Settings settings;
    settings.path = viewer::Path::shadows;
    for (int frame = 0; frame < 3; ++frame) {
        if (frame == 2) settings.light = viewer::turned_light(settings.light, 40, 10);
        const rl::Image shown = renderer.render(settings, s.scene.camera, 96, 64);
        shadows::ShadowOptions o;
        o.render = s.request.options;
        shadows::set_lights(o, s.request.view, s.request.one_light);
        if (frame == 2) {
            o.light.direction = rl::normalize(settings.light);
            o.render.lighting = shading::default_lighting(settings.light);
        }
        const shadows::ShadowMap map =
            shadows::shadow_map_for(s.scene.models, s.scene.camera, 96.0f / 64.0f, o);
        pipeline::ColourTarget target = pipeline::colour_target(96, 64);
        shadows::render(s.scene.models, s.scene.camera, o, map, target);
        // The fast path's second pass: within a level of lesson 08's (12_fast's own tests).
        EXPECT_LE(rl::compare_images(shown, target.colour(), 1).max_abs, 1) << "frame " << frame;
        EXPECT_GT(renderer.stats().shadow_map_ms, 0);
    }
    // S again: the fast path's own picture, no map left in its shader.
    settings.path = viewer::Path::fast;
    fast::FastOptions o;
    o.render = s.request.options;
    o.render.lighting = shading::default_lighting(settings.light);
    fast::Renderer reference(s.scene.models, 96, 64, o);
    reference.render(s.scene.camera);
    EXPECT_EQ(renderer.render(settings, s.scene.camera, 96, 64), reference.frame());
}

TEST(Frames, SwitchingTheNormalMapChangesThePicture) {
    Scene s;
    viewer::FrameRenderer renderer(s.scene.models, s.request);
    viewer::Settings settings;
    const rl::Image tangent = renderer.render(settings, s.scene.camera, 96, 64);
    settings.normal_map = normal_mapping::NormalMap::none;
    EXPECT_NE(renderer.render(settings, s.scene.camera, 96, 64), tangent);
    settings.path = viewer::Path::lesson07;
    const rl::Image lesson07 = renderer.render(settings, s.scene.camera, 96, 64);
    settings.path = viewer::Path::shadows;
    EXPECT_NE(renderer.render(settings, s.scene.camera, 96, 64), lesson07);  // shadows
}

// A moved light reaches every path: the fast renderer's new lights give
// the image a renderer built with them gives, lesson 07's path and lesson
// 08's light the scene from it too.
TEST(Frames, AMovedLightReachesEveryPath) {
    Scene s;
    viewer::FrameRenderer renderer(s.scene.models, s.request);
    viewer::Settings settings;
    const rl::Image before = renderer.render(settings, s.scene.camera, 96, 64);
    settings.light = viewer::turned_light(settings.light, 60, 20);
    const rl::Image moved = renderer.render(settings, s.scene.camera, 96, 64);
    EXPECT_NE(moved, before);
    fast::FastOptions o;
    o.render = s.request.options;
    o.render.lighting = shading::default_lighting(settings.light);
    fast::Renderer reference(s.scene.models, 96, 64, o);
    reference.render(s.scene.camera);
    EXPECT_EQ(moved, reference.frame());

    settings.path = viewer::Path::lesson07;
    pipeline::ColourTarget target = pipeline::colour_target(96, 64);
    normal_mapping::render(s.scene.models, s.scene.camera, o.render, target);
    EXPECT_EQ(renderer.render(settings, s.scene.camera, 96, 64), target.colour());

    settings.path = viewer::Path::shadows;
    const rl::Image shadowed = renderer.render(settings, s.scene.camera, 96, 64);
    viewer::Settings unmoved;
    unmoved.path = viewer::Path::shadows;
    EXPECT_NE(shadowed, renderer.render(unmoved, s.scene.camera, 96, 64));
}

TEST(Wireframe, DrawsEdgesOverThePicture) {
    Scene s;
    viewer::FrameRenderer renderer(s.scene.models, s.request);
    viewer::Settings settings;
    const rl::Image plain = renderer.render(settings, s.scene.camera, 96, 64);
    settings.wireframe = true;
    EXPECT_NE(renderer.render(settings, s.scene.camera, 96, 64), plain);
}

TEST(Wireframe, ASegmentIsCutWhereItCrossesTheNearPlane) {
    pipeline::ClipPosition a{0, 0, 0, 2}, b{4, 0, 0, -2};
    ASSERT_TRUE(viewer::cut_to_front(a, b, 0.5));
    EXPECT_DOUBLE_EQ(a.w, 2);
    EXPECT_DOUBLE_EQ(b.w, 0.5);
    EXPECT_DOUBLE_EQ(b.x, 1.5);  // t = (2 - 0.5) / (2 + 2) = 0.375 of the way to b
    pipeline::ClipPosition c{0, 0, 0, -1}, d{1, 1, 1, 3};
    ASSERT_TRUE(viewer::cut_to_front(c, d, 0.5));  // either end may be the one behind
    EXPECT_DOUBLE_EQ(c.w, 3);
    EXPECT_DOUBLE_EQ(d.w, 0.5);
    pipeline::ClipPosition e{0, 0, 0, 0.1}, f{0, 0, 0, -3};
    EXPECT_FALSE(viewer::cut_to_front(e, f, 0.5));  // wholly behind
}

TEST(Wireframe, EdgesBehindTheEyeAreCutNotDivided) {
    Scene s;
    pipeline::Camera inside = s.scene.camera;
    inside.eye = s.scene.camera.target;  // in the middle of the scene: edges pass behind
    inside.eye.z += 0.01f;
    inside.near = 0.001f;
    rl::Image image(64, 64, rl::kBackground);
    const std::size_t drawn =
        viewer::draw_wire_overlay(image, s.scene.models, inside, {255, 255, 255, 255});
    EXPECT_GT(drawn, 0u);
    std::size_t lit = 0;
    for (const rl::Rgba& p : image.pixels()) lit += p.r == 255;
    EXPECT_GT(lit, 0u);
}

}  // namespace
