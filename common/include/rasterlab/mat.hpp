// Square matrices, row-major, acting on column vectors (M * v), as in OpenGL's
// mathematics. mat3 and mat4 share one implementation.
//
//   rl::mat3 m = rl::mat3::identity();
//   m[0][2] = 0.5f;  // row 0, column 2: a shear
//   const rl::vec3 v = m * rl::vec3{1, 2, 3};  // each row dotted with v
//   const float det = rl::determinant(m);
//   if (const std::optional<rl::mat3> inverse = rl::inverse(m)) n = rl::transpose(*inverse) * n;
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "rasterlab/vec.hpp"

namespace rl {

template <std::size_t N, typename T>
struct Mat {
    std::array<Vec<N, T>, N> rows{};

    constexpr Vec<N, T>& operator[](std::size_t r) { return rows[r]; }
    constexpr const Vec<N, T>& operator[](std::size_t r) const { return rows[r]; }

    static constexpr Mat identity() {
        Mat m;
        for (std::size_t i = 0; i < N; ++i) m[i][i] = T{1};
        return m;
    }

    constexpr Vec<N, T> column(std::size_t c) const {
        Vec<N, T> v;
        for (std::size_t r = 0; r < N; ++r) v[r] = rows[r][c];
        return v;
    }
};

using mat3 = Mat<3, float>;
using mat4 = Mat<4, float>;
using dmat3 = Mat<3, double>;
using dmat4 = Mat<4, double>;

// The matrix with its entries converted: cast<double>(m).
template <typename To, std::size_t N, typename From>
constexpr Mat<N, To> cast(const Mat<N, From>& m) {
    Mat<N, To> r;
    for (std::size_t i = 0; i < N; ++i) r[i] = cast<To>(m[i]);
    return r;
}

template <std::size_t N, typename T>
constexpr bool operator==(const Mat<N, T>& a, const Mat<N, T>& b) {
    for (std::size_t r = 0; r < N; ++r)
        if (!(a[r] == b[r])) return false;
    return true;
}

template <std::size_t N, typename T>
constexpr Vec<N, T> operator*(const Mat<N, T>& m, const Vec<N, T>& v) {
    Vec<N, T> r;
    for (std::size_t i = 0; i < N; ++i) r[i] = dot(m[i], v);
    return r;
}

template <std::size_t N, typename T>
constexpr Mat<N, T> operator*(const Mat<N, T>& a, const Mat<N, T>& b) {
    Mat<N, T> r;
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j) r[i][j] = dot(a[i], b.column(j));
    return r;
}

template <std::size_t N, typename T>
constexpr Mat<N, T> operator*(Mat<N, T> m, T s) {
    for (auto& row : m.rows) row *= s;
    return m;
}

template <std::size_t N, typename T>
constexpr Mat<N, T> transpose(const Mat<N, T>& m) {
    Mat<N, T> r;
    for (std::size_t i = 0; i < N; ++i) r[i] = m.column(i);
    return r;
}

// Gaussian elimination with partial pivoting. Returns the determinant and
// the inverse; the inverse is empty when a pivot is no larger than
// `epsilon` times the largest entry, i.e. when the matrix is singular or
// too close to singular for its inverse to mean anything.
template <std::size_t N, typename T>
struct Inversion {
    T determinant{};
    std::optional<Mat<N, T>> inverse;
};

template <std::size_t N, typename T>
Inversion<N, T> invert(Mat<N, T> a, T epsilon = static_cast<T>(1e-6)) {
    T scale{};
    for (const auto& row : a.rows)
        for (std::size_t j = 0; j < N; ++j) scale = std::max(scale, std::abs(row[j]));
    Mat<N, T> inv = Mat<N, T>::identity();
    T det{1};
    bool singular = scale == T{0};
    for (std::size_t col = 0; col < N && !singular; ++col) {
        std::size_t pivot = col;
        for (std::size_t r = col + 1; r < N; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        if (std::abs(a[pivot][col]) <= epsilon * scale) {
            singular = true;
            break;
        }
        if (pivot != col) {
            std::swap(a[pivot], a[col]);
            std::swap(inv[pivot], inv[col]);
            det = -det;
        }
        const T p = a[col][col];
        det *= p;
        a[col] = a[col] / p;
        inv[col] = inv[col] / p;
        for (std::size_t r = 0; r < N; ++r) {
            if (r == col) continue;
            const T f = a[r][col];
            a[r] -= a[col] * f;
            inv[r] -= inv[col] * f;
        }
    }
    if (singular) return {T{0}, std::nullopt};
    return {det, inv};
}

template <std::size_t N, typename T>
std::optional<Mat<N, T>> inverse(const Mat<N, T>& m) {
    return invert(m).inverse;
}

// Exact 3x3 determinant by cofactors (no pivoting, no tolerance).
template <typename T>
constexpr T determinant(const Mat<3, T>& m) {
    return dot(m[0], cross(m[1], m[2]));
}

}  // namespace rl
