// Writes the split sum's table as a picture, as a GPU keeps it in a small
// texture: n.v from 0 on the left to 1 on the right, roughness from 0 at the
// bottom to 1 at the top; red is the scale A of F0, green the bias B. The
// page shows it (docs/09_environment.md#the-split-sum); docs/CMakeLists.txt
// enlarges it.
//
//   09_split_sum_picture -o split_sum.tga
#include "rasterlab/cli.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "09_environment/brdf.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{"Lesson 09: the split sum's table (A red, B green) as a picture."};
    std::string output = "split_sum.tga";
    app.add_option("-o,--output", output, "Image to write (.tga or .png), one pixel an entry");
    return app.run(argc, argv, "09_split_sum_picture", [&] {
        constexpr int n = environment::SplitSumTable::kSize;
        const environment::SplitSumTable& table = environment::split_sum_table();
        const auto byte = [](double v) {
            return static_cast<std::uint8_t>(std::clamp(v, 0.0, 1.0) * 255 + 0.5);
        };
        rl::Image image(n, n);
        for (int y = 0; y < n; ++y)  // row 0 is the bottom row: roughness 0
            for (int x = 0; x < n; ++x) {
                // The entries' own centres, as the table stores them.
                const environment::SplitSum s = table.at((x + 0.5f) / n, (y + 0.5f) / n);
                image.set(x, y, {byte(s.scale), byte(s.bias), 0, 255});
            }
        rl::save_image(output, image, false);
        // The corners, for the page's caption: what the picture's colours stand for.
        for (const auto& [x, y] : {std::pair{0, 0}, {n - 1, 0}, {0, n - 1}, {n - 1, n - 1}}) {
            const environment::SplitSum s = table.at((x + 0.5f) / n, (y + 0.5f) / n);
            std::printf("n.v %.3f, roughness %.3f: A %.3f, B %.3f\n", (x + 0.5) / n, (y + 0.5) / n,
                        s.scale, s.bias);
        }
        return 0;
    });
}
