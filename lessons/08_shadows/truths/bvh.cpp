#include "bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace shadows {
namespace {

rl::dvec3 centre(const pipeline::WorldTriangle& t) {
    return (t.p[0] + t.p[1] + t.p[2]) * (1.0 / 3);
}

// Whether the ray crosses the box within (t_min, t_max): the slab test.
bool crosses(rl::dvec3 low, rl::dvec3 high, rl::dvec3 origin, rl::dvec3 inverse, double t_min,
             double t_max) {
    for (std::size_t k = 0; k < 3; ++k) {
        double t0 = (low[k] - origin[k]) * inverse[k], t1 = (high[k] - origin[k]) * inverse[k];
        if (t0 > t1) std::swap(t0, t1);
        if (std::isnan(t0) || std::isnan(t1)) continue;  // origin on a slab's plane, ray along it
        t_min = std::max(t_min, t0);
        t_max = std::min(t_max, t1);
        if (t_min > t_max) return false;
    }
    return true;
}

}  // namespace

Bvh::Bvh(std::vector<pipeline::WorldTriangle> triangles) : triangles_(std::move(triangles)) {
    if (triangles_.empty()) return;
    order_.resize(triangles_.size());
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    // Nodes are built breadth-first from a work list, so that no recursion
    // depth depends on the input.
    struct Task {
        int node, first, count;
    };
    nodes_.push_back({});
    std::vector<Task> work{{0, 0, static_cast<int>(triangles_.size())}};
    while (!work.empty()) {
        const Task task = work.back();
        work.pop_back();
        Node node;
        node.low = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
        node.high = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
        rl::dvec3 c_low = node.low, c_high = node.high;
        for (int i = task.first; i < task.first + task.count; ++i) {
            const pipeline::WorldTriangle& t =
                triangles_[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])];
            for (const rl::dvec3& p : t.p)
                for (std::size_t k = 0; k < 3; ++k) {
                    node.low[k] = std::min(node.low[k], p[k]);
                    node.high[k] = std::max(node.high[k], p[k]);
                }
            const rl::dvec3 c = centre(t);
            for (std::size_t k = 0; k < 3; ++k) {
                c_low[k] = std::min(c_low[k], c[k]);
                c_high[k] = std::max(c_high[k], c[k]);
            }
        }
        const rl::dvec3 extent = c_high - c_low;
        const std::size_t axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                                 : extent.y >= extent.z                       ? 1
                                                                              : 2;
        if (task.count <= 4 || !(extent[axis] > 0)) {  // a leaf (or centres all at one point)
            node.first = task.first;
            node.count = task.count;
            nodes_[static_cast<std::size_t>(task.node)] = node;
            continue;
        }
        const auto begin = order_.begin() + task.first, end = begin + task.count;
        std::nth_element(begin, begin + task.count / 2, end, [&](int a, int b) {
            return centre(triangles_[static_cast<std::size_t>(a)])[axis] <
                   centre(triangles_[static_cast<std::size_t>(b)])[axis];
        });
        node.first = static_cast<int>(nodes_.size());
        node.count = 0;
        nodes_[static_cast<std::size_t>(task.node)] = node;
        nodes_.push_back({});
        nodes_.push_back({});
        const int half = task.count / 2;
        work.push_back({node.first, task.first, half});
        work.push_back({node.first + 1, task.first + half, task.count - half});
    }
}

template <bool kAny>
RayHit Bvh::trace(rl::dvec3 origin, rl::dvec3 d, double t_min, double t_max) const {
    RayHit best;
    if (nodes_.empty()) return best;
    const rl::dvec3 inverse{1 / d.x, 1 / d.y, 1 / d.z};
    // A median split halves each node: the tree is at most ~log2(n) + 1 deep,
    // so 128 entries hold every pending node of any input that fits in memory.
    std::array<int, 128> stack{};
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
        if (!crosses(node.low, node.high, origin, inverse, t_min, std::min(t_max, best.t)))
            continue;
        if (node.count == 0) {
            if (top + 2 > static_cast<int>(stack.size())) continue;  // cannot happen (see above)
            stack[top++] = node.first;
            stack[top++] = node.first + 1;
            continue;
        }
        for (int i = node.first; i < node.first + node.count; ++i) {
            const int index = order_[static_cast<std::size_t>(i)];
            const std::optional<pipeline::Hit> hit =
                pipeline::intersect(triangles_[static_cast<std::size_t>(index)], origin, d);
            if (!hit || !(hit->depth > t_min) || !(hit->depth < std::min(t_max, best.t))) continue;
            best = {index, hit->depth};
            if constexpr (kAny) return best;
        }
    }
    return best;
}

RayHit Bvh::nearest(rl::dvec3 origin, rl::dvec3 d, double t_min, double t_max) const {
    return trace<false>(origin, d, t_min, t_max);
}

bool Bvh::any(rl::dvec3 origin, rl::dvec3 d, double t_min, double t_max) const {
    return trace<true>(origin, d, t_min, t_max).triangle >= 0;
}

}  // namespace shadows
