// The per-tile work of the fast path, in SIMD (Google Highway, chosen at run
// time for this CPU, with a portable fallback): rasterize a tile's triangles
// into its depth and triangle-id buffers (the visibility buffer), shade each
// visible pixel once, and copy the tile into the frame. Tile buffers are laid
// out in 8x8 blocks (pixel (x, y) of the tile at block (x/8, y/8), slot
// (y%8)*8 + x%8), so a block's pixels sit side by side in memory.
//
//   fast::TileBuffers buffers(64);  // one per thread, reused tile after tile
//   const fast::TileWork work{x0, y0, 64, 64, &frame_triangles, bin, bin_size, materials, {}};
//   fast::TileCounts counts;
//   fast::render_tile(work, buffers, frame, counts);  // frame: the rl::Image of the whole frame
//   std::printf("kernels: %s\n", fast::simd_target());  // e.g. AVX2
#pragma once

#include <cstdint>
#include <vector>

#include "fast_triangle.hpp"
#include "hwy/aligned_allocator.h"
#include "material.hpp"
#include "rasterlab/image.hpp"

namespace fast {

inline constexpr int kBlock = 8;

// A tile's own buffers, reused from tile to tile by one thread.
struct TileBuffers {
    explicit TileBuffers(int tile_size);
    int size;
    std::size_t pixels;  // size * size
    // Aligned for the widest vector loads.
    hwy::AlignedFreeUniquePtr<float[]> depth;
    hwy::AlignedFreeUniquePtr<std::uint32_t[]>
        id;  // index into the frame's triangles, or kNoTriangle
    hwy::AlignedFreeUniquePtr<std::uint32_t[]> colour;  // RGBA bytes, as rl::Rgba
    std::vector<float> block_far;                       // per block: its farthest depth so far
};
inline constexpr std::uint32_t kNoTriangle = 0xffffffffu;

// The techniques of the tile kernels, each on by default; the lab turns
// them off one at a time to measure what each buys (the image is the same).
struct Techniques {
    bool coarse_blocks = true;  // decide whole 8x8 blocks from their corners
    bool hierarchical_depth =
        true;                  // skip a block whose farthest depth is nearer than the triangle
    bool shade_once = true;    // depth and ids first, then shade each visible pixel once
    bool full_vectors = true;  // queue a triangle's pixels so that the shader's vectors are full
    // ... and queue them across triangles (of one model): pixels of small
    // triangles share the shader's vectors (with full_vectors only)
    bool across_triangles = true;
    // test and shade only the rows of a block that the triangle's box
    // reaches (a small triangle's one or two of the eight)
    bool block_rows = true;
    // encode sRGB with one gather per channel (lesson 06's two tables folded
    // into one), rather than a gather of the first byte and one of the step
    bool srgb_one_gather = true;
};

struct TileWork {
    int x0, y0;         // the tile's lower-left pixel in the frame
    int width, height;  // its pixels within the frame (<= the tile size)
    const TriangleChunks* triangles;
    const std::uint32_t* bin;  // the tile's triangles, in drawing order
    std::size_t bin_size;
    const Material* materials;  // per model
    Techniques techniques;
};

struct TileCounts {
    TileCounts& operator+=(const TileCounts& o);
    std::uint64_t blocks_rejected = 0, blocks_full = 0, blocks_partial = 0;
    std::uint64_t blocks_occluded = 0;  // skipped by the hierarchical depth test
    std::uint64_t depth_passed = 0;     // samples that passed the depth test (overdraw included)
    std::uint64_t shaded = 0;           // pixels shaded (each visible pixel once)
    // Where the tile's time went (nanoseconds): clearing and the visibility
    // pass (with the shading too without shade_once), shading, copying into
    // the frame.
    std::uint64_t raster_ns = 0, shade_ns = 0, copy_ns = 0;
    std::uint64_t lanes = 0;  // SIMD lanes the shader ran on (shaded / lanes: the lanes' use)
};

// Clears the tile, rasterizes its bin (depth test `less`, the first triangle
// drawn wins a tie, as lesson 07's), shades the winners and writes the tile
// into `frame`.
void render_tile(const TileWork& work, TileBuffers& buffers, rl::Image& frame, TileCounts& counts);

// Only the visibility pass: the tile's depth and ids (for the tests and the lab).
void rasterize_tile(const TileWork& work, TileBuffers& buffers, TileCounts& counts);

// The SIMD sRGB encoding of linear values, for a test to hold against
// lesson 06's encode(): bytes[i] for values[i], count a multiple of nothing;
// one_gather as Techniques::srgb_one_gather.
void encode_srgb(const float* values, std::uint8_t* bytes, std::size_t count, bool one_gather);

// The first three channels of the packed texels at `count` indices, as the
// shader's lookups decode them, for a test to hold against the values the
// texels stand for: rgb[3 * i + c] for texel index[i].
void decode_texels(const PackedTexture& texture, const std::int32_t* index, std::size_t count,
                   float* rgb);

// The name of the instruction set the kernels run with on this CPU.
const char* simd_target();

// The instruction sets the kernels were compiled for that this CPU runs,
// best first, as Highway's target bits (hwy::SetSupportedTargetsForTest
// with one of them makes the kernels run with it; 0 goes back to the best).
std::vector<std::int64_t> simd_targets();

}  // namespace fast
