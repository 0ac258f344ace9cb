#include "scene.hpp"

#include "02_triangles/flat_shading.hpp"
#include "04_textures/textured.hpp"
#include "rasterlab/texture_files.hpp"

namespace pipeline {

TexturedModel load_model(const std::filesystem::path& path, const rl::mat4& transform,
                         std::vector<std::string>& warnings,
                         const textures::TexelEncoding* encoding) {
    rl::Mesh mesh = rl::load_obj(path, &warnings);
    rl::Texture diffuse = rl::load_texture(mesh, 0, rl::TextureRole::diffuse, warnings);
    std::string texture_name =
        diffuse.is_default ? "a plain default" : diffuse.source.filename().string();
    const Box box = bounds(mesh, rl::mat4::identity());
    return {std::move(mesh), transform, box, textures::MipChain(std::move(diffuse.image), encoding),
            std::move(texture_name)};
}

// [doc:default-scene]
std::vector<TexturedModel> default_scene(std::vector<std::string>& warnings) {
    std::vector<TexturedModel> models;
    models.push_back(load_model(rl::project_model("floor"),
                                rl::compose({.scale = {2.2f, 2.2f, 2.2f}}), warnings));
    models.push_back(load_model(rl::project_model("crate"),  // edge 1.1: its base on y = 0
                                rl::compose({.translation = {-0.9f, 0.55f, 0.5f},
                                             .rotation = rl::axis_angle({0, 1, 0}, 30)}),
                                warnings));
    models.push_back(load_model(rl::project_model("globe"),  // radius 0.9, resting on the floor
                                rl::compose({.translation = {1.0f, 0.9f, -0.6f},
                                             .rotation = rl::axis_angle({0, 1, 0}, -60)}),
                                warnings));
    return models;
}
// [/doc:default-scene]

Box scene_bounds(const std::vector<TexturedModel>& models) {
    Box box;
    for (const TexturedModel& model : models) box.add(bounds(model.mesh, model.transform));
    return box;
}

Camera view_camera(const ViewOptions& view, const Box& box, int width, int height,
                   std::vector<std::string>& warnings) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const Camera camera = resolve_camera(view, box, aspect);
    if (std::string warning = depth_precision_warning(camera); !warning.empty())
        warnings.push_back(std::move(warning));
    return camera;
}

ViewedScene<TexturedModel> load_scene(const ViewOptions& view, int width, int height,
                                      std::vector<std::string>& warnings) {
    const rl::TexelBudget budget;  // for the textures of all the models together
    ViewedScene<TexturedModel> scene;
    if (view.models.empty()) scene.models = default_scene(warnings);
    for (const std::string& path : view.models)
        scene.models.push_back(load_model(path, rl::mat4::identity(), warnings));
    scene.camera = view_camera(view, scene_bounds(scene.models), width, height, warnings);
    return scene;
}

namespace {

// Lesson 02's flat Lambert term of every face, in world space.
std::vector<float> face_light(const TexturedModel& model, const RenderOptions& options) {
    std::vector<float> light(model.mesh.faces.size(), 1.0f);
    if (!options.lighting) return light;
    for (std::size_t i = 0; i < light.size(); ++i) {
        rl::vec3 world[3];
        for (int k = 0; k < 3; ++k)
            world[k] =
                (model.transform * rl::extend(model.mesh.position(model.mesh.faces[i], k), 1.0f))
                    .xyz();
        light[i] =
            triangles::lambert(rl::cross(world[1] - world[0], world[2] - world[0]), options.light);
    }
    return light;
}

// Lesson 04's per-triangle estimate, from the set-up triangle's window
// positions and texture coordinates.
textures::UvDerivatives affine_derivatives(const TriangleSetup<rl::vec2>& t) {
    const rl::vec2 window[3] = {t.window[0].xy(), t.window[1].xy(), t.window[2].xy()};
    return textures::affine_derivatives(window, t.vertex);
}

}  // namespace

// [doc:textured-program]
rl::Rgba TexturedProgram::fragment(const Fragment<rl::vec2>& f) const {
    // Each pixel's own derivatives, or lesson 04's affine estimate from the
    // triangle's corners (the same for the whole triangle).
    const textures::UvDerivatives d = lod == LodMethod::pixel
                                          ? textures::UvDerivatives{f.d_dx(), f.d_dy()}
                                          : affine_derivatives(*f.triangle);
    const rl::vec4 c = textures::sample(texture, f.varyings, d, sampler);
    const float shade = light[static_cast<std::size_t>(f.face())];
    return textures::to_rgba({c.x * shade, c.y * shade, c.z * shade, 1.0f});
}
// [/doc:textured-program]

// [doc:render-model]
PipelineCounts render(const std::vector<TexturedModel>& models, const Camera& camera,
                      const RenderOptions& options, ColourTarget& frame) {
    const rl::mat4 view_proj = view_projection(
        camera, static_cast<float>(frame.width()) / static_cast<float>(frame.height()));
    PipelineCounts counts;
    for (const TexturedModel& model : models) {
        const rl::mat4 mvp = view_proj * model.transform;
        if (options.cull_objects && outside_frustum(model.box, mvp)) {
            ++counts.objects_culled;
            continue;
        }
        const std::vector<float> light = face_light(model, options);
        const TexturedProgram program{mvp, model.texture, options.sampler, options.lod, light};
        counts += draw(MeshView(model.mesh, model.transform), program, frame, options.pipeline);
    }
    return counts;
}
// [/doc:render-model]

}  // namespace pipeline
