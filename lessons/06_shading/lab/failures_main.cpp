// 06_failures: the page's "failure first" pictures of lighting
// (docs/06_shading.md#lighting). A plain sphere (no texture) lit by one
// light, with any shading model and exponent, to set Phong's highlight
// beside Blinn's at the same exponent; or with the classic mistake of the
// specular term: pow(r . v, shininess) without clamping r . v at 0 first,
// which lights a false highlight where the reflection points away from the
// eye (an even exponent) or writes NaN (a fractional one).
#include <cmath>
#include <cstdio>

#include "05_perspective/view_cli.hpp"
#include "06_shading/shaders.hpp"
#include "06_shading/truths/sphere_truth.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

namespace {

using namespace shading;

// Phong shading with the mistake: the highlight's base not clamped at 0.
struct UnclampedPowShader {
    PhongShader phong;
    Lighting<float> matte;  // the lighting without its specular part
    using Varyings = PhongShader::Varyings;
    pipeline::ClipVertex<Varyings> vertex(const SurfaceCorner& in) const {
        return phong.vertex(in);
    }
    rl::vec3 fragment(const pipeline::Fragment<Varyings>& f) const {
        const rl::vec3 n = rl::normalize(f.varyings.normal);
        const rl::vec3 to_eye = rl::normalize(phong.u.eye - f.varyings.position);
        rl::vec3 c = reflected(matte, n, to_eye, phong.u.colour, phong.specular);
        const Lighting<float>& lit = phong.u.lighting;
        for (const Light<float>& light : lit.lights) {
            const float n_dot_l = rl::dot(n, light.direction);
            if (!(n_dot_l > 0)) continue;
            const float s = alignment(n, light.direction, to_eye, n_dot_l, phong.specular);
            c += light.colour * lit.specular * std::pow(s, lit.shininess);  // the mistake
        }
        return c;
    }
};

enum class Mistake { none, unclamped_pow };
RASTERLAB_NAMED_ENUM(Mistake, kMistakes, {Mistake::none, "none"},
                     {Mistake::unclamped_pow, "unclamped-pow"});

}  // namespace

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 06's failure pictures: a plain sphere lit by one light, correctly or with the "
        "unclamped pow of the specular term."};
    rl::ImageOptions image_options{"06_failures.tga"};
    image_options.width = image_options.height = 256;
    ShadingModel model = ShadingModel::phong;
    Mistake mistake = Mistake::none;
    float shininess = 32;
    int segments = 128;
    std::vector<float> light{0.3f, 0.5f, 1.0f};
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--shading", model, kShadingModels, "Shading model");
    rl::add_method_option(app, "--mistake", mistake, kMistakes,
                          "The mistake to make (unclamped-pow: Phong's highlight only)");
    app.add_option("--shininess", shininess, "Specular exponent")
        ->capture_default_str()
        ->check(rl::finite_number(0, 1e6));
    app.add_option("--segments", segments, "Segments around the UV sphere")
        ->capture_default_str()
        ->check(rl::range(3, 1024));
    rl::add_light_option(app, light);
    return app.run(argc, argv, "06_failures", [&] {
        rl::check_image_output(image_options.output);
        rl::check_direction("--light", light);
        const int width = image_options.width, height = image_options.height;
        pipeline::Camera camera;  // the lab's view of the unit sphere
        camera.eye = {0, 0, 3.2f};
        camera.target = {0, 0, 0};
        camera.fov_y = 45;
        camera.near = 1;
        camera.far = 10;
        Lighting<float> lighting = default_lighting(rl::vec3{light[0], light[1], light[2]});
        lighting.lights.resize(1);  // the key light alone: one highlight to look at
        lighting.shininess = shininess;
        const float aspect = static_cast<float>(width) / static_cast<float>(height);
        const Uniforms u{.model_matrix = rl::mat4::identity(),
                         .normal_matrix = rl::mat3::identity(),
                         .model_view_projection = pipeline::view_projection(camera, aspect),
                         .eye = camera.eye,
                         .lighting = lighting,
                         .colour = rl::vec3{0.8f, 0.35f, 0.2f}};
        const rl::Mesh sphere = uv_sphere(segments);
        const std::vector<rl::vec3> normals = corner_normals(sphere, Weighting::angle);
        const Surface surface(sphere, normals);
        pipeline::ColourTarget frame = pipeline::colour_target(width, height);
        if (mistake == Mistake::unclamped_pow) {
            if (model != ShadingModel::phong && model != ShadingModel::blinn_phong)
                throw std::invalid_argument(
                    "--mistake unclamped-pow: the highlight is lit per "
                    "pixel, with --shading phong or blinn-phong");
            Lighting<float> matte = lighting;
            matte.specular = {0, 0, 0};
            const Specular specular =
                model == ShadingModel::phong ? Specular::phong : Specular::blinn_phong;
            draw(surface, UnclampedPowShader{PhongShader{u, specular}, matte}, frame, {});
        } else {
            draw_model(model, surface, u, frame, {}, Output::srgb);
        }
        rl::save_image(image_options.output, frame.colour());
        std::printf("%s shading, exponent %g, mistake %s; into %s\n", name(model), shininess,
                    name(mistake), image_options.output.c_str());
        return 0;
    });
}
