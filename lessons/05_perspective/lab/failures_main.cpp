// 05_failures: the lab's clipping scenes as pictures, for the page's
// "failure first" figure (docs/05_perspective.md#clipping). Each pixel shows
// which triangle covers it, one colour per triangle: drawn by the pipeline
// with a clipping mode, or by the lab's ray-cast truth (--truth). Drawn with
// --clip none, the triangles behind the eye come out inverted and fill the
// frame; the lab counts that frame 100% wrong.
#include <cmath>
#include <cstdio>

#include "clipping_scenes.hpp"
#include "rasterlab/cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

namespace {

// A colour per triangle: hues a golden-ratio turn apart, so that
// neighbouring indices look different; none (-1) is the background.
rl::Rgba id_colour(int id) {
    if (id < 0) return rl::kBackground;
    const double hue = std::fmod(0.618033988749895 * id, 1.0) * 6;
    const auto channel = [&](double offset) {
        const double t = std::abs(std::fmod(hue + offset, 6.0) - 3) - 1;  // -1..2
        return static_cast<std::uint8_t>(std::lround(60 + 170 * std::clamp(t, 0.0, 1.0)));
    };
    return {channel(0), channel(4), channel(2), 255};
}

enum class SceneName { around_eye, floor };
RASTERLAB_NAMED_ENUM(SceneName, kScenes, {SceneName::around_eye, "around-eye"},
                     {SceneName::floor, "floor"});

}  // namespace

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 05's failure pictures: the lab's clipping scenes, each pixel coloured by the "
        "triangle that covers it."};
    rl::ImageOptions image_options{"05_failures.tga"};
    image_options.width = image_options.height = 512;  // the lab's size
    SceneName scene = SceneName::around_eye;
    pipeline::PipelineOptions options;
    bool truth = false;
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--scene", scene, kScenes, "The lab's clipping scene");
    rl::add_method_option(app, "--clip", options.clip, pipeline::kClipModes, "Clipping");
    app.add_flag("--truth", truth, "The lab's ray-cast truth instead of the pipeline");
    return app.run(argc, argv, "05_failures", [&] {
        rl::check_image_output(image_options.output);
        const pipeline::ClippingScene s = scene == SceneName::around_eye
                                              ? pipeline::around_eye_scene(200)
                                              : pipeline::floor_scene();
        const int width = image_options.width, height = image_options.height;
        pipeline::PipelineCounts counts;
        const rl::Grid<int> ids =
            truth ? pipeline::exact_ids(s.triangles, pipeline::RayCamera(s.camera, width, height))
                  : pipeline::pipeline_ids(s.triangles, s.camera, width, height, options, &counts);
        rl::Image picture(width, height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) picture.set(x, y, id_colour(ids.get(x, y)));
        rl::save_image(image_options.output, picture);
        std::printf("%s, %s: %zu triangles clipped, %zu outside; into %s\n", s.name.c_str(),
                    truth ? "ray-cast truth" : pipeline::name(options.clip), counts.clipped,
                    counts.outside, image_options.output.c_str());
        return 0;
    });
}
