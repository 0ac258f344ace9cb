// The options every lesson program shares, declared once so that every
// program spells them, checks them and documents them the same way.
//
//   CLI::App app{"Lesson 02, triangles"};
//   rl::ImageOptions image_options{"02_triangles.tga"};  // -o, --width, --height
//   rl::add_image_options(app, image_options);
//   rl::add_method_option(app, "--raster", method, triangles::kRasterMethods, "Rasterizer");
//   rl::add_light_option(app, light);  // then rl::check_direction("--light", light)
//   app.add_option("--near", near)->check(rl::positive_number());
#pragma once

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "rasterlab/direction.hpp"
#include "rasterlab/named_enum.hpp"

namespace rl {

struct ImageOptions {
    std::string output;
    int width = 800;
    int height = 800;
};

// A check for a number option: a finite number in [low, high], by default
// the range of a float (1e300 would become infinity in one). CLI11 names
// the option in its message ("--far: 'inf' is not a finite number"). Every
// float option goes through it: NaN and infinity pass CLI11's own range
// checks, and a NaN light direction quietly drew a black image.
inline CLI::Validator finite_number(double low = -std::numeric_limits<float>::max(),
                                    double high = std::numeric_limits<float>::max()) {
    return CLI::Validator(
        [low, high](std::string& text) -> std::string {
            double value = 0;
            const char* end = text.data() + text.size();
            const auto [stop, error] = std::from_chars(text.data(), end, value);
            if (error == std::errc::result_out_of_range) return "'" + text + "' is out of range";
            if (error != std::errc{} || stop != end) return "'" + text + "' is not a number";
            if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
            if (value < low || value > high)
                return "'" + text + "' is outside [" + std::to_string(low) + ", " +
                       std::to_string(high) + "]";
            return {};
        },
        "FINITE");
}

// A number that must be greater than zero (a distance, a near plane).
inline CLI::Validator positive_number() {
    return finite_number(std::numeric_limits<double>::denorm_min());
}

// --light X Y Z: the direction towards the light, three finite numbers;
// check_direction() refuses 0 0 0 once parsing is done.
inline void add_light_option(CLI::App& app, std::vector<float>& light) {
    app.add_option("--light", light, "Direction towards the light, x y z")
        ->expected(3)
        ->check(finite_number())
        ->capture_default_str();
}

// -o/--output, --width, --height (1 to 16384).
inline void add_image_options(CLI::App& app, ImageOptions& options) {
    app.add_option("-o,--output", options.output, "Image to write (.tga or .png)")
        ->capture_default_str();
    app.add_option("--width", options.width, "Image width in pixels")
        ->capture_default_str()
        ->check(CLI::Range(1, 16384));
    app.add_option("--height", options.height, "Image height in pixels")
        ->capture_default_str()
        ->check(CLI::Range(1, 16384));
}

// -m/--model: an OBJ file; the default is one of the project's own.
inline void add_model_option(CLI::App& app, std::string& model) {
    app.add_option("-m,--model", model, "OBJ file to draw")->capture_default_str();
}

// An option choosing one value of a method enum by its name.
template <class E, std::size_t N>
CLI::Option* add_method_option(CLI::App& app, const std::string& flag, E& value,
                               const std::array<E, N>& all, const std::string& what) {
    std::vector<std::string> names;
    for (E e : all) names.push_back(name(e));
    return app
        .add_option_function<std::string>(
            flag, [&value, all](const std::string& text) { value = *from_name(text, all); },
            what + ": " + names_of(all))
        ->check(CLI::IsMember(names))
        ->default_str(name(value));
}

}  // namespace rl
