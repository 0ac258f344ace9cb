// Lesson 13: the viewer. Lesson 12's fast path (with lesson 08's shadows,
// or lesson 07's renderer) live in a window: orbit with the mouse, switch the
// methods with keys, watch the frame time. Read docs/13_viewer.md beside it.
#include <SDL.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <stdexcept>
#include <vector>

#include "07_normal_mapping/mapped_cli.hpp"
#include "08_shadows/scene.hpp"
#include "12_fast/orbit.hpp"
#include "controls.hpp"
#include "frame_renderer.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "sdl_window.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 13, the viewer: lesson 12's fast path (with lesson 08's shadows, or lesson 07's "
        "renderer) live in a window; orbit, switch methods and watch the frame time."};
    app.footer(viewer::key_help());
    rl::ImageOptions window{"", 800, 800};
    normal_mapping::MappedCli cli;
    cli.every_normal_map = true;  // the N key switches between them
    // Lesson 08's light, from the side and above: the S key's shadows fall
    // where the default camera sees them (lesson 07's, from the camera's
    // side, hid them behind the models).
    cli.view.light = {shadows::kSceneLight.x, shadows::kSceneLight.y, shadows::kSceneLight.z};
    normal_mapping::add_mapped_options(app, cli, "floor, globe and crate from obj/");
    // A window no display shows whole costs memory and time for nothing:
    // 8192 a side is past the largest displays (8K is 7680 x 4320).
    app.add_option("--width", window.width, "Window width in pixels (1 to 8192)")
        ->capture_default_str()
        ->check(rl::range(1, 8192));
    app.add_option("--height", window.height, "Window height in pixels (1 to 8192)")
        ->capture_default_str()
        ->check(rl::range(1, 8192));
    int frames = 0;  // 0: until the window is closed
    app.add_option("--frames", frames,
                   "Render this many frames along lesson 12's orbit (the last is the view the "
                   "camera options give), then stop (1 to 1000; without it, run until the "
                   "window is closed)")
        ->check(rl::range(1, 1000));
    std::string screenshot;
    rl::Option* screenshot_option =
        app.add_option("-o,--screenshot", screenshot,
                       "Write the last frame, read back from the window, here (.tga or .png); "
                       "without --frames, after one frame");
    std::string keys;
    app.add_option("--keys", keys,
                   "Key presses to send through the window's event queue before the first "
                   "frame, one character each as the list below names them (at most 256)")
        ->check([](const std::string& text) -> std::string {
            if (text.size() > 256) return "at most 256 keys";
            for (std::size_t i = 0; i < text.size(); ++i) {
                if (viewer::key_named(text[i])) continue;
                // Name the whole character, not the first byte of its UTF-8.
                std::size_t end = i + 1;
                if (static_cast<unsigned char>(text[i]) >= 0xc0)
                    while (end < text.size() &&
                           (static_cast<unsigned char>(text[end]) & 0xc0) == 0x80)
                        ++end;
                return "no key is named '" + text.substr(i, end - i) + "'";
            }
            return {};
        });
    bool vsync = false;
    app.add_flag("--vsync", vsync,
                 "Wait for the display's refresh (the frame time is then not "
                 "the renderer's)");
    return app.run(argc, argv, "13_viewer", [&] {
        const int width = window.width, height = window.height;
        if (screenshot_option->count() > 0) {  // -o '' is refused, not ignored
            rl::check_image_output(screenshot);
            frames = std::max(frames, 1);  // a screenshot alone: one frame, then stop
        }
        if (frames > 0) fast::check_frames(frames, width, height);
        normal_mapping::MappedScene scene =
            normal_mapping::load_scene(cli, width, height, "13_viewer");
        const pipeline::Box box = normal_mapping::scene_box(scene.models);
        viewer::FrameRenderer renderer(scene.models, cli);
        viewer::Settings settings;
        settings.specular = cli.options.specular;
        settings.filter = cli.options.filter;
        settings.normal_map = cli.options.normal_map;
        settings.light = pipeline::light_direction(cli.view);
        viewer::Orbit orbit = viewer::orbit_of(scene.camera);
        const viewer::Orbit first_orbit = orbit;
        const viewer::Settings first_settings = settings;
        // The first frame, drawn before the window opens: a size the memory
        // cannot hold fails here with the programs' message and no window, and
        // the frame times shown leave out building the fast renderer.
        renderer.render(settings, scene.camera, width, height);

        viewer::SdlWindow sdl("rasterlab 13_viewer", width, height, vsync);
        sdl.send_keys(keys);
        std::deque<double> recent, loops;  // the last 30 frames' render times, whole loops
        std::deque<double> maps;           // the last 30 shadow map passes (frames with shadows)
        double median = 0;
        int drawn = 0;
        for (int i = 0; frames == 0 || i < frames; ++i, ++drawn) {
            const auto loop_start = std::chrono::steady_clock::now();
            viewer::Input input = sdl.poll();
            if (input.quit) break;
            for (viewer::Key key : input.keys)
                viewer::apply(key, settings, orbit, first_settings, first_orbit);
            viewer::drag(orbit, input.drag_x, input.drag_y);
            viewer::drag_light(settings, input.light_x, input.light_y);
            viewer::zoom(orbit, input.wheel);
            const int w = std::max(1, sdl.width() / settings.scale);
            const int h = std::max(1, sdl.height() / settings.scale);
            const float aspect = static_cast<float>(w) / static_cast<float>(h);
            // Scripted frames follow lesson 12's orbit, so that the last one is
            // exactly the camera the options give (and lesson 12's image).
            const pipeline::Camera camera =
                frames > 0 ? fast::orbit(scene.camera, i, frames)
                           : viewer::camera_of(orbit, scene.camera, cli.view, box, aspect);
            const auto start = std::chrono::steady_clock::now();
            const rl::Image& frame = renderer.render(settings, camera, w, h);
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            recent.push_back(ms);
            if (recent.size() > 30) recent.pop_front();
            if (settings.path == viewer::Path::shadows) {  // a frame without adds nothing
                maps.push_back(renderer.stats().shadow_map_ms);
                if (maps.size() > 30) maps.pop_front();
            }
            median = fast::median({recent.begin(), recent.end()});
            const bool last = frames > 0 && i == frames - 1;
            sdl.show(frame, last && !screenshot.empty() ? &screenshot : nullptr);
            loops.push_back(std::chrono::duration<double, std::milli>(
                                std::chrono::steady_clock::now() - loop_start)
                                .count());
            if (loops.size() > 30) loops.pop_front();
            if (i % 10 == 0 || last) {
                char title[512];
                std::snprintf(title, sizeof title,
                              "rasterlab 13_viewer: %.1f ms per frame (median of the last %zu), "
                              "%zu triangles, %zu pixels shaded, %dx%d; %s",
                              median, recent.size(), renderer.stats().triangles,
                              renderer.stats().pixels_shaded, w, h,
                              viewer::describe(settings).c_str());
                sdl.set_title(title);
            }
        }
        char map_pass[96] = "";
        if (settings.path == viewer::Path::shadows && !maps.empty())
            std::snprintf(map_pass, sizeof map_pass,
                          " (the shadow map's pass: %.2f ms of it, median of the last %zu)",
                          fast::median({maps.begin(), maps.end()}), maps.size());
        std::printf(
            "%d frames of %dx%d in a %dx%d window: median %.2f ms per frame to render%s, "
            "%.2f ms per loop with the upload and the window (the last %zu); settings: "
            "%s%s%s\n",
            drawn, renderer.frame().width(), renderer.frame().height(), sdl.width(), sdl.height(),
            median, map_pass, fast::median({loops.begin(), loops.end()}), recent.size(),
            viewer::describe(settings).c_str(), screenshot.empty() ? "" : "; screenshot ",
            screenshot.c_str());
        return 0;
    });
}
