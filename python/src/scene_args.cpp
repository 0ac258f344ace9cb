#include "scene_args.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "keywords.hpp"
#include "rasterlab/texture_files.hpp"

namespace py_rl {

std::string model_path(py::handle model, const char* keyword) {
    if (py::isinstance<Mesh>(model)) return model.cast<const Mesh&>().mesh.source.string();
    if (py::isinstance<py::str>(model) || py::hasattr(model, "__fspath__"))
        return fs_path(model, keyword).string();
    throw py::type_error("a model is a path (str or os.PathLike) or a rasterlab.Mesh, not " +
                         std::string(py::str(py::type::of(model).attr("__name__"))));
}

std::string environment_source(py::handle environment) {
    if (py::isinstance<py::str>(environment) || py::hasattr(environment, "__fspath__"))
        return fs_path(environment, "environment").string();
    throw py::type_error(
        "environment: a name (sky, studio, white) or the path of a lat-long .hdr file (str or "
        "os.PathLike), not " +
        std::string(py::str(py::type::of(environment).attr("__name__"))));
}

std::vector<std::string> model_paths(py::handle models) {
    if (models.is_none()) return {};
    if (py::isinstance<Mesh>(models) || py::isinstance<py::str>(models) ||
        py::hasattr(models, "__fspath__"))
        return {model_path(models, "models")};
    if (py::isinstance<py::bytes>(models) || !py::isinstance<py::iterable>(models))
        return {model_path(models, "models")};  // (which says what a model is)
    std::vector<std::string> paths;
    for (py::handle m : models) {
        if (paths.size() == pipeline::kMaxModels)
            throw py::value_error("--model: at most " + std::to_string(pipeline::kMaxModels) +
                                  " models, each loaded whole");
        paths.push_back(model_path(m, "models"));
    }
    // The programs cannot be asked for no model: None is the default scene.
    if (paths.empty())
        throw py::value_error("models: an empty list (None draws the lesson's default scene)");
    return paths;
}

pipeline::ViewOptions view_options(py::handle models, const std::optional<Camera>& camera,
                                   const std::vector<double>& light) {
    pipeline::ViewOptions view;
    view.models = model_paths(models);
    view.light = three("--light", light);
    if (camera) {
        view.eye = camera->eye;
        view.target = camera->target;
        view.up = camera->up;
        view.camera.fov_y = camera->fov;
        if (camera->near) view.camera.near = *camera->near, view.near_given = true;
        if (camera->far) view.camera.far = *camera->far, view.far_given = true;
    }
    return view;
}

std::vector<double> default_light() {
    const std::vector<float> light = pipeline::ViewOptions{}.light;
    return {light.begin(), light.end()};
}

void check_size(int width, int height) {
    in_range("--width", width, 1, 16384);
    in_range("--height", height, 1, 16384);
}

namespace {

// A copy of an array of vectors as an N x K float32 array.
template <class V, std::size_t K>
py::array_t<float> rows_of(const std::vector<V>& values) {
    py::array_t<float> out({static_cast<py::ssize_t>(values.size()), static_cast<py::ssize_t>(K)});
    auto w = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < values.size(); ++i)
        for (std::size_t k = 0; k < K; ++k)
            w(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(k)) = values[i][k];
    return out;
}

template <class Numbers>
std::optional<std::vector<float>> point(const char* option, const std::optional<Numbers>& p) {
    if (!p) return std::nullopt;
    return three(option, *p);
}

// None for a point left to the framing (an empty vector), else the point.
py::object optional_point(const std::vector<float>& p) {
    if (p.empty()) return py::none();
    return py::cast(p);
}

}  // namespace

void bind_scene_args(py::module_& m) {
    py::class_<Mesh>(m, "Mesh",
                     "An OBJ file as rasterlab reads it (triangulated), with its material's "
                     "texture files. Pass it (or its path) to any lesson's render function.")
        .def_property_readonly("path", [](const Mesh& s) { return path_text(s.mesh.source); })
        .def_property_readonly(
            "positions", [](const Mesh& s) { return rows_of<rl::vec3, 3>(s.mesh.positions); },
            "N x 3 float32 vertex positions (a copy)")
        .def_property_readonly(
            "uvs", [](const Mesh& s) { return rows_of<rl::vec2, 2>(s.mesh.uvs); },
            "N x 2 float32 texture coordinates (a copy)")
        .def_property_readonly(
            "normals", [](const Mesh& s) { return rows_of<rl::vec3, 3>(s.mesh.normals); },
            "N x 3 float32 normals as the file gives them (a copy)")
        .def_property_readonly(
            "faces",
            [](const Mesh& s) {
                py::array_t<std::int32_t> out(
                    {static_cast<py::ssize_t>(s.mesh.faces.size()), py::ssize_t{3}});
                auto w = out.mutable_unchecked<2>();
                for (std::size_t i = 0; i < s.mesh.faces.size(); ++i)
                    for (int k = 0; k < 3; ++k)
                        w(static_cast<py::ssize_t>(i), k) =
                            s.mesh.faces[i].corners[static_cast<std::size_t>(k)].position;
                return out;
            },
            "F x 3 int32 indices into positions, one row per triangle (a copy)")
        .def_property_readonly(
            "textures",
            [](const Mesh& s) {
                py::dict found;
                const std::pair<const char*, rl::TextureRole> roles[] = {
                    {"diffuse", rl::TextureRole::diffuse},
                    {"normal_tangent", rl::TextureRole::normal_tangent},
                    {"normal_object", rl::TextureRole::normal_object},
                    {"specular", rl::TextureRole::specular}};
                for (const auto& [name, role] : roles)
                    if (const auto path = rl::find_texture(s.mesh, 0, role))
                        found[name] = path_text(*path);
                return found;
            },
            "The texture files the lessons would use for the first material, by role")
        .def_property_readonly("warnings",
                               [](const Mesh& s) {
                                   py::list out;
                                   for (const std::string& w : s.warnings) out.append(text(w));
                                   return out;
                               })
        .def("__repr__", [](const Mesh& s) {
            return text("<rasterlab.Mesh " + s.mesh.source.string() + ": " +
                        std::to_string(s.mesh.faces.size()) + " triangles>");
        });

    m.def(
        "load_mesh",
        [](const Path& path) {
            Mesh out;
            {
                py::gil_scoped_release unlocked;
                // Kept whole, so that the Mesh still finds its file after a
                // chdir. '' stays '' (the programs' "no such file", not
                // "cannot make absolute path"), and so does a path when the
                // working folder is gone.
                std::error_code ec;
                std::filesystem::path whole = path;
                if (!path.empty()) whole = std::filesystem::absolute(path, ec);
                out.mesh = rl::load_obj(ec ? std::filesystem::path(path) : whole, &out.warnings);
            }
            return out;
        },
        py::arg("path"),
        "Reads an OBJ file (and its MTL files) as every lesson does; raises OSError naming the "
        "file and the problem for a missing, unreadable or malformed one.");

    py::class_<Camera>(m, "Camera",
                       "Lesson 05's camera options. What is None is framed to fit the scene, "
                       "as the programs do without --eye, --target, --near or --far.")
        .def(py::init([](std::optional<Numbers<"eye">> eye, std::optional<Numbers<"target">> target,
                         Numbers<"up"> up, Real<"fov"> fov, std::optional<Real<"near">> near,
                         std::optional<Real<"far">> far) {
                 Camera c;
                 c.eye = point("--eye", eye).value_or(std::vector<float>{});
                 c.target = point("--target", target).value_or(std::vector<float>{});
                 c.up = three("--up", up);
                 c.fov = finite("--fov", fov);
                 if (near) c.near = finite("--near", *near);
                 if (far) c.far = finite("--far", *far);
                 return c;
             }),
             py::kw_only(), py::arg("eye") = py::none(), py::arg("target") = py::none(),
             py::arg("up") = std::vector<double>{0, 1, 0}, py::arg("fov") = 50.0,
             py::arg("near") = py::none(), py::arg("far") = py::none())
        .def_property_readonly("eye", [](const Camera& c) { return optional_point(c.eye); })
        .def_property_readonly("target", [](const Camera& c) { return optional_point(c.target); })
        .def_readonly("up", &Camera::up)
        .def_readonly("fov", &Camera::fov)
        .def_readonly("near", &Camera::near)
        .def_readonly("far", &Camera::far)
        .def("__repr__", [](const Camera& c) {
            const auto text = [](const std::vector<float>& p) -> std::string {
                if (p.empty()) return "None";
                return "(" + py::str(py::float_(p[0])).cast<std::string>() + ", " +
                       py::str(py::float_(p[1])).cast<std::string>() + ", " +
                       py::str(py::float_(p[2])).cast<std::string>() + ")";
            };
            const auto number = [](const std::optional<float>& v) -> std::string {
                return v ? py::str(py::float_(*v)).cast<std::string>() : "None";
            };
            return "rasterlab.Camera(eye=" + text(c.eye) + ", target=" + text(c.target) +
                   ", up=" + text(c.up) + ", fov=" + number(c.fov) + ", near=" + number(c.near) +
                   ", far=" + number(c.far) + ")";
        });
}

}  // namespace py_rl
