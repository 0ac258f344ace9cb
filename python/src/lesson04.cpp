// rasterlab.lesson04: 04_textures, a model with its diffuse texture, the
// filter and wrap mode of your choice.
#include <pybind11/stl.h>

#include "04_textures/textured.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "rasterlab/texture_files.hpp"
#include "rasterlab/transform.hpp"
#include "result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson04(py::module_ m) {
    const textures::TexturedOptions defaults;
    m.def(
        "draw",
        [](py::object model, Int<"width"> width, Int<"height"> height, const std::string& filter,
           const std::string& wrap, Real<"uv_scale"> uv_scale, Real<"uv_offset"> uv_offset,
           const Numbers<"turn">& turn, Real<"scale"> scale, bool no_light) {
            check_size(width, height);
            textures::TexturedOptions options;
            options.sampler.filter = choice("--filter", filter, textures::kFilters);
            options.sampler.wrap = choice("--wrap", wrap, textures::kWraps);
            options.uv_scale = finite("--uv-scale", uv_scale, -1e7, 1e7);
            options.uv_offset.x = options.uv_offset.y = finite("--uv-offset", uv_offset, -1e7, 1e7);
            if (turn.size() != 2)
                throw py::value_error(
                    "--turn: " + std::string(turn.size() < 2 ? "At least" : "At Most") +
                    " 2 required but received " + std::to_string(turn.size()));
            const float turn_x = finite("--turn", turn[0], -3600, 3600);
            const float turn_y = finite("--turn", turn[1], -3600, 3600);
            options.scale = finite("--scale", scale, 1e-6, 1e6);
            options.lighting = !no_light;
            options.rotation = rl::rotation_y(turn_y) * rl::rotation_x(turn_x);
            options.sampler.border = textures::kLoudBorder;
            const std::string path =
                model.is_none() ? rl::project_model("crate").string() : model_path(model);
            Result r;
            py::gil_scoped_release unlocked;
            const rl::Mesh mesh = rl::load_obj(path, &r.warnings);
            check_signals();
            const rl::Texture diffuse =
                rl::load_texture(mesh, 0, rl::TextureRole::diffuse, r.warnings);
            check_signals();
            const textures::MipChain chain(diffuse.image);
            check_signals();
            zbuffer::Frame frame(width, height);
            const triangles::DrawCounts counts =
                textures::draw_textured(frame, mesh, chain, options);
            r.count("drawn", counts.drawn);
            r.count("culled", counts.culled);
            r.count("refused", counts.refused);
            r.count("mip_levels", chain.levels());
            r.count("texture", diffuse.is_default ? std::string("a plain default")
                                                  : diffuse.source.filename().string());
            r.colour = std::move(frame.colour);
            r.depth = std::move(frame.depth);
            return r;
        },
        py::arg("model") = py::none(), py::kw_only(), py::arg("width") = 800,
        py::arg("height") = 800, py::arg("filter") = textures::name(defaults.sampler.filter),
        py::arg("wrap") = textures::name(defaults.sampler.wrap),
        py::arg("uv_scale") = defaults.uv_scale, py::arg("uv_offset") = 0.0,
        py::arg("turn") = std::vector<double>{textures::kDefaultTurnX, textures::kDefaultTurnY},
        py::arg("scale") = defaults.scale, py::arg("no_light") = false,
        "04_textures: a model (default obj/crate.obj) with its diffuse texture, orthographic, "
        "z-buffered, sampled with filter and wrap (the border colour is a loud magenta)");
}

}  // namespace py_rl
