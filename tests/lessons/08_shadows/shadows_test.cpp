#include <gtest/gtest.h>

#include "08_shadows/light_space.hpp"

namespace {

using namespace shadows;

// The orthographic projection sends its box's corners to the NDC cube's.
TEST(ShadowsTest, OrthographicSendsItsBoxToTheCube) {
    const rl::mat4 m = orthographic(-2, 4, -1, 3, 1, 11);
    const rl::vec4 low = m * rl::vec4{-2, -1, -1, 1}, high = m * rl::vec4{4, 3, -11, 1};
    EXPECT_NEAR(low.x, -1, 1e-6f);
    EXPECT_NEAR(low.y, -1, 1e-6f);
    EXPECT_NEAR(low.z, -1, 1e-6f);
    EXPECT_NEAR(high.x, 1, 1e-6f);
    EXPECT_NEAR(high.y, 1, 1e-6f);
    EXPECT_NEAR(high.z, 1, 1e-6f);
    EXPECT_EQ(low.w, 1.0f);
}

}  // namespace
