// The check every direction a user gives (a light's, say) passes before it
// is normalised: shared by the programs' command lines and the Python module.
//
//   std::vector<float> light{1, 1, 1};  // from --light X Y Z
//   rl::check_direction("--light", light);  // throws std::invalid_argument for 0 0 0
//   const rl::vec3 to_light = rl::normalize(rl::vec3{light[0], light[1], light[2]});
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace rl {

// Throws std::invalid_argument naming `option` unless the vector can be
// normalised in float: not zero, and its squared length neither underflows
// (1e-30 1e-30 1e-30) nor overflows (1e30 0 0).
inline void check_direction(const std::string& option, const std::vector<float>& v) {
    float length2 = 0;
    for (float c : v) length2 += c * c;
    if (!std::isnormal(length2))
        throw std::invalid_argument(option +
                                    ": needs a direction whose length squared is a normal float "
                                    "(not zero, not below 1e-19 or above 1e19 in length)");
}

}  // namespace rl
