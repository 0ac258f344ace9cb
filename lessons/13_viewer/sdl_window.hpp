// The window: SDL2's window, renderer and one streaming texture the frame
// is uploaded to each time (rasterlab's rows run bottom first, so the copy to
// the window flips them), the input gathered since the last frame, and the
// last frame read back from the window itself (SDL_RenderReadPixels) for
// the headless tests.
//
//   viewer::SdlWindow window("13_viewer", 800, 600, false);
//   viewer::Input input = window.poll();
//   window.show(frame, nullptr);
#pragma once

#include <string>
#include <vector>

#include "controls.hpp"
#include "rasterlab/image.hpp"

struct SDL_Window;
struct SDL_Renderer;
struct SDL_Texture;

namespace viewer {

struct Input {
    bool quit = false;
    std::vector<Key> keys;
    int drag_x = 0, drag_y = 0;    // pixels dragged with the left button
    int light_x = 0, light_y = 0;  // and with the right button (the light)
    int wheel = 0;                 // steps, towards the screen positive
};

class SdlWindow {
  public:
    // Throws std::runtime_error with SDL's message (no display, say).
    SdlWindow(const char* title, int width, int height, bool vsync);
    ~SdlWindow();
    SdlWindow(const SdlWindow&) = delete;
    SdlWindow& operator=(const SdlWindow&) = delete;

    // Puts key presses (named as key_named() names them) in the event queue,
    // as if they were typed: poll() reads them like any other.
    void send_keys(const std::string& keys);
    Input poll();
    int width() const { return width_; }  // the window's drawable size now
    int height() const { return height_; }
    // Shows `frame`, stretched to the window; if `screenshot`, first reads the
    // window's pixels back and writes them there.
    void show(const rl::Image& frame, const std::string* screenshot);
    // The colour the window shows at column x, row y counted from the
    // window's top (SDL's own coordinates), for `frame` drawn as show()
    // draws it: what a person sees there, for the tests of orientation.
    rl::Rgba shown_at(const rl::Image& frame, int x, int y_from_top);
    void set_title(const char* title);

  private:
    void draw(const rl::Image& frame);  // uploads and copies it into the back buffer
    SDL_Window* window_ = nullptr;
    SDL_Renderer* renderer_ = nullptr;
    SDL_Texture* texture_ = nullptr;
    int texture_width_ = 0, texture_height_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace viewer
