// Identities the vector and matrix code must satisfy.
#include <gtest/gtest.h>

#include "rasterlab/mat.hpp"
#include "rasterlab/vec.hpp"

namespace {

using namespace rl;

TEST(Vec, ArithmeticAndProducts) {
    const vec3 a{1, 2, 3}, b{4, 5, 6};
    EXPECT_EQ(a + b, (vec3{5, 7, 9}));
    EXPECT_EQ(b - a, (vec3{3, 3, 3}));
    EXPECT_EQ(a * 2.0f, (vec3{2, 4, 6}));
    EXPECT_EQ(a * b, (vec3{4, 10, 18}));
    EXPECT_FLOAT_EQ(dot(a, b), 32.0f);
    EXPECT_EQ(cross(vec3{1, 0, 0}, vec3{0, 1, 0}), (vec3{0, 0, 1}));  // right-handed
    EXPECT_FLOAT_EQ(cross(vec2{1, 0}, vec2{0, 1}), 1.0f);             // counter-clockwise > 0
}

TEST(Vec, CrossIsPerpendicularAndAntiCommutative) {
    const dvec3 a{0.3, -1.2, 2.5}, b{-0.7, 0.4, 1.1};
    const dvec3 c = cross(a, b);
    EXPECT_NEAR(dot(c, a), 0.0, 1e-12);
    EXPECT_NEAR(dot(c, b), 0.0, 1e-12);
    EXPECT_EQ(cross(b, a), -c);
    // |a x b|^2 = |a|^2 |b|^2 - (a.b)^2 (Lagrange's identity)
    EXPECT_NEAR(dot(c, c), dot(a, a) * dot(b, b) - dot(a, b) * dot(a, b), 1e-12);
}

TEST(Vec, NormalizeGivesUnitLengthAndKeepsZero) {
    EXPECT_NEAR(length(normalize(vec3{3, 4, 12})), 1.0f, 1e-6f);
    EXPECT_EQ(normalize(vec3{0, 0, 0}), (vec3{0, 0, 0}));
    EXPECT_FLOAT_EQ(length(vec2{3, 4}), 5.0f);
}

// Squared components below FLT_MIN are subnormal and keep few digits: a
// length taken from them is off by up to 10% (issue 17's audit saw 0.918 at |v| = 7e-23), so such
// a vector is scaled before it is normalised, as one past 1e19 is.
TEST(Vec, NormalizeGivesUnitLengthWhenTheSquaresUnderflowOrOverflow) {
    for (const vec3& v : {vec3{7e-23f, 3e-23f, 1e-23f}, vec3{5e-24f, 0, 2e-24f}, vec3{1e-40f, 0, 0},
                          vec3{3e19f, 4e19f, 0}, vec3{3e37f, 4e37f, 0}}) {
        const vec3 n = normalize(v);
        const dvec3 exact = normalize(cast<double>(v));
        for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(n[i], exact[i], 1e-6) << v;
    }
}

TEST(Mat, IdentityAndProducts) {
    const mat3 id = mat3::identity();
    const mat3 m{{vec3{1, 2, 3}, vec3{0, 1, 4}, vec3{5, 6, 0}}};
    EXPECT_EQ(m * id, m);
    EXPECT_EQ(id * m, m);
    EXPECT_EQ((m * vec3{1, 0, 0}), (vec3{1, 0, 5}));  // the first column
    EXPECT_EQ(transpose(transpose(m)), m);
    EXPECT_EQ(transpose(m)[0], (vec3{1, 0, 5}));
    EXPECT_FLOAT_EQ(determinant(m), 1.0f);
}

TEST(Mat, TransposeOfProductIsProductOfTransposesReversed) {
    const dmat4 a{{dvec4{1, 2, 0, 1}, dvec4{0, 1, 3, 0}, dvec4{2, 0, 1, 1}, dvec4{0, 0, 0, 1}}};
    const dmat4 b{{dvec4{0, 1, 0, 2}, dvec4{1, 0, 0, 0}, dvec4{0, 0, 2, 1}, dvec4{3, 0, 0, 1}}};
    EXPECT_EQ(transpose(a * b), transpose(b) * transpose(a));
}

TEST(Mat, InverseTimesMatrixIsIdentity) {
    const mat4 m{{vec4{2, 0, 1, 3}, vec4{1, 1, 0, -1}, vec4{0, 3, 1, 2}, vec4{0, 0, 0, 1}}};
    const auto inv = inverse(m);
    ASSERT_TRUE(inv.has_value());
    const mat4 product = m * *inv;
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = 0; j < 4; ++j) EXPECT_NEAR(product[i][j], i == j ? 1.0f : 0.0f, 1e-5f);
}

TEST(Mat, InversionReportsTheDeterminant) {
    const dmat3 m{{dvec3{0, 2, 1}, dvec3{1, 0, 0}, dvec3{3, 1, 4}}};  // needs a row swap
    const auto result = invert(m);
    ASSERT_TRUE(result.inverse.has_value());
    EXPECT_NEAR(result.determinant, determinant(m), 1e-12);
}

TEST(Mat, SingularMatricesHaveNoInverse) {
    const mat3 rank2{{vec3{1, 2, 3}, vec3{2, 4, 6}, vec3{0, 1, 1}}};
    EXPECT_FALSE(inverse(rank2).has_value());
    EXPECT_FALSE(inverse(mat4{}).has_value());
    const mat3 nearly{{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1e-9f}}};
    EXPECT_FALSE(inverse(nearly).has_value());
}

}  // namespace
