#include "hidden_surfaces.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "rasterlab/random.hpp"

namespace zbuffer {

void draw_in_order(const std::vector<SceneTriangle>& scene, Frame& frame) {
    for (const SceneTriangle& t : scene)
        frame.refused += !triangles::rasterize_edge(
            screen(t), frame.colour.width(), frame.colour.height(), [&](int x, int y, rl::vec3 b) {
                frame.colour.at(x, y) = t.colour;
                frame.ids.at(x, y) = t.id;
                frame.depth.at(x, y) = interpolate_depth(b, t.v[0].z, t.v[1].z, t.v[2].z);
            });
}

// [doc:painter]
void sort_far_to_near(std::vector<SceneTriangle>& scene) {
    auto mean_depth = [](const SceneTriangle& t) { return t.v[0].z + t.v[1].z + t.v[2].z; };
    std::stable_sort(scene.begin(), scene.end(),
                     [&](const SceneTriangle& a, const SceneTriangle& b) {
                         return mean_depth(a) > mean_depth(b);
                     });
}

void draw_painter(std::vector<SceneTriangle> scene, Frame& frame) {
    sort_far_to_near(scene);
    draw_in_order(scene, frame);
}
// [/doc:painter]

// [doc:zbuffer]
void draw_zbuffer(const std::vector<SceneTriangle>& scene, Frame& frame) {
    for (const SceneTriangle& t : scene)
        frame.refused += !triangles::rasterize_edge(
            screen(t), frame.colour.width(), frame.colour.height(), [&](int x, int y, rl::vec3 b) {
                // Window depth is affine in screen space: interpolate it linearly.
                const float z = interpolate_depth(b, t.v[0].z, t.v[1].z, t.v[2].z);
                if (!test_and_store_depth(frame.depth, x, y, z)) return;
                frame.colour.at(x, y) = t.colour;
                frame.ids.at(x, y) = t.id;
            });
}
// [/doc:zbuffer]

namespace {

rl::dvec3 as_double(rl::vec3 v) {
    return rl::cast<double>(v);
}

// |distance| below this counts as on the plane: float window coordinates of an
// 800-pixel image are only good to about 5e-5 pixels.
constexpr double kOnPlane = 1e-4;

// [doc:bsp-split]
// Splits a triangle by the plane into the polygons in front and behind.
void split_triangle(const std::array<rl::vec3, 3>& polygon, const std::array<double, 3>& side,
                    std::vector<rl::vec3>& front, std::vector<rl::vec3>& back) {
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        if (side[i] >= -kOnPlane) front.push_back(polygon[i]);
        if (side[i] <= kOnPlane) back.push_back(polygon[i]);
        if ((side[i] > kOnPlane && side[j] < -kOnPlane) ||
            (side[i] < -kOnPlane && side[j] > kOnPlane)) {
            const double t = side[i] / (side[i] - side[j]);  // where the edge meets the plane
            const rl::vec3 p = polygon[i] + (polygon[j] - polygon[i]) * static_cast<float>(t);
            front.push_back(p);
            back.push_back(p);
        }
    }
}

// [/doc:bsp-split]

void add_fan(const std::vector<rl::vec3>& polygon, const SceneTriangle& source,
             std::vector<SceneTriangle>& out) {
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        SceneTriangle piece = source;
        piece.v[0] = polygon[0], piece.v[1] = polygon[k], piece.v[2] = polygon[k + 1];
        out.push_back(piece);
    }
}

std::unique_ptr<BspNode> build_node(std::vector<SceneTriangle> scene, BspTree& tree, int depth) {
    if (scene.empty()) return nullptr;
    if (depth > kMaxBspDepth)
        throw BspTooLarge("BSP tree deeper than " + std::to_string(kMaxBspDepth) +
                          " levels; refusing (draw this scene with --hsr zbuffer)");
    tree.depth = std::max(tree.depth, depth);
    ++tree.nodes;
    auto node = std::make_unique<BspNode>();
    const SceneTriangle& splitter = scene.front();
    const rl::dvec3 a = as_double(splitter.v[0]);
    node->normal =
        rl::normalize(rl::cross(as_double(splitter.v[1]) - a, as_double(splitter.v[2]) - a));
    node->offset = -rl::dot(node->normal, a);
    std::vector<SceneTriangle> front, back;
    for (const SceneTriangle& t : scene) {
        std::array<double, 3> side;
        bool any_front = false, any_back = false;
        for (int k = 0; k < 3; ++k) {
            side[static_cast<std::size_t>(k)] =
                rl::dot(node->normal, as_double(t.v[k])) + node->offset;
            any_front |= side[static_cast<std::size_t>(k)] > kOnPlane;
            any_back |= side[static_cast<std::size_t>(k)] < -kOnPlane;
        }
        if (!any_front && !any_back) {
            node->coplanar.push_back(t);
            ++tree.triangles;
        } else if (!any_back) {
            front.push_back(t);
        } else if (!any_front) {
            back.push_back(t);
        } else {  // straddles the plane: cut it
            std::vector<rl::vec3> in_front, behind;
            split_triangle({t.v[0], t.v[1], t.v[2]}, side, in_front, behind);
            add_fan(in_front, t, front);
            add_fan(behind, t, back);
            tree.pieces += in_front.size() + behind.size() - 5;  // 2 or 3 pieces replace 1
            if (tree.pieces > tree.max_pieces)
                throw BspTooLarge("BSP tree: splitting made more than " +
                                  std::to_string(tree.max_pieces) +
                                  " triangles; refusing (draw this scene with --hsr zbuffer)");
        }
    }
    node->front = build_node(std::move(front), tree, depth + 1);
    node->back = build_node(std::move(back), tree, depth + 1);
    return node;
}

// [doc:bsp-draw]
void draw_node(const BspNode* node, Frame& frame) {
    if (!node) return;
    // The viewer is at depth -infinity: on the front side when the normal points towards it.
    const bool viewer_in_front = node->normal.z < 0;
    draw_node(viewer_in_front ? node->back.get() : node->front.get(), frame);
    draw_in_order(node->coplanar, frame);
    draw_node(viewer_in_front ? node->front.get() : node->back.get(), frame);
}

// [/doc:bsp-draw]

}  // namespace

BspTree build_bsp(std::vector<SceneTriangle> scene) {
    rl::SplitMix64 random(7);
    for (std::size_t i = scene.size(); i > 1; --i)  // Fisher-Yates, reproducible
        std::swap(scene[i - 1], scene[static_cast<std::size_t>(random.next() % i)]);
    BspTree tree;
    tree.pieces = scene.size();
    tree.max_pieces = max_bsp_pieces(scene.size());
    tree.root = build_node(std::move(scene), tree, 1);
    return tree;
}

std::size_t max_bsp_pieces(std::size_t input_triangles) {
    return kBspPiecesPerTriangle * input_triangles + kBspExtraPieces;
}

void draw_bsp(const BspTree& tree, Frame& frame) {
    draw_node(tree.root.get(), frame);
}

void render(HsrMethod method, const std::vector<SceneTriangle>& scene, Frame& frame) {
    switch (method) {
        case HsrMethod::painter:
            draw_painter(scene, frame);
            break;
        case HsrMethod::bsp:
            draw_bsp(build_bsp(scene), frame);
            break;
        case HsrMethod::zbuffer:
            draw_zbuffer(scene, frame);
            break;
    }
}

}  // namespace zbuffer
