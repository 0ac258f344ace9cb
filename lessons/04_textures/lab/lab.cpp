// Lesson 04's lab: the three filters against the texture averaged over each
// pixel's exact footprint, on a magnified and a strongly minified scene and on
// the program's own crate; and how the error of trilinear filtering falls with
// the texture's size. Writes 04_textures.csv and 04_texture_size.csv.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "footprint.hpp"
#include "rasterlab/image_metrics.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/mesh.hpp"
#include "rasterlab/results_table.hpp"
#include "rasterlab/texture_files.hpp"

namespace {

using namespace textures;

struct Scene {
    std::string name;
    const MipChain* texture;
    AffineScene mapping;
};

void sample_scene(benchmark::State& state, const Scene* scene, Filter filter) {
    SamplerState sampler;
    sampler.filter = filter;
    for (auto _ : state)
        benchmark::DoNotOptimize(
            render_scene(*scene->texture, scene->mapping, sampler).pixels().data());
    state.SetItemsProcessed(state.iterations() * scene->mapping.size * scene->mapping.size);
}

// The crate as 04_textures draws it by default (without lighting, so that
// only filtering differs from the truth), one whole frame per iteration.
struct CrateScene {
    const rl::Mesh* mesh;
    const MipChain* texture;
    TexturedOptions options;
    int size;
};

void draw_crate(benchmark::State& state, const CrateScene* scene, Filter filter) {
    TexturedOptions options = scene->options;
    options.sampler.filter = filter;
    for (auto _ : state) {
        zbuffer::Frame frame(scene->size, scene->size);
        draw_textured(frame, *scene->mesh, *scene->texture, options);
        benchmark::DoNotOptimize(frame.colour.pixels().data());
    }
}

rl::Image crate_frame(const CrateScene& scene, Filter filter) {
    TexturedOptions options = scene.options;
    options.sampler.filter = filter;
    zbuffer::Frame frame(scene.size, scene.size);
    draw_textured(frame, *scene.mesh, *scene.texture, options);
    return frame.colour;
}

// RMSE, PSNR and largest difference over the scored pixels only.
rl::ImageDiff compare_scored(const MeshFootprint& truth, const rl::Image& image) {
    double squares = 0;
    long count = 0;
    rl::ImageDiff d;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (!truth.scored.get(x, y)) continue;
            const rl::Rgba a = truth.average.get(x, y), b = image.get(x, y);
            for (int c : {a.r - b.r, a.g - b.g, a.b - b.b}) {
                squares += double(c) * c;
                d.max_abs = std::max(d.max_abs, std::abs(c));
            }
            ++count;
        }
    d.rmse = count ? std::sqrt(squares / (3.0 * count)) : 0.0;
    d.psnr = d.rmse > 0 ? 20.0 * std::log10(255.0 / d.rmse) : 99.0;
    return d;
}

std::string bench_name(Filter f, const std::string& scene) {
    return std::string("sample/") + name(f) + "/" + scene;
}

rl::Image project_texture(const char* model) {
    std::vector<std::string> warnings;
    const rl::Mesh mesh = rl::load_obj(rl::project_model(model), &warnings);
    const rl::Texture texture = rl::load_texture(mesh, 0, rl::TextureRole::diffuse, warnings);
    if (texture.is_default)
        throw std::runtime_error(std::string("the ") + model + " texture is missing");
    return texture.image;
}

}  // namespace

int main(int argc, char** argv) {
    const rl::lab::Options options =
        rl::lab::init(argc, argv, "Lesson 04 lab: texture filters against the footprint average.");
    return rl::guarded_main("04_textures_lab", [&] {
        const int size = options.quick ? 48 : 256;
        // Magnify a 64x64 version of the crate; minify the 1024x1024 floor checker.
        const rl::Image crate_small = MipChain(project_texture("crate")).level(3);
        const rl::Image floor = project_texture("floor");
        const MipChain crate_chain(crate_small), floor_chain(floor);
        const std::vector<Scene> scenes = {
            {"magnification (8x)", &crate_chain, magnification_scene(crate_small, size)},
            {"minification (24 texels/pixel, sheared)", &floor_chain,
             minification_scene(floor, size)},
        };
        for (Filter f : kFilters)
            for (const Scene& s : scenes)
                benchmark::RegisterBenchmark(bench_name(f, s.name).c_str(), sample_scene, &s, f)
                    ->Unit(benchmark::kMicrosecond);

        std::vector<std::string> warnings;
        const rl::Mesh crate = rl::load_obj(rl::project_model("crate"), &warnings);
        const MipChain crate_texture(project_texture("crate"));
        // The program's default size, 800 x 800 (4 x 4 truth samples a pixel
        // keep the truth's buffers near 200 MB).
        CrateScene crate_scene{&crate, &crate_texture, {}, options.quick ? 64 : 800};
        crate_scene.options.lighting = false;
        crate_scene.options.rotation =
            rl::rotation_y(kDefaultTurnY) * rl::rotation_x(kDefaultTurnX);
        const std::string crate_name = "the program's crate (default view, unlit)";
        for (Filter f : kFilters)
            benchmark::RegisterBenchmark(bench_name(f, crate_name).c_str(), draw_crate,
                                         &crate_scene, f)
                ->Unit(benchmark::kMicrosecond);
        const auto timings = rl::lab::run_benchmarks();

        rl::ResultsTable results(
            {"filter", "scene", "ns_per_sample", "rmse", "psnr_db", "max_abs", "image_size"});
        const int samples = options.quick ? 16 : 64;
        std::vector<rl::Image> truths;
        for (const Scene& s : scenes) {
            truths.push_back(footprint_average(s.texture->level(0), s.mapping, samples));
            for (Filter f : kFilters) {
                SamplerState sampler;
                sampler.filter = f;
                const rl::ImageDiff d =
                    rl::compare_images(truths.back(), render_scene(*s.texture, s.mapping, sampler));
                results.add_row(
                    {std::string(name(f)), s.name,
                     timings.at(bench_name(f, s.name)).median_ns / (double(size) * size), d.rmse,
                     d.psnr, static_cast<long long>(d.max_abs), static_cast<long long>(size)});
            }
        }

        // The crate: time per covered pixel (the whole frame, clearing
        // included), error over the pixels one face covers entirely.
        const MeshFootprint crate_truth = mesh_footprint_average(
            crate, crate_texture.level(0), crate_scene.options, crate_scene.size, 4);
        for (Filter f : kFilters) {
            const rl::ImageDiff d = compare_scored(crate_truth, crate_frame(crate_scene, f));
            results.add_row({std::string(name(f)), crate_name,
                             timings.at(bench_name(f, crate_name)).median_ns /
                                 static_cast<double>(crate_truth.covered),
                             d.rmse, d.psnr, static_cast<long long>(d.max_abs),
                             static_cast<long long>(crate_scene.size)});
        }

        // Texture size: the minified floor from smaller and smaller copies of
        // its texture, always against the full texture's footprint average.
        rl::ResultsTable by_size({"texture_size", "filter", "rmse"});
        for (int level = 0; level < floor_chain.levels() && floor_chain.level(level).width() >= 16;
             ++level) {
            const MipChain smaller(floor_chain.level(level));
            for (Filter f : {Filter::bilinear, Filter::trilinear}) {
                SamplerState sampler;
                sampler.filter = f;
                const double rmse =
                    rl::compare_images(truths[1], render_scene(smaller, scenes[1].mapping, sampler))
                        .rmse;
                by_size.add_row(
                    {static_cast<long long>(smaller.level(0).width()), std::string(name(f)), rmse});
            }
        }
        results.write_csv(options.out_dir / "04_textures.csv");
        by_size.write_csv(options.out_dir / "04_texture_size.csv");
        std::printf("%s\n%s", results.to_csv().c_str(), by_size.to_csv().c_str());
        return 0;
    });
}
