// floor: a square in the y = 0 plane, as a grid of quads, with a checker
// texture repeated four times across. The letter F in one corner of the
// texture shows at a glance whether a texture came out flipped or mirrored.
#include "model_builder.hpp"
#include "models.hpp"
#include "texture_maps.hpp"

namespace assets {
namespace {

constexpr int kCells = 8;       // quads along each side of the mesh
constexpr double kRepeats = 4;  // texture repeats along each side
constexpr int kSize = 1024;
constexpr int kChecks = 8;  // checker squares along each side of the texture

Model floor_mesh() {
    Model m;
    m.name = "floor";
    m.comment =
        "# floor: the square [-1, 1] x [-1, 1] of the plane y = 0, facing +y; "
        "u along +x, v along -z, uv from 0 to 4\n";
    m.mtl_lines = {"map_Kd floor_diffuse.tga"};
    const int up = m.add_normal({0, 1, 0});
    for (int j = 0; j <= kCells; ++j)
        for (int i = 0; i <= kCells; ++i) {
            const double s = double(i) / kCells, t = double(j) / kCells;
            m.add_position({2 * s - 1, 0, 1 - 2 * t});
            m.add_uv({kRepeats * s, kRepeats * t});
        }
    auto at = [](int i, int j) { return j * (kCells + 1) + i; };
    for (int j = 0; j < kCells; ++j)
        for (int i = 0; i < kCells; ++i) {
            const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            m.add_face({a, b, c}, {a, b, c}, {up, up, up});
            m.add_face({a, c, d}, {a, c, d}, {up, up, up});
        }
    return m;
}

// The letter F drawn in the bottom-left square, in texels.
bool letter_f(int x, int y) {
    const int cell = kSize / kChecks;
    const int left = cell / 4, bottom = cell / 6, stroke = cell / 8;
    const int top = cell - cell / 6, arm = cell - cell / 4;
    if (x < left || x >= arm || y < bottom || y >= top) return false;
    const bool stem = x < left + stroke;
    const bool upper_bar = y >= top - stroke;
    const bool middle_bar = y >= (bottom + top) / 2 && y < (bottom + top) / 2 + stroke &&
                            x < left + (arm - left) * 3 / 4;
    return stem || upper_bar || middle_bar;
}

}  // namespace

void make_floor(const std::filesystem::path& dir) {
    write_model(dir, floor_mesh());
    rl::Image diffuse(kSize, kSize);
    const int cell = kSize / kChecks;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const bool dark = ((x / cell) + (y / cell)) % 2 == 1;
            dvec3 colour = dark ? dvec3{0.22, 0.24, 0.28} : dvec3{0.86, 0.85, 0.80};
            const int gx = x % cell, gy = y % cell;
            if (gx < 2 || gy < 2 || gx >= cell - 2 || gy >= cell - 2) colour = {0.5, 0.5, 0.5};
            if (letter_f(x, y)) colour = {0.85, 0.1, 0.08};
            diffuse.set(x, y, to_rgba(colour));
        }
    write_texture(dir, "floor", "diffuse", ".tga", diffuse);
}

}  // namespace assets
