// Writes what lesson 09's page shows that is computed, not measured: the
// split sum's table as a picture, as a GPU keeps it in a small texture (n.v
// from 0 on the left to 1 on the right, roughness from 0 at the bottom to 1
// at the top; red the scale A of F0, green the bias B), its corners, and
// the tone curves at a few values of light, as Markdown tables the page's
// value markers read. docs/CMakeLists.txt (target docs_images) runs it.
//
//   09_page_figures -o split_sum.tga --corners corners.md --tone-curves curves.md
#include "rasterlab/cli.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <utility>

#include "09_environment/brdf.hpp"
#include "09_environment/tone_map.hpp"
#include "rasterlab/file_io.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

namespace {

// A Markdown table's row: the cells between bars.
std::string row(std::initializer_list<std::string> cells) {
    std::string line = "|";
    for (const std::string& cell : cells) line += " " + cell + " |";
    return line + "\n";
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

std::span<const std::uint8_t> bytes_of(const std::string& text) {
    return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

}  // namespace

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 09's computed figures: the split sum's table as a picture (A red, "
        "B green), its corners and the tone curves, as Markdown tables."};
    std::string output = "split_sum.tga", corners, curves;
    app.add_option("-o,--output", output, "The table's picture (.tga or .png), one pixel an entry");
    app.add_option("--corners", corners, "Write the table's four corners here (Markdown)");
    app.add_option("--tone-curves", curves,
                   "Write the tone curves at a few lights here (Markdown)");
    return app.run(argc, argv, "09_page_figures", [&] {
        // All or nothing, and no two outputs one file.
        rl::check_image_output(output);
        rl::OutputFiles outputs;
        for (const std::string& path : {output, corners, curves})
            if (!path.empty()) outputs.check(path);
        constexpr int n = environment::SplitSumTable::kSize;
        const environment::SplitSumTable& table = environment::split_sum_table();
        // The entries' own centres, as the table stores them; row 0 is the
        // bottom row: roughness 0.
        const auto entry = [&](int x, int y) { return table.at((x + 0.5f) / n, (y + 0.5f) / n); };
        const auto byte = [](double v) {
            return static_cast<std::uint8_t>(std::clamp(v, 0.0, 1.0) * 255 + 0.5);
        };
        rl::Image image(n, n);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const environment::SplitSum s = entry(x, y);
                image.set(x, y, {byte(s.scale), byte(s.bias), 0, 255});
            }
        outputs.stage(output, rl::encode_image(output, image, false));
        std::string corner_text, curve_text;  // kept alive until the commit
        if (!corners.empty()) {
            std::string text = row({"corner", "n_dot_v", "roughness", "A", "B"}) +
                               row({"---", "---", "---", "---", "---"});
            const std::pair<const char*, std::pair<int, int>> named[] = {
                {"smooth, grazing", {0, 0}},
                {"smooth, head-on", {n - 1, 0}},
                {"rough, grazing", {0, n - 1}},
                {"rough, head-on", {n - 1, n - 1}}};
            for (const auto& [name, at] : named) {
                const environment::SplitSum s = entry(at.first, at.second);
                text += row({name, number((at.first + 0.5) / n), number((at.second + 0.5) / n),
                             number(s.scale), number(s.bias)});
            }
            corner_text = text;
            outputs.stage(corners, bytes_of(corner_text));
        }
        if (!curves.empty()) {
            std::string text = row({"light", "clamp", "reinhard", "aces_curve", "aces"}) +
                               row({"---", "---", "---", "---", "---"});
            for (const float light : {0.5f, 1.0f, 2.0f, 4.0f, 8.0f, 16.0f}) {
                const auto shown = [light](environment::ToneMap curve) {
                    return number(environment::tone_map(light, {.curve = curve}));
                };
                text += row({number(light), shown(environment::ToneMap::clamp),
                             shown(environment::ToneMap::reinhard),
                             number(environment::aces_curve(light)),
                             shown(environment::ToneMap::aces)});
            }
            curve_text = text;
            outputs.stage(curves, bytes_of(curve_text));
        }
        outputs.commit();
        return 0;
    });
}
