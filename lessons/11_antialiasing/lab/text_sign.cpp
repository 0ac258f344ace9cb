// Writes the sign that the page's picture of the edge filter on text draws: a
// flat quad (sign.obj, sign.mtl) whose texture (sign_diffuse.tga) holds lines
// of text in strokes one texel wide, detail that a post-process filter cannot
// tell from a jagged edge. The glyphs are stb_easy_font's (axis-aligned
// rectangles). docs/CMakeLists.txt draws the sign with 11_antialiasing.
//
//   11_text_sign -o DIR/sign_diffuse.tga    then: 11_antialiasing --model DIR/sign.obj ...
#include <stb_easy_font.h>
#include "rasterlab/cli.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "rasterlab/file_io.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"

namespace {

constexpr int kTexWidth = 256, kTexHeight = 48;  // texels; the quad is 0.01 world units a texel
constexpr rl::Rgba kPaper{236, 230, 214, 255}, kInk{24, 24, 32, 255};
const std::array<const char*, 3> kLines = {
    "An edge filter sees an edge in",
    "every stroke of small text:", "1 px lines, 0123456789 ABC xyz"};

// stb_easy_font's vertex: a position (y down, in texels) and a colour.
struct FontVertex {
    float x, y, z;
    unsigned char colour[4];
};

// The text in ink on paper, every stroke a rectangle of whole texels.
rl::Image text_texture() {
    rl::Image texture(kTexWidth, kTexHeight, kPaper);
    std::vector<FontVertex> vertices(4 * 1000);  // 1000 quads: far more than three lines use
    for (std::size_t line = 0; line < kLines.size(); ++line) {
        std::string text = kLines[line];
        const int quads = stb_easy_font_print(
            4, 4 + 14 * static_cast<float>(line), text.data(), nullptr, vertices.data(),
            static_cast<int>(vertices.size() * sizeof(FontVertex)));
        for (int q = 0; q < quads; ++q) {
            const FontVertex* v = &vertices[4 * static_cast<std::size_t>(q)];
            const int x0 = static_cast<int>(std::lround(std::min(v[0].x, v[2].x)));
            const int x1 = static_cast<int>(std::lround(std::max(v[0].x, v[2].x)));
            const int y0 = static_cast<int>(std::lround(std::min(v[0].y, v[2].y)));
            const int y1 = static_cast<int>(std::lround(std::max(v[0].y, v[2].y)));
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    const int row = kTexHeight - 1 - y;  // the image keeps its bottom row first
                    if (texture.contains(x, row)) texture.set(x, row, kInk);
                }
        }
    }
    return texture;
}

std::vector<std::uint8_t> bytes_of(const std::string& text) {
    return {text.begin(), text.end()};
}

}  // namespace

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 11's sign of small text, for the picture of the edge filter on text: writes "
        "its texture (-o) and, beside it, sign.obj and sign.mtl"};
    std::string texture_name = "sign_diffuse.tga";
    app.add_option("-o,--output", texture_name,
                   "The sign's texture (.tga or .png); sign.obj and sign.mtl go in its folder")
        ->capture_default_str();
    return app.run(argc, argv, "11_text_sign", [&] {
        const std::filesystem::path texture = texture_name;
        rl::check_image_output(texture);
        const std::filesystem::path folder = texture.parent_path();
        const float half_width = 0.005f * kTexWidth, height = 0.01f * kTexHeight;
        const std::string obj =
            "# sign: a " + std::to_string(2 * half_width) + " x " + std::to_string(height) +
            " quad in the plane z = 0 facing +z, one texel per 0.01 (made by 11_text_sign)\n"
            "mtllib sign.mtl\nusemtl sign\n"
            "v " +
            std::to_string(-half_width) + " 0 0\nv " + std::to_string(half_width) + " 0 0\nv " +
            std::to_string(half_width) + " " + std::to_string(height) + " 0\nv " +
            std::to_string(-half_width) + " " + std::to_string(height) +
            " 0\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
            "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";
        const std::string mtl = "newmtl sign\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nNs 1\nmap_Kd " +
                                texture.filename().string() + "\n";
        // All three or none; a texture named sign.obj or sign.mtl is refused
        // (not .tga or .png), and OutputFiles refuses two names for one file.
        rl::OutputFiles files;
        files.check(folder / "sign.obj");
        files.check(folder / "sign.mtl");
        files.check(texture);
        files.stage(folder / "sign.obj", bytes_of(obj));
        files.stage(folder / "sign.mtl", bytes_of(mtl));
        files.stage(texture, rl::encode_image(texture, text_texture()));
        files.commit();
        std::printf("wrote %s, and sign.obj and sign.mtl beside it\n", texture.string().c_str());
        return 0;
    });
}
