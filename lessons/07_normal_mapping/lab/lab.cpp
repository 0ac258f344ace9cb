// Lesson 07's lab: the normal each method puts at each pixel of the globe,
// against the exact normal of the globe's relief (the functions its maps
// were made from), in degrees, and the time per pixel; and how the error
// falls with the tangent-space map's resolution; and, on a plane whose UVs
// are mirrored down its middle (each face's own frame is exact there), what
// averaging frames across the mirror line costs. Writes 07_normals.csv,
// 07_map_size.csv and 07_mirrored.csv; and the speed of a whole frame against
// a port of tinyrenderer's renderer, this lesson doing the same work and its
// own (07_speed.csv).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "05_perspective/truths/ray_truth.hpp"
#include "07_normal_mapping/scene.hpp"
#include "globe_relief.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"
#include "rasterlab/texture_files.hpp"
#include "test_surfaces.hpp"
#include "tinyrenderer_port.hpp"

namespace {

using namespace normal_mapping;

// One way to get the normal: a map and, for tangent space, a tangent method.
struct Method {
    std::string name;
    NormalMap source;
    TangentMethod tangents;
};

struct Globe {
    MappedModel model;
    pipeline::Camera camera;
    int size;
    shading::Uniforms uniforms;
};

// The shader's normal at every pixel it draws, as the fragment's output
// into a target of normals (NaN where nothing is drawn).
struct NormalProbe {
    NormalMappedShader shader;
    using Varyings = NormalMappedShader::Varyings;
    pipeline::ClipVertex<Varyings> vertex(const shading::SurfaceCorner& in) const {
        return shader.vertex(in);
    }
    rl::vec3 fragment(const pipeline::Fragment<Varyings>& f) const {
        return shader.normal_at(f, f.d_dx(&Varyings::uv), f.d_dy(&Varyings::uv));
    }
};

rl::Grid<rl::vec3> probe(const Globe& g, const Maps& maps, const std::vector<rl::vec4>& tangents,
                         NormalMap source, textures::Filter filter = textures::Filter::trilinear) {
    pipeline::RenderTarget<rl::vec3> normals(g.size, g.size, {}, rl::vec3{NAN, NAN, NAN});
    const NormalProbe p{
        {g.uniforms, maps, source, shading::Specular::blinn_phong, 1.0f, &tangents, filter}};
    pipeline::draw(shading::Surface(g.model.lit.model.mesh, g.model.lit.normals), p, normals);
    return normals.colour();
}

// The exact normal at each pixel: the ray meets the sphere of radius 0.9,
// whose (u, v) give the relief's normal.
rl::Grid<rl::vec3> exact_normals(const Globe& g) {
    rl::Grid<rl::vec3> out(g.size, g.size, rl::vec3{NAN, NAN, NAN});
    const pipeline::RayCamera rays(g.camera, g.size, g.size);  // lesson 05's pixel rays
    const rl::dvec3 eye = rays.eye();
    const double r = assets::kGlobeRadius;
    for (int y = 0; y < g.size; ++y)
        for (int x = 0; x < g.size; ++x) {
            const rl::dvec3 d = rl::normalize(rays.direction(x + 0.5, y + 0.5));
            const double b = rl::dot(eye, d), c = rl::dot(eye, eye) - r * r, disc = b * b - c;
            if (disc < 0) continue;
            const rl::dvec3 p = (eye + d * (-b - std::sqrt(disc))) / r;  // on the unit sphere
            const double u = std::atan2(p.x, p.z) / (2 * std::numbers::pi) + 0.5;
            const double v = std::asin(std::clamp(p.y, -1.0, 1.0)) / std::numbers::pi + 0.5;
            out.at(x, y) = rl::cast<float>(assets::globe_normal(u, v));
        }
    return out;
}

struct AngleError {
    double mean = 0, p99 = 0, max = 0;
};

AngleError compare(const rl::Grid<rl::vec3>& truth, const rl::Grid<rl::vec3>& got) {
    std::vector<double> angles;
    for (int y = 0; y < truth.height(); ++y)
        for (int x = 0; x < truth.width(); ++x) {
            const rl::vec3 a = truth.get(x, y), b = got.get(x, y);
            if (std::isnan(a.x) || std::isnan(b.x)) continue;
            const double c =
                std::clamp(double(rl::dot(rl::normalize(a), rl::normalize(b))), -1.0, 1.0);
            angles.push_back(std::acos(c) * 180 / std::numbers::pi);
        }
    AngleError e;
    if (angles.empty()) return e;
    for (double a : angles) e.mean += a;
    e.mean /= static_cast<double>(angles.size());
    std::sort(angles.begin(), angles.end());
    e.p99 = angles[angles.size() * 99 / 100];
    e.max = angles.back();
    return e;
}

struct Timed {
    const Globe* globe;
    const Maps* maps;
    const std::vector<rl::vec4>* tangents;
    NormalMap source;
};

// One frame of the globe at the program's size: by this lesson's render
// (the program's path) with some options, or by the port of tinyrenderer.
struct LessonFrame {
    const std::vector<MappedModel>* models;
    pipeline::Camera camera;
    RenderOptions options;
    int size;
};

void frame_lesson(benchmark::State& state, const LessonFrame* f) {
    for (auto _ : state) {
        pipeline::ColourTarget frame = pipeline::colour_target(f->size, f->size);
        benchmark::DoNotOptimize(render(*f->models, f->camera, f->options, frame).shaded);
    }
}

// The same frame's geometry alone: a depth-only pass (no colour attachment,
// so no fragment stage runs), to split this lesson's time into the work
// before the fragment stage and the fragment stage itself.
void frame_depth_only(benchmark::State& state, const LessonFrame* f) {
    const MappedModel& m = f->models->front();
    const shading::UnlitShader unlit{
        pipeline::view_projection(f->camera, 1.0f) * m.lit.model.transform, {}};
    for (auto _ : state) {
        pipeline::RenderTarget<> depth(f->size, f->size);
        benchmark::DoNotOptimize(
            pipeline::draw(shading::Surface(m.lit.model.mesh, m.lit.normals), unlit, depth).shaded);
    }
}

struct PortFrame {
    const rl::Mesh* mesh;
    tinyrenderer_port::Textures textures;
    pipeline::Camera camera;
    int size;
};

void frame_port(benchmark::State& state, const PortFrame* f) {
    for (auto _ : state)
        benchmark::DoNotOptimize(tinyrenderer_port::render(*f->mesh, f->textures, f->camera,
                                                           {0.3f, 0.5f, 1.0f}, f->size, f->size)
                                     .fragments);
}

// The tangent frames of the globe's corners (the one-off cost, on loading).
void build_tangents(benchmark::State& state, const shading::LitModel* lit, TangentMethod m) {
    for (auto _ : state)
        benchmark::DoNotOptimize(corner_tangents(lit->model.mesh, lit->normals, m).data());
}

void render_globe(benchmark::State& state, const Timed* t) {
    for (auto _ : state) {
        pipeline::ColourTarget frame = pipeline::colour_target(t->globe->size, t->globe->size);
        const NormalMappedShader shader{
            t->globe->uniforms, *t->maps, t->source, shading::Specular::blinn_phong, 1.0f,
            t->tangents};
        shading::draw(shading::Surface{t->globe->model.lit.model.mesh, t->globe->model.lit.normals},
                      shader, frame, {});
        benchmark::DoNotOptimize(frame.colour().get(0, 0));
    }
}

}  // namespace

int main(int argc, char** argv) {
    const rl::lab::Options options = rl::lab::init(
        argc, argv, "Lesson 07 lab: normal-map methods against the globe's exact normals.");
    return rl::guarded_main("07_normal_mapping_lab", [&] {
        std::vector<std::string> warnings;
        Globe g{load_mapped_model(rl::project_model("globe"), rl::mat4::identity(),
                                  TangentMethod::split, warnings),
                {},
                options.quick ? 96 : 512,
                {}};
        g.camera.eye = {0.9f, 0.7f, 2.2f};  // the globe's u = 0.5 faces +z; the seam is behind
        g.camera.target = {0, 0, 0};
        g.camera.fov_y = 50;
        g.camera.near = 0.5f;
        g.camera.far = 10;
        g.uniforms =
            shading::Uniforms{.model_matrix = rl::mat4::identity(),
                              .normal_matrix = rl::mat3::identity(),
                              .model_view_projection = pipeline::view_projection(g.camera, 1.0f),
                              .eye = g.camera.eye,
                              .lighting = shading::default_lighting(rl::vec3{0.3f, 0.5f, 1.0f}),
                              .texture = &g.model.lit.model.texture};
        const rl::Mesh& mesh = g.model.lit.model.mesh;
        std::vector<std::vector<rl::vec4>> frames;
        for (TangentMethod m : kTangentMethods)
            frames.push_back(corner_tangents(mesh, g.model.lit.normals, m));
        const std::vector<Method> methods = {
            {"no map (smooth normals)", NormalMap::none, TangentMethod::split},
            {"tangent map, per-face frames", NormalMap::tangent, TangentMethod::face},
            {"tangent map, per-vertex frames", NormalMap::tangent, TangentMethod::vertex},
            {"tangent map, per-vertex split frames", NormalMap::tangent, TangentMethod::split},
            {"object-space map", NormalMap::object, TangentMethod::split}};
        std::vector<Timed> timed;
        for (const Method& m : methods)
            timed.push_back(
                {&g, &g.model.maps, &frames[static_cast<std::size_t>(m.tangents)], m.source});
        for (std::size_t i = 0; i < methods.size(); ++i)
            benchmark::RegisterBenchmark(("globe/" + methods[i].name).c_str(), render_globe,
                                         &timed[i])
                ->Unit(benchmark::kMicrosecond);
        // Speed against the port of tinyrenderer, at the program's 800 x 800: this
        // lesson as the program draws it, and set to tinyrenderer's work (nearest
        // texels, one light, bytes lit as they are, Phong's highlight, no
        // specular map).
        Globe big = g;
        big.size = options.quick ? 128 : 800;
        std::vector<MappedModel> lesson_globe, same_work_globe;
        lesson_globe.push_back(g.model);
        same_work_globe.push_back(load_mapped_model(rl::project_model("globe"),
                                                    rl::mat4::identity(), TangentMethod::split,
                                                    warnings, shading::Output::naive));
        same_work_globe[0].maps.specular.reset();
        RenderOptions same_work;
        same_work.filter = textures::Filter::nearest;
        same_work.output = shading::Output::naive;
        same_work.specular = shading::Specular::phong;
        same_work.lighting.lights.resize(1);
        const LessonFrame lesson_frame{&lesson_globe, big.camera, {}, big.size},
            same_work_frame{&same_work_globe, big.camera, same_work, big.size};
        const rl::Image port_diffuse =
            rl::load_texture(mesh, 0, rl::TextureRole::diffuse, warnings).image;
        const rl::Image port_normals =
            rl::load_texture(mesh, 0, rl::TextureRole::normal_tangent, warnings).image;
        const PortFrame port_frame{&mesh, {&port_diffuse, &port_normals}, big.camera, big.size};
        benchmark::RegisterBenchmark("frame/this lesson", frame_lesson, &lesson_frame)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark("frame/this lesson, tinyrenderer's work", frame_lesson,
                                     &same_work_frame)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark("frame/tinyrenderer port", frame_port, &port_frame)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark("frame/this lesson, depth only", frame_depth_only,
                                     &same_work_frame)
            ->Unit(benchmark::kMillisecond);
        for (TangentMethod m : kTangentMethods)
            benchmark::RegisterBenchmark((std::string("tangents/") + name(m)).c_str(),
                                         build_tangents, &g.model.lit, m)
                ->Unit(benchmark::kMicrosecond);
        const auto timings = rl::lab::run_benchmarks();

        const rl::Grid<rl::vec3> truth = exact_normals(g);
        long covered = 0;
        for (const rl::vec3& n : truth.pixels()) covered += !std::isnan(n.x);
        rl::ResultsTable table(
            {"method", "ns_per_pixel", "mean_error_degrees", "p99_error_degrees"});
        for (std::size_t i = 0; i < methods.size(); ++i) {
            const AngleError e =
                compare(truth, probe(g, g.model.maps, *timed[i].tangents, methods[i].source));
            table.add_row({methods[i].name,
                           timings.at("globe/" + methods[i].name).median_ns /
                               static_cast<double>(std::max(covered, 1L)),
                           e.mean, e.p99});
        }

        // The map's resolution: the tangent-space map from smaller copies.
        rl::ResultsTable sizes({"map_size", "method", "mean_error_degrees", "p99_error_degrees"});
        const textures::MipChain& full = *g.model.maps.tangent_normals;
        for (int level = 0; level < full.levels() && full.level(level).height() >= 8; ++level) {
            Maps smaller;
            smaller.tangent_normals = textures::MipChain(full.level(level));
            const AngleError e = compare(
                truth, probe(g, smaller, frames[static_cast<std::size_t>(TangentMethod::split)],
                             NormalMap::tangent));
            sizes.add_row({static_cast<long long>(full.level(level).width()),
                           std::string("tangent map, split frames"), e.mean, e.p99});
        }
        // The mirrored plane (test_surfaces.hpp): each face's own frame is
        // exact there; against those frames:
        MappedModel plane = mirrored_plane(TangentMethod::face, warnings);
        Globe crate{std::move(plane), {}, g.size, {}};
        crate.camera = g.camera;
        crate.camera.eye = {0.3f, -0.4f, 2.4f};
        crate.uniforms = g.uniforms;
        crate.uniforms.model_view_projection = pipeline::view_projection(crate.camera, 1.0f);
        crate.uniforms.eye = crate.camera.eye;
        crate.uniforms.texture = &crate.model.lit.model.texture;
        const rl::Mesh& box = crate.model.lit.model.mesh;
        std::vector<std::vector<rl::vec4>> crate_frames;
        for (TangentMethod m : kTangentMethods)
            crate_frames.push_back(corner_tangents(box, crate.model.lit.normals, m));
        const rl::Grid<rl::vec3> exact_frames =
            probe(crate, crate.model.maps, crate_frames[0], NormalMap::tangent);
        rl::ResultsTable crate_table({"method", "ns_per_corner", "mean_error_degrees",
                                      "p99_error_degrees", "max_error_degrees"});
        for (TangentMethod m : kTangentMethods) {
            const AngleError e = compare(
                exact_frames, probe(crate, crate.model.maps,
                                    crate_frames[static_cast<std::size_t>(m)], NormalMap::tangent));
            crate_table.add_row({std::string(name(m)),
                                 timings.at(std::string("tangents/") + name(m)).median_ns /
                                     static_cast<double>(3 * mesh.faces.size()),
                                 e.mean, e.p99, e.max});
        }
        crate_table.write_csv(options.out_dir / "07_mirrored.csv");
        // The three frames: time, time per fragment (with the spread of the
        // repetitions), and the normals against the exact ones.
        rl::ResultsTable speed_table({"renderer", "ms_per_frame", "ms_min", "ms_max",
                                      "ns_per_fragment", "fragments", "mean_error_degrees",
                                      "p99_error_degrees"});
        {
            const rl::Grid<rl::vec3> big_truth = exact_normals(big);
            const AngleError ours = compare(
                big_truth, probe(big, big.model.maps, big.model.tangents, NormalMap::tangent));
            const AngleError ours_nearest =
                compare(big_truth, probe(big, big.model.maps, big.model.tangents,
                                         NormalMap::tangent, textures::Filter::nearest));
            rl::Grid<rl::vec3> theirs(big.size, big.size, rl::vec3{NAN, NAN, NAN});
            const std::size_t port_fragments =
                tinyrenderer_port::render(mesh, port_frame.textures, big.camera, {0.3f, 0.5f, 1.0f},
                                          big.size, big.size, &theirs)
                    .fragments;
            const AngleError tr = compare(big_truth, theirs);
            const auto fragments_of = [](const LessonFrame& f) {
                pipeline::ColourTarget frame = pipeline::colour_target(f.size, f.size);
                return render(*f.models, f.camera, f.options, frame).shaded;
            };
            const auto row = [&](const std::string& name, const char* timer, std::size_t fragments,
                                 const AngleError& e) {
                const rl::lab::Timing& t = timings.at(timer);
                speed_table.add_row({name, t.median_ns / 1e6, t.min_ns / 1e6, t.max_ns / 1e6,
                                     t.median_ns / static_cast<double>(fragments),
                                     static_cast<double>(fragments), e.mean, e.p99});
            };
            row("this lesson (split frames, trilinear, linear light, two lights)",
                "frame/this lesson", fragments_of(lesson_frame), ours);
            row("this lesson doing tinyrenderer's work (nearest, bytes, one light)",
                "frame/this lesson, tinyrenderer's work", fragments_of(same_work_frame),
                ours_nearest);
            row("tinyrenderer port (double, per-pixel 3x3 inverse and frame, nearest)",
                "frame/tinyrenderer port", port_fragments, tr);
            // (no normals: the depth-only pass shades nothing)
            row("this lesson, depth only (everything before the fragment stage)",
                "frame/this lesson, depth only", fragments_of(same_work_frame),
                AngleError{NAN, NAN, NAN});
        }
        speed_table.write_csv(options.out_dir / "07_speed.csv");
        table.write_csv(options.out_dir / "07_normals.csv");
        sizes.write_csv(options.out_dir / "07_map_size.csv");
        std::printf("%s\n%s\n%s\n%s", table.to_csv().c_str(), sizes.to_csv().c_str(),
                    crate_table.to_csv().c_str(), speed_table.to_csv().c_str());
        return 0;
    });
}
