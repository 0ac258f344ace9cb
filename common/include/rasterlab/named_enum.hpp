// Competing methods sit behind one enum per lesson; each enum has a
// `const char* name(E)` found by argument-dependent lookup and an array of
// all its values. These helpers turn names into values and back, for the
// command lines, the labs and the tests alike.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

namespace rl {

template <class E, std::size_t N>
std::optional<E> from_name(const std::string& text, const std::array<E, N>& all) {
    for (E value : all)
        if (text == name(value)) return value;
    return std::nullopt;
}

// "a, b or c"
template <class E, std::size_t N>
std::string names_of(const std::array<E, N>& all) {
    std::string out;
    for (std::size_t i = 0; i < N; ++i) {
        if (i > 0) out += i + 1 == N ? " or " : ", ";
        out += name(all[i]);
    }
    return out;
}

}  // namespace rl
