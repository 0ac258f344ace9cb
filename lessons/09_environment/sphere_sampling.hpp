// Points to sample the sphere with: hashed random numbers (a pixel's own
// sequence, from its seed) and the Hammersley set (evenly spread, the same
// every time), and a frame around a normal that turns a direction sampled
// about +z into one about that normal.
//
//   const environment::Frame frame(n);
//   const rl::dvec2 u = environment::hammersley(i, 64);
//   const rl::dvec3 d = frame.to_world({0, 0, 1});  // = n
#pragma once

#include <cmath>
#include <cstdint>

#include "rasterlab/vec.hpp"

namespace environment {

// A 32-bit hash step (PCG's output function): well-mixed bits from a counter.
inline std::uint32_t hash(std::uint32_t v) {
    v = v * 747796405u + 2891336453u;
    v = ((v >> ((v >> 28u) + 4u)) ^ v) * 277803737u;
    return (v >> 22u) ^ v;
}

// 24 of the bits as a number in [0, 1).
inline double unit_interval(std::uint32_t bits) {
    return (bits >> 8) * (1.0 / 16777216.0);
}

// Point i of the n-point Hammersley set in [0, 1)²: (i + 1/2) / n, and i's
// bits mirrored about the binary point (van der Corput). Every row and
// every column of the square gets its share of points.
inline rl::dvec2 hammersley(std::uint32_t i, std::uint32_t n) {
    std::uint32_t bits = i;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return {(i + 0.5) / n, bits * (1.0 / 4294967296.0)};
}

// Two unit tangents t and b with (t, b, n) right-handed, for a unit n.
struct Frame {
    rl::dvec3 t, b, n;
    explicit Frame(rl::dvec3 normal) : n(normal) {
        const rl::dvec3 helper = std::fabs(n.y) < 0.9 ? rl::dvec3{0, 1, 0} : rl::dvec3{1, 0, 0};
        t = rl::normalize(rl::cross(helper, n));
        b = rl::cross(n, t);
    }
    // A direction given about +z (x along t, y along b), about n.
    rl::dvec3 to_world(rl::dvec3 local) const { return t * local.x + b * local.y + n * local.z; }
    // A world direction in this frame's terms (x along t, y along b, z along n).
    rl::dvec3 to_local(rl::dvec3 world) const {
        return {rl::dot(world, t), rl::dot(world, b), rl::dot(world, n)};
    }
};

}  // namespace environment
