// 07_failures: the page's "failure first" pictures of normal mapping
// (docs/07_normal_mapping.md). The lesson's render with one thing done
// wrong, or on a surface that shows a weak method's failure:
//   --mistake green-flipped       the tangent map's green channel read the
//                                 other way up (DirectX's convention, +v down)
//   --mistake handedness-ignored  every frame's w taken as +1: on mirrored
//                                 UVs the bitangent points the wrong way
//   --scene mirrored-plane        UVs mirrored down the middle: averaged
//                                 (vertex) frames are wrong along the seam
//   --scene low-poly-globe        few, large faces: each face's own frame
//                                 (face) jumps at every edge
#include <cstdio>

#include "05_perspective/view_options.hpp"
#include "07_normal_mapping/scene.hpp"
#include "rasterlab/cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/transform.hpp"
#include "test_surfaces.hpp"

namespace {

using namespace normal_mapping;

enum class SceneName { globe, crate, mirrored_plane, low_poly_globe };
RASTERLAB_NAMED_ENUM(SceneName, kScenes, {SceneName::globe, "globe"}, {SceneName::crate, "crate"},
                     {SceneName::mirrored_plane, "mirrored-plane"},
                     {SceneName::low_poly_globe, "low-poly-globe"});

enum class Mistake { none, green_flipped, handedness_ignored };
RASTERLAB_NAMED_ENUM(Mistake, kMistakes, {Mistake::none, "none"},
                     {Mistake::green_flipped, "green-flipped"},
                     {Mistake::handedness_ignored, "handedness-ignored"});

// The map with each texel's green byte inverted: what a renderer expecting
// +v up makes of a map baked with +v down, or the reverse.
textures::MipChain green_flipped(const textures::MipChain& map) {
    rl::Image image = map.level(0);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            rl::Rgba t = image.get(x, y);
            t.g = static_cast<std::uint8_t>(255 - t.g);
            image.set(x, y, t);
        }
    return textures::MipChain(std::move(image));
}

}  // namespace

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 07's failure pictures: the lesson's render with one mistake, or on a surface "
        "that shows a weak tangent method's failure."};
    rl::ImageOptions image_options{"07_failures.tga"};
    image_options.width = image_options.height = 256;
    SceneName scene = SceneName::globe;
    Mistake mistake = Mistake::none;
    TangentMethod tangents = TangentMethod::split;
    int segments = 12;
    std::vector<float> eye, light{0.3f, 0.5f, 1.0f};
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--scene", scene, kScenes, "Model to draw");
    rl::add_method_option(app, "--mistake", mistake, kMistakes, "The mistake to make");
    rl::add_method_option(app, "--tangents", tangents, kTangentMethods, "Tangent frames");
    app.add_option("--segments", segments, "Segments around the low-poly globe")
        ->capture_default_str()
        ->check(rl::range(3, 1024));
    app.add_option("--eye", eye, "Camera position (default: the scene's own), x y z")
        ->expected(3)
        ->check(rl::finite_number());
    rl::add_light_option(app, light);
    return app.run(argc, argv, "07_failures", [&] {
        rl::check_image_output(image_options.output);
        std::vector<std::string> warnings;
        pipeline::ViewOptions view;
        MappedModel model = [&] {
            switch (scene) {
                case SceneName::globe:
                    view.eye = {0.9f, 0.7f, 2.2f};  // the lab's view: the seam is behind
                    return load_mapped_model(rl::project_model("globe"), rl::mat4::identity(),
                                             tangents, warnings);
                case SceneName::crate:
                    view.eye = {-1.6f, 1.4f, 2.2f};
                    return load_mapped_model(rl::project_model("crate"), rl::mat4::identity(),
                                             tangents, warnings);
                case SceneName::mirrored_plane:
                    view.eye = {0.3f, -0.4f, 2.4f};
                    return mirrored_plane(tangents, warnings);
                case SceneName::low_poly_globe:
                    view.eye = {0.9f, 0.7f, 2.2f};
                    return low_poly_globe(segments, tangents, warnings);
            }
            throw std::logic_error("unknown scene");
        }();
        rl::print_warnings("07_failures", warnings);
        if (!eye.empty()) view.eye = eye;
        if (mistake == Mistake::green_flipped) {
            if (!model.maps.tangent_normals)
                throw std::invalid_argument(
                    "--mistake green-flipped: the model has no tangent map");
            model.maps.tangent_normals = green_flipped(*model.maps.tangent_normals);
        }
        if (mistake == Mistake::handedness_ignored)
            for (rl::vec4& t : model.tangents) t.w = 1;
        const int width = image_options.width, height = image_options.height;
        const pipeline::Camera camera = pipeline::resolve_camera(
            view, pipeline::bounds(model.lit.model.mesh, model.lit.model.transform),
            static_cast<float>(width) / static_cast<float>(height));
        const std::vector<MappedModel> models{std::move(model)};
        pipeline::ColourTarget frame = pipeline::colour_target(width, height);
        RenderOptions options;
        rl::check_direction("--light", light);
        options.lighting = shading::default_lighting(rl::vec3{light[0], light[1], light[2]});
        render(models, camera, options, frame);
        rl::save_image(image_options.output, frame.colour());
        std::printf("%s, %s tangents, mistake %s; into %s\n", name(scene),
                    normal_mapping::name(tangents), name(mistake), image_options.output.c_str());
        return 0;
    });
}
