// Lesson 05's lab. Three questions, each against a ray-cast truth in double:
//  1. affine vs perspective-correct texture coordinates on a tilted quad,
//     and whether subdividing the quad rescues affine interpolation;
//  2. clipping: which pixels each mode gets wrong, and what it costs;
//  3. the mip level from each pixel's derivatives vs one per triangle, on
//     the receding floor, against the texture averaged over each pixel.
// Writes 05_interpolation.csv, 05_clipping.csv and 05_lod.csv.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "05_perspective/scene.hpp"
#include "clipping_scenes.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"
#include "rasterlab/texture_files.hpp"

namespace {

using namespace pipeline;

// ---------------------------------------------------------------- 1. interpolation

// A 2 x 2 quad, its centre 3 in front of the eye, turned by `tilt` degrees
// about the x axis (0: facing the eye; 80: nearly edge-on, a floor seen low),
// cut into n x n cells of two triangles each; uv runs 0..1 across it.
std::vector<WorldTriangle> tilted_quad(double tilt, int n) {
    const double a = tilt * std::numbers::pi / 180;
    const auto at = [&](double s, double t) {  // s, t in [0, 1]
        const double y = 2 * t - 1;
        return WorldTriangle{{{2 * s - 1, y * std::cos(a), -3 - y * std::sin(a)}}, {{s, t}}};
    };
    std::vector<WorldTriangle> quad;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double s0 = double(i) / n, s1 = double(i + 1) / n;
            const double t0 = double(j) / n, t1 = double(j + 1) / n;
            const WorldTriangle c[4] = {at(s0, t0), at(s1, t0), at(s1, t1), at(s0, t1)};
            quad.push_back(
                {{c[0].p[0], c[1].p[0], c[2].p[0]}, {c[0].uv[0], c[1].uv[0], c[2].uv[0]}});
            quad.push_back(
                {{c[0].p[0], c[2].p[0], c[3].p[0]}, {c[0].uv[0], c[2].uv[0], c[3].uv[0]}});
        }
    return quad;
}

Camera quad_camera() {
    Camera camera;
    camera.eye = {0, 0, 0};
    camera.target = {0, 0, -1};
    camera.fov_y = 45;
    camera.near = 0.5f;
    camera.far = 10;
    return camera;
}

// Draws the triangles and returns each pixel's interpolated uv (NaN where
// nothing was drawn) and how many fragments were shaded.
struct UvFrame {
    rl::Grid<rl::vec2> uv;
    std::size_t fragments = 0;
};

// Draws into `target`, cleared first (the benchmark reuses one target, so
// that a frame's time is drawing, not allocating 16 bytes a pixel).
std::size_t draw_uv(const std::vector<WorldTriangle>& scene, const Camera& camera,
                    Interpolation interpolation, WorldTarget& target) {
    target.clear(-1, rl::vec2{NAN, NAN});
    PipelineOptions options;
    options.interpolation = interpolation;
    return draw(WorldScene{&scene}, WorldProgram{view_projection(camera, 1.0f)}, target, options)
        .shaded;
}

UvFrame draw_uv(const std::vector<WorldTriangle>& scene, const Camera& camera, int size,
                Interpolation interpolation) {
    WorldTarget target = world_target(size, size);
    const std::size_t fragments = draw_uv(scene, camera, interpolation, target);
    return {target.colour<1>(), fragments};
}

// Mean and largest distance from the exact uv, in texels of a 256 x 256 texture.
struct UvError {
    double mean = 0, max = 0;
};

// `quad` is the undivided quad: the exact uv of a point of the plane does not
// depend on how the quad was cut.
UvError uv_error(const UvFrame& frame, const std::vector<WorldTriangle>& quad, const Camera& camera,
                 int size) {
    const RayCamera rays(camera, size, size);
    double sum = 0, worst = 0;
    long count = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const rl::vec2 uv = frame.uv.get(x, y);
            if (std::isnan(uv.x)) continue;
            for (const WorldTriangle& t : quad) {
                const std::optional<Hit> hit =
                    intersect(t, rays.eye(), rays.direction(x + 0.5, y + 0.5));
                if (!hit) continue;
                const rl::dvec2 exact =
                    t.uv[0] * hit->weights.x + t.uv[1] * hit->weights.y + t.uv[2] * hit->weights.z;
                const double e = rl::length(rl::cast<double>(uv) - exact) * 256;
                sum += e;
                worst = std::max(worst, e);
                ++count;
                break;
            }
        }
    return {count ? sum / count : 0.0, worst};
}

struct InterpolationCase {
    std::string method;  // "perspective", "affine", "affine, 4x4 cells", ...
    Interpolation interpolation;
    int cells;
    double tilt;
    int size;
    std::vector<WorldTriangle> scene;
    std::size_t fragments = 0;
};

void draw_interpolation_case(benchmark::State& state, InterpolationCase* c) {
    const Camera camera = quad_camera();
    WorldTarget target = world_target(c->size, c->size);
    for (auto _ : state) {
        c->fragments = draw_uv(c->scene, camera, c->interpolation, target);
        benchmark::DoNotOptimize(target.colour<1>().get(0, 0));
    }
}

// ---------------------------------------------------------------- 2. clipping

void draw_clipping_case(benchmark::State& state, const ClippingScene* scene, ClipMode mode,
                        int size) {
    PipelineOptions options;
    options.clip = mode;
    WorldTarget target = world_target(size, size);
    const WorldProgram program{view_projection(scene->camera, 1.0f)};
    for (auto _ : state) {  // one target, cleared each frame: drawing is timed, not allocating
        target.clear(-1, rl::vec2{NAN, NAN});
        draw(WorldScene{&scene->triangles}, program, target, options);
        benchmark::DoNotOptimize(target.colour<0>().get(0, 0));
    }
}

// ---------------------------------------------------------------- 3. level of detail

// The floor of the default scene (scaled 3x: x, z in [-3, 3], uv = 2 (x/3 + 1),
// 2 (1 - z/3)), from 0.5 above, looking along it: as stored (8 x 8 cells,
// 128 triangles) or as one quad of 2 triangles with the same mapping.
struct LodScene {
    std::string name;
    std::vector<TexturedModel> models;
    Camera camera;
    int size;
    rl::Image truth;
    rl::Grid<std::uint8_t> scored;
};

// The floor as two triangles: the same square, the same texture coordinates.
rl::Mesh two_triangle_floor(const rl::Mesh& floor) {
    rl::Mesh quad = floor;
    quad.positions = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}};
    quad.uvs = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    quad.normals.clear();
    const auto corner = [](int i) { return rl::Corner{i, i, -1}; };
    quad.faces = {{{corner(0), corner(1), corner(2)}, 0}, {{corner(0), corner(2), corner(3)}, 0}};
    return quad;
}

rl::dvec2 floor_uv(rl::dvec3 p) {
    return {2 * (p.x / 3 + 1), 2 * (1 - p.z / 3)};
}

// Per pixel, the floor's texture (texels as constant squares, repeat)
// averaged over n x n rays through the pixel; scored where all rays hit.
void floor_footprint(LodScene& s, const rl::Image& texture, int n) {
    const RayCamera rays(s.camera, s.size, s.size);
    s.truth = rl::Image(s.size, s.size);
    s.scored = rl::Grid<std::uint8_t>(s.size, s.size, 0);
    const int tw = texture.width(), th = texture.height();
    for (int y = 0; y < s.size; ++y)
        for (int x = 0; x < s.size; ++x) {
            double sum[3] = {0, 0, 0};
            bool all = true;
            for (int j = 0; j < n && all; ++j)
                for (int i = 0; i < n; ++i) {
                    const rl::dvec3 d = rays.direction(x + (i + 0.5) / n, y + (j + 0.5) / n);
                    if (!(d.y < 0)) {
                        all = false;
                        break;
                    }
                    const double t = -rays.eye().y / d.y;
                    const rl::dvec3 p = rays.eye() + d * t;
                    if (std::abs(p.x) > 3 || std::abs(p.z) > 3 || t > s.camera.far) {
                        all = false;
                        break;
                    }
                    const rl::dvec2 uv = floor_uv(p);
                    const auto wrap = [](double c, int size) {
                        const int texel = static_cast<int>(std::floor(c * size)) % size;
                        return texel < 0 ? texel + size : texel;
                    };
                    const rl::Rgba c = texture.get(wrap(uv.x, tw), wrap(uv.y, th));
                    sum[0] += c.r, sum[1] += c.g, sum[2] += c.b;
                }
            if (!all) continue;
            const double k = 1.0 / (n * n);
            s.truth.at(x, y) = {static_cast<std::uint8_t>(std::lround(sum[0] * k)),
                                static_cast<std::uint8_t>(std::lround(sum[1] * k)),
                                static_cast<std::uint8_t>(std::lround(sum[2] * k)), 255};
            s.scored.at(x, y) = 1;
        }
}

RenderOptions lod_options(LodMethod lod, textures::Filter filter) {
    RenderOptions options;
    options.lod = lod;
    options.sampler.filter = filter;
    options.lighting = false;
    return options;
}

rl::Image render_floor(const LodScene& s, LodMethod lod, textures::Filter filter) {
    pipeline::ColourTarget frame = pipeline::colour_target(s.size, s.size);
    render(s.models, s.camera, lod_options(lod, filter), frame);
    return frame.colour();
}

void draw_lod_case(benchmark::State& state, const LodScene* s, LodMethod lod,
                   textures::Filter filter) {
    for (auto _ : state) benchmark::DoNotOptimize(render_floor(*s, lod, filter).get(0, 0));
}

double scored_rmse(const LodScene& s, const rl::Image& image, long* count_out) {
    double squares = 0;
    long count = 0;
    for (int y = 0; y < s.size; ++y)
        for (int x = 0; x < s.size; ++x) {
            if (!s.scored.get(x, y)) continue;
            const rl::Rgba a = s.truth.get(x, y), b = image.get(x, y);
            for (int c : {a.r - b.r, a.g - b.g, a.b - b.b}) squares += double(c) * c;
            ++count;
        }
    *count_out = count;
    return count ? std::sqrt(squares / (3.0 * count)) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
    const rl::lab::Options options = rl::lab::init(
        argc, argv, "Lesson 05 lab: interpolation, clipping and level of detail against rays.");
    return rl::guarded_main("05_perspective_lab", [&] {
        // 1. Interpolation: tilts x sizes x methods.
        const std::vector<double> tilts =
            options.quick ? std::vector<double>{60} : std::vector<double>{0, 30, 60, 75, 85};
        const std::vector<int> sizes =
            options.quick ? std::vector<int>{256} : std::vector<int>{64, 256, 1024};
        const std::vector<int> cells =
            options.quick ? std::vector<int>{1, 4} : std::vector<int>{1, 2, 4, 8, 16, 32};
        std::vector<InterpolationCase> cases;
        for (double tilt : tilts)
            for (int size : sizes) {
                cases.push_back({"perspective", Interpolation::perspective_correct, 1, tilt, size,
                                 tilted_quad(tilt, 1)});
                for (int n : cells)
                    cases.push_back({n == 1 ? "affine"
                                            : "affine, " + std::to_string(n) + "x" +
                                                  std::to_string(n) + " cells",
                                     Interpolation::affine, n, tilt, size, tilted_quad(tilt, n)});
            }
        const auto interpolation_name = [](const InterpolationCase& c) {
            return "interpolation/" + c.method + "/tilt " + std::to_string(int(c.tilt)) + "/" +
                   std::to_string(c.size);
        };
        for (InterpolationCase& c : cases)
            benchmark::RegisterBenchmark(interpolation_name(c).c_str(), draw_interpolation_case, &c)
                ->Unit(benchmark::kMicrosecond);

        // 2. Clipping.
        const int clip_size = options.quick ? 96 : 512;
        const std::vector<ClippingScene> clipping_scenes = {
            around_eye_scene(options.quick ? 40 : 200), floor_scene()};
        const auto clipping_name = [](const ClippingScene& s, ClipMode m) {
            return "clip/" + s.name + "/" + name(m);
        };
        for (const ClippingScene& s : clipping_scenes)
            for (ClipMode m : kClipModes)
                benchmark::RegisterBenchmark(clipping_name(s, m).c_str(), draw_clipping_case, &s, m,
                                             clip_size)
                    ->Unit(benchmark::kMicrosecond);

        // 3. Level of detail on the floor, as stored and as two triangles.
        std::vector<std::string> warnings;
        std::vector<LodScene> lod_scenes(2);
        lod_scenes[0].name = "floor, 128 triangles";
        lod_scenes[1].name = "floor, 2 triangles";
        for (LodScene& lod : lod_scenes) {
            lod.size = options.quick ? 64 : 512;
            lod.models.push_back(load_model(rl::project_model("floor"),
                                            rl::compose({.scale = {3, 3, 3}}), warnings));
            lod.camera.eye = {0, 0.5f, 3.2f};
            lod.camera.target = {0, 0.1f, 0};
            lod.camera.fov_y = 50;
            lod.camera.near = 0.1f;
            lod.camera.far = 20;
        }
        lod_scenes[1].models[0].mesh = two_triangle_floor(lod_scenes[1].models[0].mesh);
        const auto lod_name = [](const LodScene& s, LodMethod m, textures::Filter f) {
            return "lod/" + s.name + "/" + name(m) + "/" + textures::name(f);
        };
        const textures::Filter lod_filters[2] = {textures::Filter::bilinear,
                                                 textures::Filter::trilinear};
        for (const LodScene& lod : lod_scenes)
            for (LodMethod m : kLodMethods)
                for (textures::Filter f : lod_filters)
                    benchmark::RegisterBenchmark(lod_name(lod, m, f).c_str(), draw_lod_case, &lod,
                                                 m, f)
                        ->Unit(benchmark::kMicrosecond);

        const auto timings = rl::lab::run_benchmarks();

        rl::ResultsTable interpolation({"method", "tilt", "image_size", "ns_per_pixel", "ns_min",
                                        "ns_max", "mean_error_texels", "max_error_texels",
                                        "triangles"});
        const Camera camera = quad_camera();
        for (const InterpolationCase& c : cases) {
            const UvError e = uv_error(draw_uv(c.scene, camera, c.size, c.interpolation),
                                       tilted_quad(c.tilt, 1), camera, c.size);
            const rl::lab::Timing& t = timings.at(interpolation_name(c));
            const double pixels = static_cast<double>(std::max<std::size_t>(c.fragments, 1));
            interpolation.add_row({c.method, c.tilt, static_cast<long long>(c.size),
                                   t.median_ns / pixels, t.min_ns / pixels, t.max_ns / pixels,
                                   e.mean, e.max, static_cast<long long>(c.scene.size())});
        }

        rl::ResultsTable clipping({"mode", "scene", "ns_per_triangle", "ns_min", "ns_max",
                                   "wrong_percent", "wrong_pixels", "covered_pixels", "clipped",
                                   "outside", "refused", "triangles"});
        for (const ClippingScene& s : clipping_scenes) {
            const rl::Grid<int> truth =
                exact_ids(s.triangles, RayCamera(s.camera, clip_size, clip_size));
            for (ClipMode m : kClipModes) {
                PipelineOptions o;
                o.clip = m;
                PipelineCounts counts;
                const IdDifference d = compare_ids(
                    truth, pipeline_ids(s.triangles, s.camera, clip_size, clip_size, o, &counts));
                const double n = static_cast<double>(s.triangles.size());
                const rl::lab::Timing& t = timings.at(clipping_name(s, m));
                clipping.add_row(
                    {std::string(name(m)), s.name, t.median_ns / n, t.min_ns / n, t.max_ns / n,
                     100.0 * static_cast<double>(d.wrong) /
                         static_cast<double>(std::max(d.covered, 1L)),
                     static_cast<long long>(d.wrong), static_cast<long long>(d.covered),
                     static_cast<long long>(counts.clipped), static_cast<long long>(counts.outside),
                     static_cast<long long>(counts.refused),
                     static_cast<long long>(s.triangles.size())});
            }
        }

        rl::ResultsTable lod_table(
            {"lod", "filter", "scene", "ns_per_pixel", "rmse", "scored_pixels"});
        for (LodScene& lod : lod_scenes) {
            floor_footprint(lod, lod.models[0].texture.level(0), options.quick ? 4 : 16);
            for (LodMethod m : kLodMethods)
                for (textures::Filter f : lod_filters) {
                    long scored = 0;
                    const double rmse = scored_rmse(lod, render_floor(lod, m, f), &scored);
                    lod_table.add_row({std::string(name(m)), std::string(textures::name(f)),
                                       lod.name,
                                       timings.at(lod_name(lod, m, f)).median_ns /
                                           static_cast<double>(lod.size * lod.size),
                                       rmse, static_cast<long long>(scored)});
                }
        }

        interpolation.write_csv(options.out_dir / "05_interpolation.csv");
        clipping.write_csv(options.out_dir / "05_clipping.csv");
        lod_table.write_csv(options.out_dir / "05_lod.csv");
        std::printf("%s\n%s\n%s", interpolation.to_csv().c_str(), clipping.to_csv().c_str(),
                    lod_table.to_csv().c_str());
        return 0;
    });
}
