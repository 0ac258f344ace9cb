// Lesson 06's lab: the four shading models on UV spheres of 8 to 256
// segments against the analytic sphere (exact normal per pixel, lit in
// double with the same lights), timed per frame; and lighting in linear
// light against lighting the sRGB bytes naively; and vertex normals averaged
// by area or angle against the exact ones. Writes 06_shading.csv,
// 06_linear.csv and 06_normals.csv.
#include <benchmark/benchmark.h>

#include <cstdio>

#include "06_shading/shaders.hpp"
#include "06_shading/truths/sphere_truth.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"

namespace {

using namespace shading;

struct Setup {
    pipeline::Camera camera;
    Lighting<float> lighting = default_lighting(rl::vec3{0.5f, 0.6f, 1.0f});
    rl::vec3 albedo{0.8f, 0.35f, 0.2f};  // linear: a terracotta red
    int size = 256;
};

struct Case {
    ShadingModel model;
    int segments;
    rl::Mesh mesh;
    std::vector<rl::vec3> normals;
    Output output = Output::srgb;
};

rl::Image draw_sphere(const Setup& s, const Case& c) {
    pipeline::ColourTarget frame = pipeline::colour_target(s.size, s.size);
    Uniforms u{.model_matrix = rl::mat4::identity(),
               .normal_matrix = rl::mat3::identity(),
               .model_view_projection = pipeline::view_projection(s.camera, 1.0f),
               .eye = s.camera.eye,
               .lighting = s.lighting,
               .colour = s.albedo};
    if (c.output == Output::naive)  // the albedo as the byte that stores it, taken as light
        u.colour = {linear_to_srgb(s.albedo.x), linear_to_srgb(s.albedo.y),
                    linear_to_srgb(s.albedo.z)};
    draw_model(c.model, Surface{c.mesh, c.normals}, u, frame, {}, c.output);
    return frame.colour();
}

void draw_case(benchmark::State& state, const Setup* s, const Case* c) {
    for (auto _ : state) benchmark::DoNotOptimize(draw_sphere(*s, *c).get(0, 0));
}

void average_normals(benchmark::State& state, const rl::Mesh* mesh, Weighting w) {
    for (auto _ : state) benchmark::DoNotOptimize(vertex_normals(*mesh, w).data());
}

Specular specular_of(ShadingModel m) {
    return m == ShadingModel::phong ? Specular::phong : Specular::blinn_phong;
}

}  // namespace

int main(int argc, char** argv) {
    const rl::lab::Options options = rl::lab::init(
        argc, argv, "Lesson 06 lab: shading models and tessellation against an analytic sphere.");
    return rl::guarded_main("06_shading_lab", [&] {
        Setup setup;
        setup.camera.eye = {0, 0, 3.2f};
        setup.camera.target = {0, 0, 0};
        setup.camera.fov_y = 45;
        setup.camera.near = 1;
        setup.camera.far = 10;
        setup.size = options.quick ? 64 : 256;
        const std::vector<int> levels =
            options.quick ? std::vector<int>{8, 32} : std::vector<int>{8, 16, 32, 64, 128, 256};
        std::vector<Case> cases;
        for (ShadingModel m : kShadingModels)
            for (int n : levels) {
                Case c{m, n, uv_sphere(n), {}};
                c.normals = corner_normals(c.mesh, Weighting::angle);
                cases.push_back(std::move(c));
            }
        // Linear light against naive, Blinn-Phong on the finest sphere.
        for (Output o : kOutputs) {
            Case c{ShadingModel::blinn_phong, levels.back(), uv_sphere(levels.back()), {}, o};
            c.normals = corner_normals(c.mesh, Weighting::angle);
            cases.push_back(std::move(c));
        }
        const auto bench_name = [](const Case& c) {
            return std::string("shade/") + name(c.model) + "/" + std::to_string(c.segments) + "/" +
                   name(c.output);
        };
        for (const Case& c : cases)
            benchmark::RegisterBenchmark(bench_name(c).c_str(), draw_case, &setup, &c)
                ->Unit(benchmark::kMicrosecond);
        // Vertex normals averaged by area or by angle, against the exact ones.
        std::vector<rl::Mesh> spheres;
        for (int n : levels) spheres.push_back(uv_sphere(n));
        const auto normals_name = [](int n, Weighting w) {
            return std::string("normals/") + std::to_string(n) + "/" + name(w);
        };
        for (std::size_t i = 0; i < spheres.size(); ++i)
            for (Weighting w : kWeightings)
                benchmark::RegisterBenchmark(normals_name(levels[i], w).c_str(), average_normals,
                                             &spheres[i], w)
                    ->Unit(benchmark::kMicrosecond);
        const auto timings = rl::lab::run_benchmarks();

        const rl::Image truth_blinn =
            sphere_truth(setup.camera, setup.size, setup.size, setup.lighting, setup.albedo,
                         Specular::blinn_phong, rl::kBackground);
        const rl::Image truth_phong =
            sphere_truth(setup.camera, setup.size, setup.size, setup.lighting, setup.albedo,
                         Specular::phong, rl::kBackground);
        rl::ResultsTable shading(
            {"model", "segments", "triangles", "ns_per_pixel", "rmse", "interior_rmse", "pixels"});
        rl::ResultsTable linear({"output", "segments", "ns_per_pixel", "rmse", "interior_rmse"});
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const Case& c = cases[i];
            const rl::Image& truth =
                specular_of(c.model) == Specular::phong ? truth_phong : truth_blinn;
            const SphereError e = compare_spheres(truth, draw_sphere(setup, c), rl::kBackground);
            if (i + kOutputs.size() < cases.size()) {
                shading.add_row({std::string(name(c.model)), static_cast<long long>(c.segments),
                                 static_cast<long long>(c.mesh.faces.size()),
                                 timings.at(bench_name(c)).median_ns /
                                     static_cast<double>(std::max(e.pixels, 1L)),
                                 e.rmse, e.interior_rmse, static_cast<long long>(e.pixels)});
            } else {
                linear.add_row({std::string(name(c.output)), static_cast<long long>(c.segments),
                                timings.at(bench_name(c)).median_ns /
                                    static_cast<double>(std::max(e.pixels, 1L)),
                                e.rmse, e.interior_rmse});
            }
        }
        rl::ResultsTable normals(
            {"weighting", "segments", "ns_per_vertex", "mean_error_degrees", "max_error_degrees"});
        for (std::size_t i = 0; i < spheres.size(); ++i)
            for (Weighting w : kWeightings) {
                const NormalError e =
                    sphere_normal_error(spheres[i], vertex_normals(spheres[i], w));
                normals.add_row({std::string(name(w)), static_cast<long long>(levels[i]),
                                 timings.at(normals_name(levels[i], w)).median_ns /
                                     static_cast<double>(spheres[i].positions.size()),
                                 e.mean, e.max});
            }
        normals.write_csv(options.out_dir / "06_normals.csv");
        shading.write_csv(options.out_dir / "06_shading.csv");
        linear.write_csv(options.out_dir / "06_linear.csv");
        std::printf("%s\n%s\n%s", shading.to_csv().c_str(), linear.to_csv().c_str(),
                    normals.to_csv().c_str());
        return 0;
    });
}
