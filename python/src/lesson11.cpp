// rasterlab.lesson11: 11_antialiasing, lesson 08's scene with several
// samples a pixel (supersampled or multisampled) or an edge filter after.
#include <pybind11/stl.h>

#include <optional>

#include "11_antialiasing/scene.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson11(py::module_ m) {
    const antialiasing::AaOptions defaults;
    m.def(
        "render",
        [](py::object models, std::optional<Camera> camera, const Numbers<"light">& light,
           Int<"width"> width, Int<"height"> height, const std::string& aa,
           std::optional<Int<"samples">> samples, const std::string& pattern,
           const std::string& resolve, std::optional<std::string> shade_at,
           const std::string& tone_map, Real<"exposure"> exposure, bool resolve_encoded,
           Real<"orbit"> orbit, const std::string& normal_map, const std::string& tangents) {
            check_size(width, height);
            antialiasing::AaOptions options;
            options.method = choice("--aa", aa, antialiasing::kMethods);
            if (samples) options.samples = *samples;
            options.pattern = choice("--pattern", pattern, antialiasing::kPatterns);
            options.resolve = choice("--resolve", resolve, antialiasing::kResolves);
            if (shade_at)
                options.shade_at = choice("--shade-at", *shade_at, antialiasing::kShadeAts);
            options.tone = choice("--tone-map", tone_map, antialiasing::kToneOrders);
            options.exposure_stops = finite("--exposure", exposure, -16, 16);
            options.resolve_encoded = resolve_encoded;
            const double orbit_degrees = finite("--orbit", orbit, -360, 360);
            // As the program: options the method would ignore are refused
            // (here a pattern or resolve counts as given when not its default).
            antialiasing::refuse_unused_options(
                options, {.samples = samples.has_value(),
                          .pattern = options.pattern != antialiasing::AaOptions{}.pattern,
                          .resolve = options.resolve != antialiasing::AaOptions{}.resolve,
                          .shade_at = shade_at.has_value()});
            antialiasing::check(options);
            antialiasing::check_frame_size(width, height, antialiasing::samples_of(options));
            shadows::ShadowOptions shadow;
            shadow.render.normal_map =
                choice("--normal-map", normal_map, normal_mapping::kNormalMaps);
            const auto frames = choice("--tangents", tangents, normal_mapping::kTangentMethods);
            const pipeline::ViewOptions view = view_options(models, camera, light);
            Result r;
            py::gil_scoped_release unlocked;
            shadows::set_lights(shadow, view, false);
            const auto scene = antialiasing::load_scene(view, frames, width, height, r.warnings);
            if (shadow.render.filter == textures::Filter::trilinear)
                normal_mapping::build_mip_levels(scene.models);
            check_signals();
            const antialiasing::Frame frame =
                antialiasing::render(scene.models, antialiasing::orbit(scene.camera, orbit_degrees),
                                     shadow, options, width, height);
            r.colour = frame.picture;
            r.count("faces", frame.counts.faces);
            r.count("fragments", frame.counts.shaded);
            r.count("samples_stored", frame.counts.stored);
            return r;
        },
        py::arg("models") = py::none(), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("light") = std::vector<double>{shadows::kSceneLight.x, shadows::kSceneLight.y,
                                               shadows::kSceneLight.z},
        py::arg("width") = 800, py::arg("height") = 800,
        py::arg("aa") = antialiasing::name(defaults.method), py::arg("samples") = py::none(),
        py::arg("pattern") = antialiasing::name(defaults.pattern),
        py::arg("resolve") = antialiasing::name(defaults.resolve), py::arg("shade_at") = py::none(),
        py::arg("tone_map") = antialiasing::name(defaults.tone),
        py::arg("exposure") = defaults.exposure_stops, py::arg("resolve_encoded") = false,
        py::arg("orbit") = 0.0, py::arg("normal_map") = "tangent", py::arg("tangents") = "split",
        "11_antialiasing: the floor, globe, crate and torus (or the models given, as stored) with "
        "several samples a pixel: aa='none', 'ssaa' (every sample shaded), 'msaa' (one shading "
        "a pixel, shade_at='centre' or 'centroid') or 'post' (one sample, then an edge filter); "
        "samples 2, 4, 8 or 16 as the pattern ('grid', 'rotated', 'standard') has them; "
        "resolve='box' or 'tent', in linear light; tone_map='after-resolve' or 'before-resolve' "
        "(lesson 09's ACES) with exposure in stops");
}

}  // namespace py_rl
