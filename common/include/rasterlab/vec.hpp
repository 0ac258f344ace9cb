// Small fixed-size vectors: Vec<2|3|4, T> with named components x, y, z, w,
// and the usual arithmetic written once for every size.
//
//   const rl::vec3 n = rl::normalize(rl::cross(b - a, c - a));  // a face normal
//   const float lambert = std::max(0.0f, rl::dot(n, to_light));
//   const rl::vec4 direction = rl::extend(n, 0.0f);  // w = 0: a direction, w = 1: a point
//   const rl::dvec3 exact = rl::cast<double>(a);  // a double-precision reference
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <ostream>

namespace rl {

template <std::size_t N, typename T>
struct Vec;

template <typename T>
struct Vec<2, T> {
    T x{}, y{};
    constexpr T& operator[](std::size_t i) { return i == 0 ? x : y; }
    constexpr const T& operator[](std::size_t i) const { return i == 0 ? x : y; }
};

template <typename T>
struct Vec<3, T> {
    T x{}, y{}, z{};
    constexpr T& operator[](std::size_t i) { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr const T& operator[](std::size_t i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr Vec<2, T> xy() const { return {x, y}; }
};

template <typename T>
struct Vec<4, T> {
    T x{}, y{}, z{}, w{};
    constexpr T& operator[](std::size_t i) { return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w)); }
    constexpr const T& operator[](std::size_t i) const {
        return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w));
    }
    constexpr Vec<3, T> xyz() const { return {x, y, z}; }
};

using vec2 = Vec<2, float>;
using vec3 = Vec<3, float>;
using vec4 = Vec<4, float>;
using dvec2 = Vec<2, double>;
using dvec3 = Vec<3, double>;
using dvec4 = Vec<4, double>;

// Appends a w component: a point (w = 1) or a direction (w = 0).
template <typename T>
constexpr Vec<4, T> extend(const Vec<3, T>& v, T w) {
    return {v.x, v.y, v.z, w};
}

// Converts component-wise, e.g. to compute a double-precision reference.
template <typename To, std::size_t N, typename From>
constexpr Vec<N, To> cast(const Vec<N, From>& v) {
    Vec<N, To> r;
    for (std::size_t i = 0; i < N; ++i) r[i] = static_cast<To>(v[i]);
    return r;
}

template <std::size_t N, typename T>
constexpr bool operator==(const Vec<N, T>& a, const Vec<N, T>& b) {
    for (std::size_t i = 0; i < N; ++i)
        if (a[i] != b[i]) return false;
    return true;
}

template <std::size_t N, typename T>
constexpr Vec<N, T> operator+(Vec<N, T> a, const Vec<N, T>& b) {
    for (std::size_t i = 0; i < N; ++i) a[i] += b[i];
    return a;
}

template <std::size_t N, typename T>
constexpr Vec<N, T> operator-(Vec<N, T> a, const Vec<N, T>& b) {
    for (std::size_t i = 0; i < N; ++i) a[i] -= b[i];
    return a;
}

template <std::size_t N, typename T>
constexpr Vec<N, T> operator-(Vec<N, T> a) {
    for (std::size_t i = 0; i < N; ++i) a[i] = -a[i];
    return a;
}

// Component-wise (Hadamard) product, e.g. colour times colour.
template <std::size_t N, typename T>
constexpr Vec<N, T> operator*(Vec<N, T> a, const Vec<N, T>& b) {
    for (std::size_t i = 0; i < N; ++i) a[i] *= b[i];
    return a;
}

template <std::size_t N, typename T>
constexpr Vec<N, T> operator*(Vec<N, T> a, T s) {
    for (std::size_t i = 0; i < N; ++i) a[i] *= s;
    return a;
}

template <std::size_t N, typename T>
constexpr Vec<N, T> operator*(T s, const Vec<N, T>& a) {
    return a * s;
}

template <std::size_t N, typename T>
constexpr Vec<N, T> operator/(Vec<N, T> a, T s) {
    for (std::size_t i = 0; i < N; ++i) a[i] /= s;
    return a;
}

template <std::size_t N, typename T>
constexpr Vec<N, T>& operator+=(Vec<N, T>& a, const Vec<N, T>& b) {
    return a = a + b;
}

template <std::size_t N, typename T>
constexpr Vec<N, T>& operator-=(Vec<N, T>& a, const Vec<N, T>& b) {
    return a = a - b;
}

template <std::size_t N, typename T>
constexpr Vec<N, T>& operator*=(Vec<N, T>& a, T s) {
    return a = a * s;
}

template <std::size_t N, typename T>
constexpr T dot(const Vec<N, T>& a, const Vec<N, T>& b) {
    T sum{};
    for (std::size_t i = 0; i < N; ++i) sum += a[i] * b[i];
    return sum;
}

template <typename T>
constexpr Vec<3, T> cross(const Vec<3, T>& a, const Vec<3, T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// The z component of the 3D cross product: twice the signed area of the
// triangle (0, a, b), positive when b lies counter-clockwise of a.
template <typename T>
constexpr T cross(const Vec<2, T>& a, const Vec<2, T>& b) {
    return a.x * b.y - a.y * b.x;
}

template <std::size_t N, typename T>
[[gnu::always_inline]] inline T length(const Vec<N, T>& v) {
    return std::sqrt(dot(v, v));
}

template <std::size_t N, typename T>
Vec<N, T> normalize_scaled(const Vec<N, T>& v);

// Unit vector in v's direction; the zero vector stays zero rather than
// turning into NaNs, so a degenerate normal shows up as black, not garbage.
// A vector whose squared length overflows (components past 1e19 in float)
// or falls below the smallest normal float (components below about 1e-19,
// whose squares are subnormal and keep too few digits) is first scaled by its
// largest component. Inlined: it runs several times for every pixel.
template <std::size_t N, typename T>
[[gnu::always_inline]] inline Vec<N, T> normalize(const Vec<N, T>& v) {
    const T squared = dot(v, v);
    if (squared >= std::numeric_limits<T>::min() && squared <= std::numeric_limits<T>::max())
        [[likely]]
        return v / std::sqrt(squared);
    return normalize_scaled(v);  // out of line: the common case above stays small enough to inline
}

// normalize() for vectors whose length underflows or overflows: scaled by
// the largest component first.
template <std::size_t N, typename T>
[[gnu::noinline]] Vec<N, T> normalize_scaled(const Vec<N, T>& v) {
    T largest{};
    for (std::size_t i = 0; i < N; ++i) largest = std::max(largest, std::abs(v[i]));
    if (!(largest > T{0}) || !(largest <= std::numeric_limits<T>::max())) return v;
    const Vec<N, T> scaled = v / largest;
    return scaled / length(scaled);
}

// "(x, y, z)": what GoogleTest prints when a test comparing vectors fails.
template <std::size_t N, typename T>
std::ostream& operator<<(std::ostream& out, const Vec<N, T>& v) {
    out << '(';
    for (std::size_t i = 0; i < N; ++i) out << (i ? ", " : "") << v[i];
    return out << ')';
}

}  // namespace rl
