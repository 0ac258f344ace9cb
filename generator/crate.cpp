// crate: a wooden box. Each face carries the whole texture; two faces have
// their u mirrored, so their tangent frames are left-handed, the case that
// normal mapping (lesson 07) must detect from the UVs.
#include <algorithm>
#include <cmath>

#include "model_builder.hpp"
#include "models.hpp"
#include "texture_maps.hpp"

namespace assets {
namespace {

constexpr double kHalf = 0.55;  // half the edge: the corners lie 0.95 from the centre
constexpr int kSize = 512;
constexpr int kFrame = 40;  // width of the frame and the brace, texels
constexpr int kPlate = 56;  // corner plates, texels
constexpr int kPlanks = 4;

struct Side {
    dvec3 normal, tangent, bitangent;  // tangent x bitangent = normal
    bool mirrored;                     // u runs against the tangent
};

constexpr Side kSides[] = {
    {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, false},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}, false},
    {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}, false}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}, true},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}, false}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}, true},
};

Model crate_mesh() {
    Model m;
    m.name = "crate";
    m.comment = "# crate: cube of edge 1.1; the -x and -y faces have mirrored u\n";
    m.mtl_lines = {"map_Kd crate_diffuse.tga", "map_Bump crate_nm_tangent.tga",
                   "map_Ks crate_spec.tga"};
    for (const Side& s : kSides) {
        const int n = m.add_normal(s.normal);
        int p[4], t[4];
        const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // (u, v) before mirroring
        for (int k = 0; k < 4; ++k) {
            const double a = corners[k][0], b = corners[k][1];
            p[k] = m.add_position(s.normal * kHalf + s.tangent * ((2 * a - 1) * kHalf) +
                                  s.bitangent * ((2 * b - 1) * kHalf));
            t[k] = m.add_uv({s.mirrored ? 1 - a : a, b});
        }
        m.add_face({p[0], p[1], p[2]}, {t[0], t[1], t[2]}, {n, n, n});
        m.add_face({p[0], p[2], p[3]}, {t[0], t[2], t[3]}, {n, n, n});
    }
    return m;
}

// What lies at a texel: which part of the crate, and how high it stands.
struct CrateTexel {
    enum Part { plank, groove, frame, plate, rivet } part;
    double height;  // texels
};

CrateTexel crate_texel(double x, double y) {
    auto distance_to_edge = [](double c) { return std::min(c, kSize - c); };
    const double edge = std::min(distance_to_edge(x), distance_to_edge(y));
    const double corner_x = distance_to_edge(x), corner_y = distance_to_edge(y);
    if (corner_x < kPlate && corner_y < kPlate) {
        const double rx = corner_x - kPlate / 2.0, ry = corner_y - kPlate / 2.0;
        const double r = std::sqrt(rx * rx + ry * ry);
        if (r < 7) return {CrateTexel::rivet, 4 + std::sqrt(49 - r * r) * 0.4};
        return {CrateTexel::plate, 4};
    }
    // Frame and brace stand 3 texels proud, with a 4-texel bevel.
    const double brace = std::abs(x - y) / std::sqrt(2.0);  // distance to the diagonal
    const double raised = std::max(smoothstep(kFrame, kFrame - 4, edge),
                                   smoothstep(kFrame / 2.0, kFrame / 2.0 - 4, brace));
    if (raised > 0) return {CrateTexel::frame, 3 * raised};
    const double plank_height = double(kSize) / kPlanks;
    const double seam = std::abs(std::remainder(y, plank_height));
    if (seam < 2) return {CrateTexel::groove, -2 + seam * 0.5};
    return {CrateTexel::plank, 0};
}

dvec3 wood(double x, double y, double variation) {
    const double grain = fbm({x * 0.004, y * 0.09, 0.3}, 5);
    const double fine = fbm({x * 0.03, y * 0.6, 4.2}, 3);
    dvec3 base = mix({0.50, 0.32, 0.16}, {0.66, 0.46, 0.25}, 0.5 + 0.5 * variation);
    return base * (0.85 + 0.25 * grain + 0.08 * fine);
}

}  // namespace

void make_crate(const std::filesystem::path& dir) {
    write_model(dir, crate_mesh());
    rl::Image diffuse(kSize, kSize), specular(kSize, kSize);
    HeightField height(kSize, kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double cx = x + 0.5, cy = y + 0.5;
            const CrateTexel t = crate_texel(cx, cy);
            height.set(x, y, t.height);
            const int plank = static_cast<int>(cy * kPlanks / kSize);
            dvec3 colour;
            double shine = 0.08;
            switch (t.part) {
                case CrateTexel::plank:
                    colour = wood(cx, cy + 37.0 * plank, plank % 2 ? 0.3 : -0.4);
                    break;
                case CrateTexel::groove:
                    colour = {0.12, 0.07, 0.03};
                    break;
                case CrateTexel::frame:
                    colour = wood(cy * 0.5, cx * 0.5, 0.9) * 0.9;
                    break;
                case CrateTexel::plate:
                case CrateTexel::rivet:
                    colour =
                        dvec3{0.55, 0.56, 0.58} * (0.9 + 0.1 * fbm({cx * 0.2, cy * 0.2, 9.0}, 2));
                    shine = 0.85;
                    break;
            }
            diffuse.set(x, y, to_rgba(colour));
            specular.set(x, y, to_rgba({shine, shine, shine}));
        }
    write_texture(dir, "crate", "diffuse", ".tga", diffuse);
    write_texture(dir, "crate", "spec", ".tga", specular);
    write_texture(dir, "crate", "nm_tangent", ".tga", tangent_normal_map(height, 1.0, false));
}

}  // namespace assets
