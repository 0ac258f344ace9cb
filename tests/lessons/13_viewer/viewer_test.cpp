// Lesson 13 without a window: each key changes what it says, the orbit
// gives back the camera it came from, the frame renderer draws lesson 12's
// image (and lesson 07's), and the wireframe survives edges behind the eye.
#include <gtest/gtest.h>

#include <cmath>

#include "12_fast/renderer.hpp"
#include "13_viewer/controls.hpp"
#include "13_viewer/frame_renderer.hpp"
#include "13_viewer/wire_overlay.hpp"

namespace {

using viewer::Key;

TEST(Keys, EachKeyChangesWhatItSays) {
    viewer::Settings s;
    viewer::Orbit o{10, 20, 4};
    viewer::apply(Key::next_path, s, o);
    EXPECT_EQ(s.path, viewer::Path::lesson07);
    viewer::apply(Key::next_path, s, o);
    EXPECT_EQ(s.path, viewer::Path::fast);
    viewer::apply(Key::shadows, s, o);
    EXPECT_EQ(s.path, viewer::Path::shadows);
    viewer::apply(Key::specular, s, o);
    EXPECT_EQ(s.specular, shading::Specular::phong);
    viewer::apply(Key::filter, s, o);
    EXPECT_EQ(s.filter, textures::Filter::nearest);
    viewer::apply(Key::normal_map, s, o);
    EXPECT_EQ(s.normal_map, normal_mapping::NormalMap::object);
    viewer::apply(Key::wireframe, s, o);
    EXPECT_TRUE(s.wireframe);
    viewer::apply(Key::coarser, s, o);
    viewer::apply(Key::coarser, s, o);
    viewer::apply(Key::coarser, s, o);
    EXPECT_EQ(s.scale, 4);  // no coarser than a quarter
    viewer::apply(Key::finer, s, o);
    EXPECT_EQ(s.scale, 2);
    viewer::apply(Key::turn_right, s, o);
    EXPECT_GT(o.yaw, 10);
    viewer::apply(Key::move_closer, s, o);
    EXPECT_LT(o.distance, 4);
    viewer::apply(Key::reset, s, o);
    EXPECT_EQ(s, viewer::Settings{});
}

TEST(Keys, EveryKeyHasANameAndAHelpLine) {
    for (char c : std::string("<>^vpsmfnw+-r")) {
        ASSERT_TRUE(viewer::key_named(c)) << c;
        EXPECT_NE(viewer::key_help().find(std::string("[") + c + "]"), std::string::npos) << c;
    }
    EXPECT_FALSE(viewer::key_named('x'));
}

TEST(Orbit, GivesBackTheCameraItCameFrom) {
    perspective::Camera c;
    c.eye = {1.5f, 2.0f, -3.0f};
    c.target = {0.2f, 0.4f, 0.1f};
    perspective::Box box;
    box.add(rl::vec3{-1, 0, -1});
    box.add(rl::vec3{1, 1, 1});
    const perspective::Camera back = viewer::camera_of(viewer::orbit_of(c), c, box, 1.0f);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(back.eye[k], c.eye[k], 1e-4f);
    EXPECT_GT(back.near, 0);
    EXPECT_LT(back.near, back.far);
}

TEST(Orbit, DraggingStopsShortOfThePoles) {
    viewer::Orbit o{0, 0, 3};
    viewer::drag(o, 0, 100000);
    EXPECT_LT(o.pitch, 90);
    perspective::Camera c;
    perspective::Box box;
    box.add(rl::vec3{-1, -1, -1});
    box.add(rl::vec3{1, 1, 1});
    EXPECT_NO_THROW(viewer::camera_of(o, c, box, 1.0f));  // up is never the view direction
}

struct Scene {
    normal_mapping::MappedView request;
    perspective::ViewedScene<normal_mapping::MappedModel> scene;
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

TEST(Wireframe, DrawsEdgesOverThePicture) {
    Scene s;
    viewer::FrameRenderer renderer(s.scene.models, s.request);
    viewer::Settings settings;
    const rl::Image plain = renderer.render(settings, s.scene.camera, 96, 64);
    settings.wireframe = true;
    EXPECT_NE(renderer.render(settings, s.scene.camera, 96, 64), plain);
}

TEST(Wireframe, EdgesBehindTheEyeAreCutNotDivided) {
    Scene s;
    perspective::Camera inside = s.scene.camera;
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
