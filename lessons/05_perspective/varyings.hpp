// Varyings: what the vertex stage hands on to be interpolated across a
// triangle (texture coordinates, normals, positions, light). A varyings type
// is any struct made only of floats (float, rl::vec2, rl::vec3, structs of
// them); the pipeline adds and scales it as one row of floats, so its
// arithmetic is written once, here, and no member can be forgotten.
//
//   struct Varyings { rl::vec3 normal; rl::vec2 uv; };   // nothing else to write
//   const Varyings mid = pipeline::blend(a, 0.5f, b, 0.5f);
#pragma once

#include <array>
#include <bit>
#include <concepts>
#include <cstddef>
#include <type_traits>

#include "rasterlab/mat.hpp"
#include "rasterlab/vec.hpp"

namespace pipeline {

// Made of floats: trivially copyable, a whole number of floats in size, and
// aligned as a float (a member of another type, an int say, would be added
// as if it were a float: keep flat data in a program's Flat type instead).
template <class V>
concept Interpolable = std::default_initializable<V> && std::is_trivially_copyable_v<V> &&
                       (sizeof(V) % sizeof(float) == 0) &&
                       (alignof(V) == alignof(float));

template <Interpolable V>
using Lanes = std::array<float, sizeof(V) / sizeof(float)>;

// a * s + b * t, member by member.
template <Interpolable V>
V blend(const V& a, float s, const V& b, float t) {
    Lanes<V> x = std::bit_cast<Lanes<V>>(a);
    const Lanes<V> y = std::bit_cast<Lanes<V>>(b);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = x[i] * s + y[i] * t;
    return std::bit_cast<V>(x);
}

// a * s.
template <Interpolable V>
V scaled(const V& a, float s) {
    Lanes<V> x = std::bit_cast<Lanes<V>>(a);
    for (float& lane : x) lane *= s;
    return std::bit_cast<V>(x);
}

// v0 * w.x + v1 * w.y + v2 * w.z: the varyings at barycentric weights w.
template <Interpolable V>
V weighted(const V (&v)[3], rl::vec3 w) {
    Lanes<V> x = std::bit_cast<Lanes<V>>(v[0]);
    const Lanes<V> y = std::bit_cast<Lanes<V>>(v[1]), z = std::bit_cast<Lanes<V>>(v[2]);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = x[i] * w.x + y[i] * w.y + z[i] * w.z;
    return std::bit_cast<V>(x);
}

// A clip-space position, in double. In float, a vertex 1e5 away holds its z
// and w to about 0.004, and the near plane's distance z + w of a point 0.001
// in front of the eye is lost in that: clipping would put the cut vertex
// anywhere within a few thousandths of the eye, and its depth with it
// (docs/05_perspective.md#clipping). Computed in double
// from the float model position, z + w keeps its digits.
using ClipPosition = rl::dvec4;

// The clip position of model point p under the matrix m, in double.
inline ClipPosition clip_position(const rl::mat4& m, rl::vec3 p) {
    return rl::cast<double>(m) * ClipPosition{p.x, p.y, p.z, 1.0};
}

// A vertex as the vertex stage hands it on: a clip-space position, the
// varyings to interpolate, and the values that stay the same across the
// triangle (`Flat`, taken from its first vertex: see pipeline.hpp).
struct NoFlat {};

template <Interpolable V, class Flat = NoFlat>
struct ClipVertex {
    ClipPosition position;
    V varyings;
    [[no_unique_address]] Flat flat{};
};

}  // namespace pipeline
