// rasterlab.lesson10: 10_ambient_occlusion, lesson 08's scene drawn into a
// G-buffer, its ambient light darkened by screen-space or baked occlusion.
#include <pybind11/stl.h>

#include <optional>

#include "10_ambient_occlusion/scene.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson10(py::module_ m) {
    const occlusion::AoOptions defaults;
    m.def(
        "render",
        [](py::object models, std::optional<Camera> camera, const Numbers<"light">& light,
           Int<"width"> width, Int<"height"> height, const std::string& ao, Int<"samples"> samples,
           Real<"radius"> radius, Int<"blur"> blur, bool rotation,
           std::optional<py::object> environment, const std::string& show,
           const std::string& normal_map, const std::string& tangents) {
            check_size(width, height);
            occlusion::check_frame_size(width, height);
            occlusion::SceneOptions options;
            options.ao.method = choice("--ao", ao, occlusion::kAoMethods);
            in_range("--samples", samples, 1, occlusion::kMaxAoSamples);
            options.ao.samples = samples;
            options.ao.radius = finite("--radius", radius, 1e-4, 1e4);
            in_range("--blur", blur, 0, occlusion::kMaxBlurRadius);
            options.ao.blur = blur;
            options.ao.rotate = rotation;
            const occlusion::Show picture = choice("--show", show, occlusion::kShows);
            options.shadow.render.normal_map =
                choice("--normal-map", normal_map, normal_mapping::kNormalMaps);
            const auto frames = choice("--tangents", tangents, normal_mapping::kTangentMethods);
            const std::optional<std::string> source =
                environment ? std::optional(environment_source(*environment)) : std::nullopt;
            // As the program: an option the method or the picture would
            // ignore is refused; here one counts as given when it is not its
            // default.
            const occlusion::AoOptions d;
            const std::vector<float> scene_light = {shadows::kSceneLight.x, shadows::kSceneLight.y,
                                                    shadows::kSceneLight.z};
            occlusion::refuse_unused_options(options.ao, source.has_value(), picture,
                                             {.ao = options.ao.method != d.method,
                                              .samples = samples != d.samples,
                                              .radius = options.ao.radius != d.radius,
                                              .blur = blur != d.blur,
                                              .no_rotation = !rotation,
                                              .light = three("--light", light) != scene_light});
            const pipeline::ViewOptions view = view_options(models, camera, light);
            Result r;
            py::gil_scoped_release unlocked;
            std::optional<occlusion::EnvironmentLighting> lighting;
            if (source) {
                lighting.emplace(*source, r.warnings);
                options.environment = &lighting->light();
            }
            shadows::set_lights(options.shadow, view, false);
            const auto scene = occlusion::load_scene(view, frames, width, height, r.warnings);
            if (options.shadow.render.filter == textures::Filter::trilinear)
                normal_mapping::build_mip_levels(scene.models);
            check_signals();
            std::optional<occlusion::BakedAo> baked;
            if (options.ao.method == occlusion::AoMethod::baked)
                baked =
                    occlusion::bake_vertex_ao(scene.models, occlusion::RayTracedAo(scene.models),
                                              options.ao.radius, options.ao.samples);
            check_signals();
            const occlusion::Frame frame = occlusion::render(
                scene.models, scene.camera, options, width, height, baked ? &*baked : nullptr);
            const occlusion::Screen screen(scene.camera, width, height);
            r.colour = occlusion::picture(frame, options, picture, &screen);
            r.depth = *frame.g.depth();
            r.count("faces", frame.counts.faces);
            r.count("fragments", frame.counts.shaded);
            return r;
        },
        py::arg("models") = py::none(), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("light") = std::vector<double>{shadows::kSceneLight.x, shadows::kSceneLight.y,
                                               shadows::kSceneLight.z},
        py::arg("width") = 800, py::arg("height") = 800,
        py::arg("ao") = occlusion::name(defaults.method), py::arg("samples") = defaults.samples,
        py::arg("radius") = defaults.radius, py::arg("blur") = defaults.blur,
        py::arg("rotation") = true, py::arg("environment") = py::none(), py::arg("show") = "image",
        py::arg("normal_map") = "tangent", py::arg("tangents") = "split",
        "10_ambient_occlusion: the floor, globe, crate and torus (or the models given, as "
        "stored) into a G-buffer, lesson 08's direct light plus an ambient light darkened by "
        "ambient occlusion (ao='none', 'crytek', 'hemisphere', 'horizon' or 'baked'); "
        "show='ao' gives the occlusion alone, 'direct', 'albedo', 'normal' or 'depth' a "
        "G-buffer image; environment='sky', 'studio', 'white' or an .hdr path lights it by "
        "lesson 09's environment instead, whose diffuse light the occlusion darkens");
}

}  // namespace py_rl
