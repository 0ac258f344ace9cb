// The options every lesson program shares, declared once so that every
// program spells them, checks them and documents them the same way.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "rasterlab/named_enum.hpp"

namespace rl {

struct ImageOptions {
    std::string output;
    int width = 800;
    int height = 800;
};

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
