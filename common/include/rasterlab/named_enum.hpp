// Competing methods sit behind one enum per lesson. Each enum lists its
// values with their names once, under the enum:
//
//   enum class Filter { nearest, bilinear };
//   RASTERLAB_NAMED_ENUM(Filter, kFilters, {Filter::nearest, "nearest"},
//                        {Filter::bilinear, "bilinear"});
//
// which declares, in the enum's namespace, `kFilters` (every value, in the
// table's order), `name(Filter)` (found by argument-dependent lookup) and
// `name_table(Filter)` (the pairs). The helpers below turn names into values
// and back, for the command lines, the labs and the tests alike.
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

// The table of an enum's values and names, its name() and the array of its
// values, from one list of {value, "name"} pairs (see the top of this file).
// A macro because the three must be declared in the enum's own namespace for
// name() to be found beside the enum.
#define RASTERLAB_NAMED_ENUM(Enum, all_values, ...)           \
    constexpr auto name_table(Enum) {                         \
        return std::to_array<rl::Named<Enum>>({__VA_ARGS__}); \
    }                                                         \
    constexpr const char* name(Enum value) {                  \
        return rl::name_in(name_table(value), value);         \
    }                                                         \
    inline constexpr auto all_values = rl::values_of(name_table(Enum{}))
