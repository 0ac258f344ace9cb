// Lesson 02: triangles. Fills a model's faces with flat Lambert shading,
// orthographic, back faces culled. Read docs/02_triangles.md beside it.
#include <cstdio>

#include "rasterlab/cli.hpp"

#include "flat_shading.hpp"
#include "overdraw.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 02, triangles: a model filled with flat Lambert shading (orthographic)."};
    std::string model = rl::project_model("torus").string();
    rl::ImageOptions image_options{"02_triangles.tga"};
    triangles::RasterMethod method = triangles::RasterMethod::edge;
    bool no_cull = false, test_image = false, overdraw = false, owners = false;
    std::vector<float> light{triangles::kDefaultLight.x, triangles::kDefaultLight.y,
                             triangles::kDefaultLight.z};
    rl::add_model_option(app, model);
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--raster", method, triangles::kRasterMethods, "Rasterizer");
    rl::add_light_option(app, light);
    app.add_flag("--no-cull", no_cull, "Draw back faces too");
    app.add_flag("--test-image", test_image, "Draw the classic three triangles (200x200) instead");
    app.add_flag(
        "--overdraw", overdraw,
        "Draw a fan of 12 triangles sharing a hub (48x48) coloured by how often each pixel "
        "is drawn: grey once, red twice or more");
    app.add_flag("--owners", owners,
                 "Draw a fan of 4 triangles whose spokes run through pixel centres (16x16), each "
                 "pixel in the colour of the triangle that drew it: red where two did");
    return app.run(argc, argv, "02_triangles", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        rl::check_image_output(output);  // before any work: a bad path costs nothing
        rl::check_direction("--light", light);
        if (overdraw) {
            rl::save_image(output, triangles::overdraw_fan(method, 48, 12));
            std::printf("overdraw fan drawn with %s into %s\n", triangles::name(method),
                        output.c_str());
            return 0;
        }
        if (owners) {
            rl::save_image(output, triangles::edge_owners(method, 16));
            std::printf("edge owners drawn with %s into %s\n", triangles::name(method),
                        output.c_str());
            return 0;
        }
        if (test_image) {
            rl::save_image(output, triangles::three_triangles(method));
            std::printf("three triangles drawn with %s into %s\n", triangles::name(method),
                        output.c_str());
            return 0;
        }
        std::vector<std::string> warnings;
        const rl::Mesh mesh = rl::load_obj(model, &warnings);
        rl::print_warnings("02_triangles", warnings);
        rl::Image image(width, height, rl::kBackground);
        triangles::FlatOptions options;
        options.method = method;
        options.cull_back_faces = !no_cull;
        options.light_direction = {light[0], light[1], light[2]};
        const triangles::DrawCounts stats = triangles::draw_flat_shaded(image, mesh, options);
        rl::save_image(output, image);
        std::printf("%s: %zu faces drawn, %zu culled, %zu refused, with %s into %s\n",
                    model.c_str(), stats.drawn, stats.culled, stats.refused,
                    triangles::name(method), output.c_str());
        return 0;
    });
}
