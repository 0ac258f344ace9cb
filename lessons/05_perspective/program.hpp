// What the pipeline asks of a program: its varyings, its vertex function,
// and, if it declares them, its flat values and whether its fragment stage
// may discard (pipeline.hpp's opening comment shows a whole program).
//
//   struct Cutout { using Varyings = rl::vec2; static constexpr bool may_discard = true; ... };
//   static_assert(pipeline::ProgramTraits<Cutout>::may_discard);
#pragma once

#include <concepts>
#include <type_traits>

#include "clipping.hpp"
#include "varyings.hpp"

namespace pipeline {

// A program's flat values (not interpolated: every pixel of a triangle gets
// those of the face's first vertex, its "provoking vertex" as Direct3D and
// Vulkan choose it; OpenGL's default is the last), and whether its fragment
// stage may discard a pixel. Both are declared by the program: `using Flat
// = ...;` and `static constexpr bool may_discard = true;` (then fragment()
// returns std::optional); a program that declares neither has neither.
template <class P>
struct ProgramTraits {
    static constexpr auto flat() {
        if constexpr (requires { typename P::Flat; })
            return std::type_identity<typename P::Flat>{};
        else
            return std::type_identity<NoFlat>{};
    }
    using Flat = typename decltype(flat())::type;
    static constexpr bool may_discard = [] {
        if constexpr (requires { P::may_discard; })
            return static_cast<bool>(P::may_discard);
        else
            return false;
    }();
};
template <class P>
using FlatOf = typename ProgramTraits<P>::Flat;

template <class P, class Corner>
concept Program = Interpolable<typename P::Varyings> && requires(const P& p, const Corner& c) {
    { p.vertex(c) } -> std::same_as<ClipVertex<typename P::Varyings, FlatOf<P>>>;
};

}  // namespace pipeline
