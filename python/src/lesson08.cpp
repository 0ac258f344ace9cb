// rasterlab.lesson08: 08_shadows, lesson 07's render with shadows from a
// shadow map of a directional or a spot light.
#include <pybind11/stl.h>

#include "03_zbuffer/depth_picture.hpp"
#include "08_shadows/scene.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "pipeline_result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson08(py::module_ m) {
    const shadows::ShadowOptions defaults;
    m.def(
        "render",
        [](py::object models, std::optional<Camera> camera, const Numbers<"light">& light,
           Int<"width"> width, Int<"height"> height, const std::string& light_type,
           const std::optional<Numbers<"light_position">>& light_position, Real<"cone"> cone,
           Int<"shadow_map_size"> shadow_map_size, Real<"bias"> bias, Real<"slope_bias"> slope_bias,
           Real<"normal_offset"> normal_offset, const std::string& filter, const std::string& fit,
           const std::string& map_faces, const std::string& show, const std::string& normal_map,
           const std::string& tangents, const std::string& specular,
           const std::string& texture_filter, bool one_light) {
            check_size(width, height);
            shadows::ShadowOptions options;
            options.light.type = choice("--light-type", light_type, shadows::kLightTypes);
            const std::vector<float> position =
                light_position ? three("--light-position", *light_position) : std::vector<float>{};
            options.light.cone_degrees = finite("--cone", cone, 1, 170);
            // A cone other than the default counts as given, as on the command line.
            shadows::refuse_spot_options(
                options.light.type, light_position.has_value(),
                options.light.cone_degrees != shadows::ShadowOptions{}.light.cone_degrees);
            options.map.size = shadow_map_size;
            options.map.constant_bias = finite("--bias", bias, 0, 0.1);
            options.map.slope_bias = finite("--slope-bias", slope_bias, 0, 100);
            options.lookup.normal_offset = finite("--normal-offset", normal_offset, 0, 100);
            options.lookup.filter = choice("--filter", filter, shadows::kShadowFilters);
            options.fit = choice("--fit", fit, shadows::kFits);
            options.map.cull =
                shadows::cull_for(choice("--map-faces", map_faces, shadows::kMapFaces));
            const shadows::Show picture = choice("--show", show, shadows::kShows);
            options.casters = picture != shadows::Show::unshadowed;
            options.render.normal_map =
                choice("--normal-map", normal_map, normal_mapping::kNormalMaps);
            const auto frames = choice("--tangents", tangents, normal_mapping::kTangentMethods);
            options.render.specular = choice("--specular", specular, shading::kSpeculars);
            options.render.filter = choice("--texture-filter", texture_filter, textures::kFilters);
            const pipeline::ViewOptions view = view_options(models, camera, light);
            Result r;
            py::gil_scoped_release unlocked;
            shadows::set_lights(options, view, one_light);
            const auto scene = shadows::load_scene(view, frames, width, height, r.warnings);
            check_signals();
            shadows::place_spot(options, shadows::scene_box(scene.models), position);
            const float aspect = static_cast<float>(width) / static_cast<float>(height);
            const shadows::ShadowMap map =
                shadows::shadow_map_for(scene.models, scene.camera, aspect, options);
            check_signals();
            pipeline::ColourTarget frame = pipeline::colour_target(width, height);
            const pipeline::PipelineCounts counts =
                shadows::render(scene.models, scene.camera, options, map, frame);
            take_frame(r, frame, counts, scene.camera);
            if (picture == shadows::Show::shadow_map) {
                r.colour = zbuffer::depth_picture(map.depth);
                r.depth.reset();  // the camera's depth would not match the picture
            }
            r.count("shadow_map_size", map.size());
            return r;
        },
        py::arg("models") = py::none(), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("light") = std::vector<double>{shadows::kSceneLight.x, shadows::kSceneLight.y,
                                               shadows::kSceneLight.z},
        py::arg("width") = 800, py::arg("height") = 800,
        py::arg("light_type") = shadows::name(defaults.light.type),
        py::arg("light_position") = py::none(), py::arg("cone") = defaults.light.cone_degrees,
        py::arg("shadow_map_size") = defaults.map.size,
        py::arg("bias") = defaults.map.constant_bias,
        py::arg("slope_bias") = defaults.map.slope_bias,
        py::arg("normal_offset") = defaults.lookup.normal_offset,
        py::arg("filter") = shadows::name(defaults.lookup.filter),
        py::arg("fit") = shadows::name(defaults.fit), py::arg("map_faces") = "front",
        py::arg("show") = "image",
        py::arg("normal_map") = normal_mapping::name(defaults.render.normal_map),
        py::arg("tangents") = "split",
        py::arg("specular") = shading::name(defaults.render.specular),
        py::arg("texture_filter") = textures::name(defaults.render.filter),
        py::arg("one_light") = false,
        "08_shadows: the floor, globe, crate and torus (or the models given, as stored) with "
        "lesson 07's shading, the key light shadowed through a shadow map (show='shadow-map': "
        "the map's depth as a picture instead)");
}

}  // namespace py_rl
