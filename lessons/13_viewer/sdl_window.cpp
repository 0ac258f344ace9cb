#include "sdl_window.hpp"

#include <SDL.h>

#include <cctype>
#include <optional>
#include <stdexcept>
#include <string>

#include "rasterlab/image_io.hpp"

namespace viewer {

namespace {

[[noreturn]] void sdl_failed(const char* what) {
    throw std::runtime_error(std::string(what) + " failed: " + SDL_GetError());
}

// The SDL key that --keys' character stands for, and back.
SDL_Keycode keycode_of(char c) {
    switch (c) {
        case '<':
            return SDLK_LEFT;
        case '>':
            return SDLK_RIGHT;
        case '^':
            return SDLK_UP;
        case 'v':
            return SDLK_DOWN;
        case '+':
            return SDLK_KP_PLUS;
        case '-':
            return SDLK_MINUS;
        default:
            return static_cast<SDL_Keycode>(std::tolower(static_cast<unsigned char>(c)));
    }
}
std::optional<Key> key_of(SDL_Keycode code) {
    switch (code) {
        case SDLK_LEFT:
            return Key::turn_left;
        case SDLK_RIGHT:
            return Key::turn_right;
        case SDLK_UP:
            return Key::move_closer;
        case SDLK_DOWN:
            return Key::move_away;
        case SDLK_PLUS:
        case SDLK_EQUALS:
        case SDLK_KP_PLUS:
            return Key::finer;
        case SDLK_MINUS:
        case SDLK_KP_MINUS:
            return Key::coarser;
        default:
            if (code >= SDLK_a && code <= SDLK_z) return key_of_letter(static_cast<char>(code));
            return std::nullopt;
    }
}

}  // namespace

SdlWindow::SdlWindow(const char* title, int width, int height, bool vsync) {
    if (SDL_Init(SDL_INIT_VIDEO) != 0)
        throw std::runtime_error(std::string("no display to open a window on (SDL_Init: ") +
                                 SDL_GetError() + "); set DISPLAY, or run under xvfb-run");
    // Without a display SDL falls back to drivers that show nothing: a window
    // nobody sees, running until killed, is refused instead.
    const std::string driver = SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "";
    if (driver == "offscreen" || driver == "dummy" || driver == "evdev") {
        SDL_Quit();
        throw std::runtime_error("no display to open a window on (SDL's video driver is '" +
                                 driver + "'); set DISPLAY, or run under xvfb-run");
    }
    // Frames are copied to the window as they are: nearest texels when the
    // framebuffer is smaller than the window, no smoothing that would hide
    // the resolution scale.
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "0");
    window_ = SDL_CreateWindow(title, SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, width,
                               height, SDL_WINDOW_RESIZABLE);
    if (!window_) sdl_failed("SDL_CreateWindow");
    renderer_ = SDL_CreateRenderer(window_, -1, vsync ? SDL_RENDERER_PRESENTVSYNC : 0);
    if (!renderer_) sdl_failed("SDL_CreateRenderer");
    if (SDL_GetRendererOutputSize(renderer_, &width_, &height_) != 0)
        sdl_failed("SDL_GetRendererOutputSize");
}

SdlWindow::~SdlWindow() {
    if (texture_) SDL_DestroyTexture(texture_);
    if (renderer_) SDL_DestroyRenderer(renderer_);
    if (window_) SDL_DestroyWindow(window_);
    SDL_Quit();
}

void SdlWindow::send_keys(const std::string& keys) {
    for (char c : keys) {
        SDL_Event e{};
        e.type = SDL_KEYDOWN;
        e.key.state = SDL_PRESSED;
        e.key.windowID = SDL_GetWindowID(window_);
        e.key.keysym.sym = keycode_of(c);
        if (SDL_PushEvent(&e) < 0) sdl_failed("SDL_PushEvent");
    }
}

Input SdlWindow::poll() {
    Input input;
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
        switch (e.type) {
            case SDL_QUIT:
                input.quit = true;
                break;
            case SDL_KEYDOWN:
                if (e.key.keysym.sym == SDLK_ESCAPE || e.key.keysym.sym == SDLK_q)
                    input.quit = true;
                else if (const std::optional<Key> key = key_of(e.key.keysym.sym))
                    input.keys.push_back(*key);
                break;
            case SDL_MOUSEMOTION:
                if (e.motion.state & SDL_BUTTON_LMASK) {
                    input.drag_x += e.motion.xrel;
                    input.drag_y += e.motion.yrel;
                } else if (e.motion.state & SDL_BUTTON_RMASK) {
                    input.light_x += e.motion.xrel;
                    input.light_y += e.motion.yrel;
                }
                break;
            case SDL_MOUSEWHEEL:
                input.wheel += e.wheel.y;
                break;
            default:
                break;
        }
    }
    // The window may have been resized: the next frame is drawn at its size.
    if (SDL_GetRendererOutputSize(renderer_, &width_, &height_) != 0)
        sdl_failed("SDL_GetRendererOutputSize");
    return input;
}

void SdlWindow::draw(const rl::Image& frame) {
    if (!texture_ || frame.width() != texture_width_ || frame.height() != texture_height_) {
        if (texture_) SDL_DestroyTexture(texture_);
        // RGBA bytes in memory order: SDL's ABGR8888 on a little-endian machine.
        texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING,
                                     frame.width(), frame.height());
        if (!texture_) sdl_failed("SDL_CreateTexture");
        SDL_SetTextureBlendMode(texture_, SDL_BLENDMODE_NONE);
        texture_width_ = frame.width(), texture_height_ = frame.height();
    }
    if (SDL_UpdateTexture(texture_, nullptr, frame.pixels().data(), frame.width() * 4) != 0)
        sdl_failed("SDL_UpdateTexture");
    SDL_RenderClear(renderer_);
    // rasterlab's first row is the bottom one, the window's the top one.
    if (SDL_RenderCopyEx(renderer_, texture_, nullptr, nullptr, 0, nullptr, SDL_FLIP_VERTICAL) != 0)
        sdl_failed("SDL_RenderCopyEx");
}

void SdlWindow::show(const rl::Image& frame, const std::string* screenshot) {
    draw(frame);
    if (screenshot) {
        rl::Image shot(width_, height_);
        if (SDL_RenderReadPixels(renderer_, nullptr, SDL_PIXELFORMAT_RGBA32, shot.pixels().data(),
                                 width_ * 4) != 0)
            sdl_failed("SDL_RenderReadPixels");
        shot.flip_vertically();  // the window's top row first, to rasterlab's bottom row first
        rl::save_image(*screenshot, shot);
    }
    SDL_RenderPresent(renderer_);
}

rl::Rgba SdlWindow::shown_at(const rl::Image& frame, int x, int y_from_top) {
    draw(frame);
    rl::Rgba pixel{};
    const SDL_Rect one{x, y_from_top, 1, 1};
    if (SDL_RenderReadPixels(renderer_, &one, SDL_PIXELFORMAT_RGBA32, &pixel, 4) != 0)
        sdl_failed("SDL_RenderReadPixels");
    return pixel;
}

void SdlWindow::set_title(const char* title) {
    SDL_SetWindowTitle(window_, title);
}

}  // namespace viewer
