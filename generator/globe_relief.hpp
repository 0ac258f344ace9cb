// The globe's surface as functions: the parametrisation shared by its mesh
// and textures, its relief, and the bumped normal the normal maps encode.
// The generator writes the maps from these; lesson 07's lab uses the same
// functions as the exact normal field its tangent frames are measured against.
//
//   const rl::dvec3 n = assets::globe_normal(0.25, 0.6);  // object space, unit
#pragma once

#include "texture_maps.hpp"

namespace assets {

inline constexpr double kGlobeRadius = 0.9;
inline constexpr double kGlobeSeaLevel = 0.02;
inline constexpr double kGlobeReliefScale = 0.04;  // bump height per unit of noise, in radii

// u runs east with longitude (u = 0.5 faces +z), v north with latitude
// (v = 0: south pole).
struct SpherePoint {
    dvec3 normal, tangent, bitangent;  // N, T = dP/du, B = dP/dv, normalised
};
SpherePoint sphere_point(double u, double v);

double globe_terrain(dvec3 p);  // noise; below kGlobeSeaLevel is ocean
double globe_relief(dvec3 p);   // the height above the sea, 0 at sea

// The relief's slopes along T and B at (u, v), scaled to the bump height.
struct Slopes {
    double along_tangent, along_bitangent;
};
Slopes globe_slopes(const SpherePoint& s);

// The bumped unit normal at (u, v): in object space, and in the (T, B, N)
// tangent space of the smooth sphere.
dvec3 globe_normal(double u, double v);
dvec3 globe_tangent_space_normal(double u, double v);

}  // namespace assets
