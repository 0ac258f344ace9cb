// Lesson 03: the z-buffer. Draws a scene of overlapping models with flat
// shading and hidden surfaces removed by the method of your choice, and a
// picture of the depth buffer. Read docs/03_zbuffer.md beside this file.
#include <algorithm>
#include <cstdio>

#include "depth_picture.hpp"
#include "hidden_surfaces.hpp"
#include "hsr_scenes.hpp"
#include "rasterlab/cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "zfight.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 03, the z-buffer: overlapping models, hidden surfaces removed "
        "(orthographic, flat shading)."};
    std::string model;
    std::string depth_output;
    rl::ImageOptions image_options{"03_zbuffer.tga"};
    zbuffer::HsrMethod method = zbuffer::HsrMethod::zbuffer;
    const rl::Option* model_option = app.add_option(
        "-m,--model", model, "OBJ file to draw alone (default: the rock pierced by the torus)");
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--hsr", method, zbuffer::kHsrMethods, "Hidden-surface method");
    app.add_option("--depth-out", depth_output, "Also write the depth buffer as a picture here");
    std::string scene_name = "models";
    app.add_option(
           "--scene", scene_name,
           "models (the rock pierced by the torus), sticks (three sticks in a cycle) or soup "
           "(60 triangles piercing each other)")
        ->check(rl::one_of(zbuffer::kProgramScenes))
        ->capture_default_str();
    auto* zfight = app.add_subcommand(
        "zfight",
        "Instead: the depth-precision experiment (two planes 0.01 apart, perspective) as a "
        "picture, red where the far plane wrongly wins");
    zbuffer::DepthFormat format = zbuffer::DepthFormat::float_z;
    zbuffer::TwoPlanes planes;
    zbuffer::DepthRange range{0.1f, 1000.0f};
    bool fitted = false;
    rl::add_method_option(*zfight, "--format", format, zbuffer::kDepthFormats, "Depth format");
    zfight->add_option("--distance", planes.distance, "Distance to the planes")
        ->check(rl::finite_number(1e-3, 1e6))
        ->capture_default_str();
    zfight->add_option("--near", range.near_plane, "Near plane")
        ->check(rl::positive_number())
        ->capture_default_str();
    zfight->add_option("--far", range.far_plane, "Far plane")
        ->check(rl::positive_number())
        ->capture_default_str();
    zfight->add_flag("--fitted", fitted, "Fit near and far to the planes instead");
    return app.run(argc, argv, "03_zbuffer", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        const bool model_given = model_option->count() > 0;  // even as --model '': no such file
        // Every output is checked before any work and written only when all
        // are ready, so a bad --depth-out cannot cost the colour image.
        rl::ImageOutputs outputs;
        outputs.check(output);
        if (!depth_output.empty()) outputs.check(depth_output);
        if (zfight->parsed()) {
            planes.size = std::min(width, height);
            if (fitted) range = zbuffer::fitted_range(planes);
            if (!(range.near_plane > 0 && range.near_plane < range.far_plane))
                throw std::invalid_argument("need 0 < near < far");
            outputs.stage(output, zbuffer::zfight_map(format, range, planes));
            outputs.commit();
            std::printf(
                "z-fighting with %s, near %g, far %g, distance %g: %.2f%% of pixels, in %s\n",
                zbuffer::name(format), range.near_plane, range.far_plane, planes.distance,
                100.0 * zbuffer::zfight_share(format, range, planes), output.c_str());
            return 0;
        }
        std::vector<zbuffer::Placement> placements = zbuffer::default_placements();
        if (model_given) placements = {{model}};
        std::vector<std::string> warnings;
        std::size_t culled = 0;
        const std::vector<zbuffer::SceneTriangle> scene =
            zbuffer::program_scene(scene_name, placements, width, height, warnings, culled);
        rl::print_warnings("03_zbuffer", warnings);
        // [doc:lesson03-main]
        zbuffer::Frame frame(width, height);
        zbuffer::render(method, scene, frame);
        outputs.stage(output, frame.colour);
        if (!depth_output.empty()) outputs.stage(depth_output, zbuffer::depth_picture(frame.depth));
        outputs.commit();
        // [/doc:lesson03-main]
        std::printf("%zu triangles drawn, %zu culled, %zu refused, with %s into %s\n",
                    scene.size() - frame.refused, culled, frame.refused, zbuffer::name(method),
                    output.c_str());
        return 0;
    });
}
