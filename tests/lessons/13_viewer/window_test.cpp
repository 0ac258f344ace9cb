// Lesson 13's window under Xvfb: a frame shows right way up. rasterlab
// stores the bottom row first and a window counts rows from its top, so the
// copy to the window flips the rows, and the screenshot flips them back.
// Without both flips the screenshot would still match lesson 12's image
// while the window showed it upside down: this test reads the window at its
// top, in SDL's own coordinates, where the frame's top row must be.
#include <gtest/gtest.h>

#include "13_viewer/sdl_window.hpp"

namespace {

TEST(Window, ShowsTheFramesTopRowAtTheWindowsTop) {
    viewer::SdlWindow window("window_test", 64, 48, false);
    rl::Image frame(64, 48);  // red above the middle, blue below (y counts up)
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            frame.set(x, y, y >= 24 ? rl::Rgba{255, 0, 0, 255} : rl::Rgba{0, 0, 255, 255});
    const rl::Rgba top = window.shown_at(frame, 5, 2), bottom = window.shown_at(frame, 5, 45);
    EXPECT_GT(top.r, 200);
    EXPECT_LT(top.b, 50);
    EXPECT_GT(bottom.b, 200);
    EXPECT_LT(bottom.r, 50);
}

}  // namespace
