// Lesson 09's maps: every direction has one face and one place on it, the
// ties on edges and corners agree with the neighbouring face, the lat-long
// map's poles and seam, and what seamless filtering buys at a face's edge.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "09_environment/cube_map.hpp"
#include "09_environment/latlong_map.hpp"

namespace {

using namespace environment;

rl::dvec3 unit(rl::dvec3 d) {
    return d / rl::length(d);
}

// The angle between two directions (radians), exact near 0 (acos of their
// dot product is not: it cannot see below 1.5e-8).
double angle_between(rl::dvec3 a, rl::dvec3 b) {
    return 2 * std::asin(std::min(1.0, 0.5 * rl::length(unit(a) - unit(b))));
}

std::vector<rl::dvec3> random_directions(int count, unsigned seed) {
    std::mt19937 random(seed);
    std::normal_distribution<double> normal;
    std::vector<rl::dvec3> out;
    while (static_cast<int>(out.size()) < count) {
        const rl::dvec3 d{normal(random), normal(random), normal(random)};
        if (rl::length(d) > 1e-6) out.push_back(unit(d));
    }
    return out;
}

TEST(CubeMap, EveryDirectionComesBackFromItsFacePoint) {
    for (const rl::dvec3& d : random_directions(2000, 9)) {
        const FacePoint p = face_point(d);
        ASSERT_GE(p.u, 0.0);
        ASSERT_LE(p.u, 1.0);
        ASSERT_GE(p.v, 0.0);
        ASSERT_LE(p.v, 1.0);
        EXPECT_LT(angle_between(face_direction(p.face, p.u, p.v), d), 1e-12);
    }
}

TEST(CubeMap, AxesLookAtTheFacesCentres) {
    const std::pair<rl::dvec3, Face> axes[] = {{{1, 0, 0}, Face::px}, {{-1, 0, 0}, Face::nx},
                                               {{0, 1, 0}, Face::py}, {{0, -1, 0}, Face::ny},
                                               {{0, 0, 1}, Face::pz}, {{0, 0, -1}, Face::nz}};
    for (const auto& [d, face] : axes) {
        const FacePoint p = face_point(d);
        EXPECT_EQ(p.face, face) << name(face);
        EXPECT_EQ(p.u, 0.5);
        EXPECT_EQ(p.v, 0.5);
    }
}

// A direction on an edge or a corner goes to x before y before z; the
// point it gets lies on that face's edge, and a direction a hair to the
// other side lands on the neighbour's matching edge, at the same place.
TEST(CubeMap, EdgesAndCornersHaveOneFaceAndMeetTheirNeighbour) {
    EXPECT_EQ(face_point({1, 1, 0}).face, Face::px);
    EXPECT_EQ(face_point({-1, 1, 1}).face, Face::nx);  // a corner: x first
    EXPECT_EQ(face_point({0, -1, -1}).face, Face::ny);
    EXPECT_EQ(face_point({0.5, 1, -1}).face, Face::py);
    for (const rl::dvec3& d : random_directions(500, 4)) {
        // Put d on the edge between its face's axis and its second largest axis.
        rl::dvec3 a{std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)};
        int first = 0;
        for (int k = 1; k < 3; ++k)
            if (a[k] > a[first]) first = k;
        int second = (first + 1) % 3;
        if (a[(first + 2) % 3] > a[second]) second = (first + 2) % 3;
        rl::dvec3 edge = d;
        edge[second] = std::copysign(a[first], d[second]);
        const FacePoint on = face_point(edge);
        EXPECT_TRUE(on.u == 0 || on.u == 1 || on.v == 0 || on.v == 1);
        // The tie goes to the earlier axis (x, then y, then z).
        EXPECT_EQ(static_cast<int>(on.face) / 2, std::min(first, second));
        // A hair to either side: the two faces that meet there, at one place.
        rl::dvec3 one = edge, other = edge;
        one[first] *= 1 + 1e-9;
        other[second] *= 1 + 1e-9;
        const FacePoint p = face_point(one), q = face_point(other);
        EXPECT_NE(p.face, q.face);
        EXPECT_TRUE(on.face == p.face || on.face == q.face);
        EXPECT_LT(angle_between(face_direction(p.face, p.u, p.v), face_direction(q.face, q.u, q.v)),
                  1e-8);
    }
}

// docs/09_environment.md's worked example: d = (0.9, 0.3, 0.45) has its
// largest part along x, so it lands on +x; divided by 0.9, z gives
// u = (0.5 + 1) / 2 = 0.75 and y gives v = (1/3 + 1) / 2 = 2/3. In a face of
// 8 texels that is texel (6, 5); the lat-long point of the same direction
// is u = 1/2 + atan2(0.9, -0.45) / 2 pi = 0.8238, v = 1/2 + asin(0.3 / 1.05) / pi = 0.5922.
TEST(WorkedExample, TheFaceAndTheLatLongPointOfThePage) {
    const FacePoint p = face_point({0.9, 0.3, 0.45});
    EXPECT_EQ(p.face, Face::px);
    EXPECT_NEAR(p.u, 0.75, 1e-12);
    EXPECT_NEAR(p.v, 2.0 / 3, 1e-12);
    EXPECT_EQ(static_cast<int>(p.u * 8), 6);
    EXPECT_EQ(static_cast<int>(p.v * 8), 5);
    const rl::dvec2 q = latlong_point({0.9, 0.3, 0.45});
    EXPECT_NEAR(q.x, 0.8238, 5e-5);
    EXPECT_NEAR(q.y, 0.5922, 5e-5);
}

TEST(CubeMap, ZeroAndNonFiniteDirectionsHaveAPlace) {
    for (rl::dvec3 d : {rl::dvec3{0, 0, 0}, rl::dvec3{NAN, 0, 1}, rl::dvec3{INFINITY, 0, 0}}) {
        const FacePoint p = face_point(d);
        EXPECT_EQ(p.face, Face::px);
        EXPECT_EQ(p.u, 0.5);
    }
}

// A smooth environment (radiance varying linearly with direction): along a
// path that crosses a face edge, per-face bilinear clamps at the edge and
// errs there; seamless filtering reads the neighbour and errs less.
TEST(CubeMap, SeamlessFilteringErrsLessThanPerFaceAtTheEdges) {
    auto smooth = [](rl::dvec3 d) {
        d = unit(d);
        return rl::dvec3{1 + d.x, 1 + d.y, 1 + d.z};
    };
    const CubeMap cube = cube_map(smooth, 8);
    double per_face = 0, seamless = 0;
    for (int k = 0; k <= 200; ++k) {  // around the equator, through the four side faces' edges
        const double a = 2 * std::acos(-1.0) * k / 200;
        const rl::dvec3 d{std::cos(a), 0.3, std::sin(a)};
        const rl::dvec3 truth = smooth(d);
        const rl::vec3 dir = rl::cast<float>(d);
        per_face = std::max(
            per_face, rl::length(rl::cast<double>(cube.sample(dir, MapFilter::bilinear)) - truth));
        seamless = std::max(
            seamless, rl::length(rl::cast<double>(cube.sample(dir, MapFilter::seamless)) - truth));
    }
    EXPECT_LT(seamless, 0.5 * per_face) << "seamless " << seamless << ", per face " << per_face;
}

TEST(LatLong, EveryDirectionComesBackFromItsPoint) {
    for (const rl::dvec3& d : random_directions(2000, 5)) {
        const rl::dvec2 p = latlong_point(d);
        ASSERT_GE(p.x, 0.0);
        ASSERT_LE(p.x, 1.0);
        EXPECT_LT(angle_between(latlong_direction(p.x, p.y), d), 1e-9);
    }
    EXPECT_EQ(latlong_point({0, 0, -1}).x, 0.5);  // the middle looks along -z
    EXPECT_EQ(latlong_point({0, 1, 0}).y, 1.0);   // the top row is straight up
    EXPECT_EQ(latlong_point({0, -1, 0}).y, 0.0);
}

// The seam: just either side of u = 0 / 1 the filtered values agree (the
// map wraps); the poles: every longitude at the top gives the same value.
TEST(LatLong, TheSeamWrapsAndThePolesAgree) {
    const LatLongMap map = latlong_map(Analytic::sky, 32);
    const rl::vec3 left =
        map.sample(rl::cast<float>(latlong_direction(1e-6, 0.6)), MapFilter::bilinear);
    const rl::vec3 right =
        map.sample(rl::cast<float>(latlong_direction(1 - 1e-6, 0.6)), MapFilter::bilinear);
    EXPECT_LT(rl::length(left - right), 1e-3f * rl::length(left));
    const rl::vec3 pole = map.sample({0, 1, 0}, MapFilter::bilinear);
    for (double u : {0.1, 0.4, 0.77}) {
        const rl::vec3 near_pole =
            map.sample(rl::cast<float>(latlong_direction(u, 1)), MapFilter::bilinear);
        EXPECT_LT(rl::length(near_pole - pole), 0.02f * rl::length(pole)) << u;
    }
}

TEST(Sky, ZenithHorizonGroundAndSun) {
    const Sky sky = default_sky();
    const rl::dvec3 zenith = radiance(sky, {0, 1, 0});
    EXPECT_GT(zenith.z, zenith.x);                             // blue above
    const rl::dvec3 ground = radiance(sky, {0.3, -0.8, 0.2});  // the square (0, 0): light
    EXPECT_EQ(ground.x, sky.ground.x);                         // below the band: the ground alone
    const rl::dvec3 next = radiance(sky, {1.2, -0.8, 0.2});    // (1.5, 0.25): the square (1, 0)
    EXPECT_EQ(next.x, sky.ground_dark.x);
    const rl::dvec3 sun = radiance(sky, sky.sun_direction);
    EXPECT_GT(sun.x, sky.sun.x);  // the disc, plus the corona and the sky under it
    // Just below the horizon the checker's squares run off to infinity: a
    // defined colour, not an integer overflow.
    const rl::dvec3 grazing = radiance(sky, {1, -1e-300, 0.3});
    EXPECT_TRUE(std::isfinite(grazing.x));
    EXPECT_EQ(radiance(sky, {0, 0, 0}).x, 0.0);
    EXPECT_EQ(radiance(sky, {NAN, 1, 0}).x, 0.0);
    EXPECT_EQ(radiance(sky, {0, 2, 0}).x, zenith.x);  // any length
}

}  // namespace
