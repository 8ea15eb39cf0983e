// How the renderer's side-by-side image reaches the window: the eyes' places
// in the window (aspect kept, centred), a copy of the image into a texture,
// and one draw per eye (or one anaglyph draw).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "gl/handles.hpp"
#include "gl/state.hpp"
#include "preview/options.hpp"
#include "render/target.hpp"

namespace impossible::preview {

struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;  // GL window coordinates (origin bottom left)
};

// Where the eyes go in a framebuffer of fb_width × fb_height: the largest
// rectangles of the eye aspect that fit, centred. rects[0] shows the left
// eye; with Cross it is the right-hand one; with Anaglyph both are the same.
struct WindowLayout {
    std::array<PixelRect, 2> eye_rects;
};

WindowLayout window_layout(int fb_width, int fb_height, double eye_aspect, PreviewView view);

struct Presenter {
    gl::Program program;
    gl::VertexArray empty_vao;
    gl::Texture texture;  // a copy of the renderer's colour, side by side
    gl::Framebuffer framebuffer;
    int width = 0, height = 0;
    GLint u_eye = -1;
};

Result<Presenter> build_presenter();

// Clears the default framebuffer and draws the renderer's colour image into
// the eye rectangles, through the window context's state cache; leaves the
// default framebuffer bound with the whole window as the viewport.
void present(Presenter& presenter, gl::StateCache& state, const render::Target& target, const WindowLayout& layout,
             PreviewView view, int fb_width, int fb_height);

// The default framebuffer's back buffer as RGB rows from the top.
std::vector<std::uint8_t> read_window(gl::StateCache& state, int fb_width, int fb_height);

}  // namespace impossible::preview
