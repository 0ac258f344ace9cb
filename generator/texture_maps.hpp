// Texture-making helpers for the generator: noise, colour ramps, and normal
// maps derived from height fields.
#pragma once

#include <filesystem>
#include <string>

#include "rasterlab/image.hpp"
#include "rasterlab/vec.hpp"

namespace assets {

using rl::dvec3;
using HeightField = rl::Grid<double>;  // one height per texel, bottom row first

// Fractal Perlin noise (stb_perlin) at a point in space: `octaves` layers,
// each twice the frequency and half the amplitude of the last. Roughly -1..1.
double fbm(dvec3 p, int octaves);

// The same over the unit square, seamless across u = 0/1 and v = 0/1:
// `cells` (a power of two up to 256) noise cells across at the first octave.
double tileable_fbm(double u, double v, int cells, int octaves, int seed);

double smoothstep(double edge0, double edge1, double x);
dvec3 mix(dvec3 a, dvec3 b, double t);

// A colour with components in 0..1, rounded to 8 bits (clamped).
rl::Rgba to_rgba(dvec3 colour);

// A unit vector stored as a colour: rgb = (n + 1) / 2, the OpenGL convention.
rl::Rgba encode_normal(dvec3 n);

// The tangent-space normal map of a height field drawn over the texture:
// heights are in texels, so `strength` = 1 means a slope of 1 per texel.
// The normal of the surface z = h(x, y) is (-dh/dx, -dh/dy, 1): red follows
// +u, green +v. Neighbours wrap around when `seamless`, else clamp.
rl::Image tangent_normal_map(const HeightField& height, double strength, bool seamless);

// Heights mapped linearly from [low, high] to grey 0..255.
rl::Image grey_image(const HeightField& height, double low, double high);

// Writes <dir>/<model>_<suffix><extension> (.png or .tga, RLE).
void write_texture(const std::filesystem::path& dir, const std::string& model,
                   const std::string& suffix, const std::string& extension, const rl::Image& image);

}  // namespace assets
