// Stages 7-8 of lesson 05's pipeline for one covered sample: the depth
// test, the fragment stage and the writes into the render target, in the
// halves every coverage policy calls (sample_passes, shade, write_sample).
//
//   pipeline::fragment_operations(program, t, x, y, z, weights, target, x, counts);
#pragma once

#include <algorithm>
#include <optional>
#include <tuple>
#include <utility>
#include <variant>

#include "03_zbuffer/depth_test.hpp"
#include "pipeline_options.hpp"
#include "program.hpp"
#include "render_target.hpp"
#include "triangle_setup.hpp"

namespace pipeline {

// Writes a fragment's outputs into the target's colour attachments: one
// value for a target of one attachment, a tuple in attachment order for several.
template <class Outputs, class... Pixels>
void store(RenderTarget<Pixels...>& target, int column, int y, const Outputs& out) {
    if constexpr (sizeof...(Pixels) == 1) {
        target.template colour<0>().at(column, y) = out;
    } else {
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((target.template colour<I>().at(column, y) = std::get<I>(out)), ...);
        }
        (std::index_sequence_for<Pixels...>{});
    }
}

// The target's depth bias (lesson 08's) for triangle t: constant, plus
// slope-scaled by the triangle's depth slope. Once per triangle.
template <Interpolable V, class F>
float depth_bias(const TriangleSetup<V, F>& t, const zbuffer::DepthState& state) {
    return state.constant_bias + state.slope_bias * t.depth_slope;
}

// The window depth at weights b: interpolated with the plain weights (window
// depth is linear on screen), plus the bias, kept in [0, 1].
template <Interpolable V, class F>
float window_depth(const TriangleSetup<V, F>& t, rl::vec3 b, float bias) {
    const float z = zbuffer::interpolate_depth(b, t.window[0].z, t.window[1].z, t.window[2].z);
    return bias != 0 ? std::clamp(z + bias, 0.0f, 1.0f) : z;
}

// [doc:fragment-operations]
// The fragment operations of one covered sample, in the halves every
// coverage policy calls: the sample's test, before the fragment stage (as a
// GPU's early depth test), and its write. In between, the fragment stage,
// whose outputs are nothing where the program discards: such a fragment
// writes neither colour nor depth.
template <class... Pixels>
bool sample_passes(const RenderTarget<Pixels...>& target, int column, int y, float z) {
    const rl::FloatImage* const depth = target.depth();
    return !depth || zbuffer::depth_passes(target.depth_state.compare, z, depth->at(column, y));
}

template <class Outputs, class... Pixels>
void write_sample(RenderTarget<Pixels...>& target, int column, int y, float z, const Outputs& out) {
    if constexpr (sizeof...(Pixels) > 0) store(target, column, y, out);
    rl::FloatImage* const depth = target.depth();
    if (depth && target.depth_state.write) depth->at(column, y) = z;
}

template <class P, Interpolable V, class F, class... Pixels>
auto shade(const P& program, const Fragment<V, F>& fragment, const RenderTarget<Pixels...>&,
           PipelineCounts& counts) {
    if constexpr (!ProgramTraits<P>::may_discard && sizeof...(Pixels) == 0) {
        return std::optional<std::monostate>(std::in_place);  // depth only: nothing to run
    } else {
        ++counts.shaded;
        if constexpr (ProgramTraits<P>::may_discard)
            return program.fragment(fragment);  // an optional
        else
            return std::optional(program.fragment(fragment));
    }
}

// One sample of triangle t at window depth z, stored at (column, y) of the
// target: its test, the fragment stage (its varyings at weights b, pixel
// (x, y)), its write; counted in `counts`.
template <class P, Interpolable V, class F, class... Pixels>
void fragment_operations(const P& program, const TriangleSetup<V, F>& t, int x, int y, float z,
                         rl::vec3 b, RenderTarget<Pixels...>& target, int column,
                         PipelineCounts& counts) {
    if (!sample_passes(target, column, y, z)) return;
    const auto out = shade(program, fragment_at(t, x, y, z, b), target, counts);
    if (!out) return;
    write_sample(target, column, y, z, *out);
    ++counts.stored;
}
// [/doc:fragment-operations]

}  // namespace pipeline
