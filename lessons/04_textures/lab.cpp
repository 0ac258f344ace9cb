// Lesson 04's lab: the three filters against the texture averaged over each
// pixel's exact footprint, on a magnified and a strongly minified scene; and
// how the error of trilinear filtering falls with the texture's size. Writes
// 04_textures.csv and 04_texture_size.csv.
#include <benchmark/benchmark.h>

#include <cstdio>

#include "footprint.hpp"
#include "rasterlab/image_metrics.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/mesh.hpp"
#include "rasterlab/results_table.hpp"
#include "rasterlab/textures.hpp"

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
