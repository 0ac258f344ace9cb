#include "frame_renderer.hpp"

#include "08_shadows/scene.hpp"

#include <chrono>
#include "wire_overlay.hpp"

namespace viewer {

namespace {

// The wireframe's colour: a warm white that reads over the lit scene.
constexpr rl::Rgba kWire{255, 236, 160, 255};

}  // namespace

FrameRenderer::FrameRenderer(const std::vector<normal_mapping::MappedModel>& models,
                             const normal_mapping::MappedView& request)
    : models_(models), request_(request) {
    for (const normal_mapping::MappedModel& m : models) faces_ += m.lit.model.mesh.faces.size();
}

bool FrameRenderer::light_moved(const Settings& s) const {
    return !(s.light == pipeline::light_direction(request_.view));
}

normal_mapping::RenderOptions FrameRenderer::options_for(const Settings& s) const {
    normal_mapping::RenderOptions options = request_.options;
    options.specular = s.specular;
    options.filter = s.filter;
    options.normal_map = s.normal_map;
    // The lights as lesson 07's load_scene() makes them, from the moved
    // light (until it moves: --light's, exactly as loaded).
    if (light_moved(s)) {
        options.lighting = shading::default_lighting(s.light);
        if (request_.one_light) options.lighting.lights.resize(1);
    }
    return options;
}

shadows::ShadowOptions FrameRenderer::shadow_options(
    const Settings& s, const normal_mapping::RenderOptions& options) const {
    shadows::ShadowOptions shadowed;
    shadowed.render = options;  // then its lights from lesson 08's key light
    shadows::set_lights(shadowed, request_.view, request_.one_light);
    if (light_moved(s)) {
        shadowed.light.direction = rl::normalize(s.light);
        shadowed.render.lighting = options.lighting;
    }
    return shadowed;
}

const rl::Image& FrameRenderer::render(const Settings& settings, const pipeline::Camera& camera,
                                       int width, int height) {
    stats_ = {faces_, 0, 0};
    const normal_mapping::RenderOptions options = options_for(settings);
    if (settings.path == Path::lesson07) {
        pipeline::ColourTarget target = pipeline::colour_target(width, height);
        stats_.pixels_shaded = normal_mapping::render(models_, camera, options, target).shaded;
        picture_ = std::move(target.colour());
        frame_ = &picture_;
    } else {  // the fast path, with lesson 08's two passes for shadows
        // What a rebuild depends on: not the path, the wire, the scale or the
        // light (the renderer takes new lights and a shadow map as they are).
        Settings shading = settings;
        shading.path = Path::fast, shading.wireframe = false, shading.scale = 1;
        shading.light = {};
        if (!fast_ || !(shading == fast_settings_) || width != fast_width_ ||
            height != fast_height_) {
            fast::FastOptions o;
            o.render = options;
            fast_ = std::make_unique<fast::Renderer>(models_, width, height, o);
            fast_settings_ = shading;
            fast_width_ = width, fast_height_ = height;
        }
        if (settings.path == Path::shadows) {
            const shadows::ShadowOptions shadowed = shadow_options(settings, options);
            const float aspect = static_cast<float>(width) / static_cast<float>(height);
            // The map's options never change in the viewer: the pass is built once.
            if (!shadow_pass_)
                shadow_pass_ = std::make_unique<fast::ShadowPass>(models_, shadowed.map);
            const auto start = std::chrono::steady_clock::now();
            const shadows::ShadowMap& map =
                shadow_pass_->render(shadows::light_view_for(models_, camera, aspect, shadowed));
            stats_.shadow_map_ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            fast_->set_lighting(shadowed.render.lighting);
            fast_->set_shadow_map(&map, shadowed.lookup);
        } else {
            fast_->set_lighting(options.lighting);
            fast_->set_shadow_map(nullptr);
        }
        stats_.pixels_shaded = fast_->render(camera).tiles.shaded;
        frame_ = &fast_->frame();
    }
    if (settings.wireframe) {
        if (frame_ != &picture_) picture_ = *frame_;
        draw_wire_overlay(picture_, models_, camera, kWire);
        frame_ = &picture_;
    }
    return *frame_;
}

}  // namespace viewer
