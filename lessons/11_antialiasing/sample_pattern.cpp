#include "sample_pattern.hpp"

#include <stdexcept>
#include <string>

namespace antialiasing {

namespace {

// Direct3D's standard patterns, in sixteenths of a pixel from its centre,
// y pointing down as Direct3D's window does (flipped below).
struct Sixteenths {
    int x, y;
};
constexpr Sixteenths kStandard2[] = {{4, 4}, {-4, -4}};
constexpr Sixteenths kStandard4[] = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
constexpr Sixteenths kStandard8[] = {{1, -3}, {-1, 3},  {5, 1}, {-3, -5},
                                     {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
constexpr Sixteenths kStandard16[] = {{1, 1},  {-1, -3}, {-3, 2}, {4, -1}, {-5, -2}, {2, 5},
                                      {5, 3},  {3, -5},  {-2, 6}, {0, -7}, {-4, -6}, {-6, 4},
                                      {-8, 0}, {7, -4},  {6, 7},  {-7, -8}};

template <std::size_t N>
std::vector<rl::vec2> from_sixteenths(const Sixteenths (&table)[N]) {
    std::vector<rl::vec2> out;
    for (const Sixteenths& s : table)
        out.push_back({static_cast<float>(s.x) / 16, -static_cast<float>(s.y) / 16});
    return out;
}

std::vector<rl::vec2> grid(int side) {
    std::vector<rl::vec2> out;
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
            out.push_back({(static_cast<float>(i) + 0.5f) / static_cast<float>(side) - 0.5f,
                           (static_cast<float>(j) + 0.5f) / static_cast<float>(side) - 0.5f});
    return out;
}

const char* counts_of(Pattern pattern) {
    switch (pattern) {
        case Pattern::grid:
            return "1, 4 or 16";
        case Pattern::rotated:
            return "4";
        case Pattern::standard:
            return "1, 2, 4, 8 or 16";
    }
    return "";
}

}  // namespace

bool has_count(Pattern pattern, int samples) {
    switch (pattern) {
        case Pattern::grid:
            return samples == 1 || samples == 4 || samples == 16;
        case Pattern::rotated:
            return samples == 4;
        case Pattern::standard:
            return samples == 1 || samples == 2 || samples == 4 || samples == 8 || samples == 16;
    }
    return false;
}

std::vector<rl::vec2> sample_offsets(Pattern pattern, int samples) {
    if (!has_count(pattern, samples))
        throw std::invalid_argument("the " + std::string(name(pattern)) + " pattern has " +
                                    counts_of(pattern) + " samples a pixel, not " +
                                    std::to_string(samples));
    if (samples == 1) return {{0, 0}};
    switch (pattern) {
        case Pattern::grid:
            return grid(samples == 4 ? 2 : 4);
        case Pattern::rotated:
            // The 2 x 2 grid turned by atan(1/2) = 26.6 degrees and spread a
            // little (0.40 from the centre, not 0.35), so that its samples
            // lie at 1/8 and 3/8 of a pixel from the centre on each axis.
            return {{0.125f, 0.375f}, {-0.375f, 0.125f}, {-0.125f, -0.375f}, {0.375f, -0.125f}};
        case Pattern::standard:
            break;
    }
    switch (samples) {
        case 2:
            return from_sixteenths(kStandard2);
        case 4:
            return from_sixteenths(kStandard4);
        case 8:
            return from_sixteenths(kStandard8);
        default:
            return from_sixteenths(kStandard16);
    }
}

}  // namespace antialiasing
