// Competing methods sit behind one enum per lesson. Each enum lists its
// values with their names once, in a table of Named<E>:
//
//   enum class Filter { nearest, bilinear };
//   inline constexpr std::array<rl::Named<Filter>, 2> kFilterNames = {
//       {{Filter::nearest, "nearest"}, {Filter::bilinear, "bilinear"}}};
//   inline constexpr std::array<Filter, 2> kFilters = rl::values_of(kFilterNames);
//   inline const char* name(Filter f) { return rl::name_in(kFilterNames, f); }
//
// and `name(E)` is found by argument-dependent lookup. The helpers below
// turn names into values and back, for the command lines, the labs and the
// tests alike.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

namespace rl {

template <class E>
struct Named {
    E value;
    const char* name;
};

template <class E, std::size_t N>
constexpr std::array<E, N> values_of(const std::array<Named<E>, N>& table) {
    std::array<E, N> values{};
    for (std::size_t i = 0; i < N; ++i) values[i] = table[i].value;
    return values;
}

template <class E, std::size_t N>
constexpr const char* name_in(const std::array<Named<E>, N>& table, E value) {
    for (const Named<E>& entry : table)
        if (entry.value == value) return entry.name;
    return "?";  // only for a value cast from an out-of-range integer
}

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
