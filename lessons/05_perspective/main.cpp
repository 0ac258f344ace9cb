// Lesson 05: perspective. Textured models seen through a camera: look-at,
// perspective projection, clipping in clip space, and texture coordinates
// interpolated perspective-correctly. Read docs/05_perspective.md beside it.
#include <cstdio>

#include "rasterlab/cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "scene.hpp"

namespace {

// --eye, --target, --up: three finite numbers each.
CLI::Option* add_point_option(CLI::App& app, const std::string& flag, std::vector<float>& point,
                              const std::string& what) {
    return app.add_option(flag, point, what + ", x y z")->expected(3)->check(rl::finite_number());
}

rl::vec3 to_vec3(const std::vector<float>& v) {
    return {v[0], v[1], v[2]};
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Lesson 05, perspective: textured models through a look-at camera and a perspective "
        "projection, clipped in clip space, texture coordinates interpolated "
        "perspective-correctly."};
    std::vector<std::string> model_paths;
    rl::ImageOptions image_options{"05_perspective.tga"};
    perspective::Camera camera;
    perspective::RenderOptions options;
    std::vector<float> eye, target, up{0, 1, 0};
    std::vector<float> light{options.light.x, options.light.y, options.light.z};
    app.add_option("-m,--model", model_paths,
                   "OBJ file to draw, as stored (repeat for several); default: floor, crate and "
                   "globe from obj/");
    rl::add_image_options(app, image_options);
    add_point_option(app, "--eye", eye, "Camera position (default: framing the scene)");
    add_point_option(app, "--target", target, "Point looked at (default: the scene's centre)");
    add_point_option(app, "--up", up, "Up direction")->capture_default_str();
    app.add_option("--fov", camera.fov_y, "Vertical field of view, degrees (0 to 180)")
        ->check(rl::finite_number())
        ->capture_default_str();
    auto* near = app.add_option("--near", camera.near,
                                "Near plane distance (default: just in front of the scene)")
                     ->check(rl::finite_number());
    auto* far =
        app.add_option("--far", camera.far, "Far plane distance (default: just behind the scene)")
            ->check(rl::finite_number());
    rl::add_light_option(app, light);
    rl::add_method_option(app, "--clip", options.pipeline.clip, perspective::kClipModes,
                          "Clipping");
    rl::add_method_option(app, "--interpolation", options.pipeline.interpolation,
                          perspective::kInterpolations, "Interpolation of texture coordinates");
    rl::add_method_option(app, "--lod", options.lod, perspective::kLodMethods,
                          "Mip level from each pixel's derivatives or one per triangle");
    rl::add_method_option(app, "--filter", options.sampler.filter, textures::kFilters,
                          "Texture filter");
    bool no_light = false;
    app.add_flag("--no-light", no_light, "Texture colour only, no Lambert shading");
    CLI11_PARSE(app, argc, argv);
    const std::string& output = image_options.output;
    const int width = image_options.width, height = image_options.height;

    return rl::guarded_main("05_perspective", [&] {
        rl::check_image_output(output);
        rl::check_direction("--light", light);
        options.light = to_vec3(light);
        options.lighting = !no_light;
        std::vector<std::string> warnings;
        std::vector<perspective::Model> models;
        if (model_paths.empty()) models = perspective::default_scene(warnings);
        for (const std::string& path : model_paths)  // as stored: the identity model matrix
            models.push_back(perspective::load_model(path, rl::mat4::identity(), warnings));
        rl::print_warnings("05_perspective", warnings);

        // [doc:lesson05-camera]
        const perspective::Box box = perspective::scene_bounds(models);
        const float aspect = static_cast<float>(width) / static_cast<float>(height);
        const perspective::Camera framed = perspective::frame_box(box, camera.fov_y, aspect);
        camera.eye = eye.empty() ? framed.eye : to_vec3(eye);
        camera.target = !target.empty() ? to_vec3(target) : box.empty() ? rl::vec3{} : box.centre();
        camera.up = to_vec3(up);
        const float chosen_near = camera.near, chosen_far = camera.far;
        perspective::fit_depth_range(camera, box);  // the defaults: just around the scene
        if (near->count()) camera.near = chosen_near;
        if (far->count()) camera.far = chosen_far;
        perspective::check(camera);
        // [/doc:lesson05-camera]

        zbuffer::Frame frame(width, height);
        const perspective::PipelineCounts counts =
            perspective::render(models, camera, options, frame);
        rl::save_image(output, frame.colour);
        std::printf(
            "%zu models (%zu culled by their boxes): %zu faces, %zu back faces, %zu clipped, "
            "%zu outside, %zu triangles drawn, %zu refused, %zu fragments shaded; eye (%g, %g, "
            "%g), near %g, far %g; %s interpolation, %s clipping, into %s\n",
            models.size(), counts.objects_culled, counts.faces, counts.back_faces, counts.clipped,
            counts.outside, counts.drawn, counts.refused, counts.fragments,
            static_cast<double>(camera.eye.x), static_cast<double>(camera.eye.y),
            static_cast<double>(camera.eye.z), static_cast<double>(camera.near),
            static_cast<double>(camera.far), perspective::name(options.pipeline.interpolation),
            perspective::name(options.pipeline.clip), output.c_str());
        return 0;
    });
}
