#include "render/target.hpp"

#include <cstdio>
#include <cstring>
#include <string>

namespace impossible::render {

namespace {

enum class TargetKind { Renderbuffers, Sampled, Multisampled };

// Colour and ids of a target of the given kind, attached to its framebuffer.
void attach_colour_and_ids(Target& t, TargetKind kind) {
    const GLuint fb = t.framebuffer.get();
    const int width = t.width, height = t.height;
    if (kind == TargetKind::Sampled) {
        t.color_texture = gl::create_texture(GL_TEXTURE_2D);
        t.ids_texture = gl::create_texture(GL_TEXTURE_2D);
        glTextureStorage2D(t.color_texture.get(), 1, GL_RGBA8, width, height);
        glTextureStorage2D(t.ids_texture.get(), 1, GL_R8UI, width, height);
        for (GLuint tex : {t.color_texture.get(), t.ids_texture.get()}) {
            const GLint filter = tex == t.color_texture.get() ? GL_LINEAR : GL_NEAREST;
            glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, filter);
            glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, filter);
            glTextureParameteri(tex, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        }
        glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT0, t.color_texture.get(), 0);
        glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT1, t.ids_texture.get(), 0);
    } else if (kind == TargetKind::Multisampled) {
        t.color = gl::create_renderbuffer();
        t.ids_texture = gl::create_texture(GL_TEXTURE_2D_MULTISAMPLE);
        glNamedRenderbufferStorageMultisample(t.color.get(), t.samples, GL_RGBA8, width, height);
        // Fixed sample locations: required when textures and renderbuffers share a framebuffer.
        glTextureStorage2DMultisample(t.ids_texture.get(), t.samples, GL_R8UI, width, height, GL_TRUE);
        glNamedFramebufferRenderbuffer(fb, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.color.get());
        glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT1, t.ids_texture.get(), 0);
    } else {
        t.color = gl::create_renderbuffer();
        t.ids = gl::create_renderbuffer();
        glNamedRenderbufferStorage(t.color.get(), GL_RGBA8, width, height);
        glNamedRenderbufferStorage(t.ids.get(), GL_R8UI, width, height);
        glNamedFramebufferRenderbuffer(fb, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.color.get());
        glNamedFramebufferRenderbuffer(fb, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, t.ids.get());
    }
}

Result<Target> make_target(int width, int height, DepthMode depth, TargetKind kind, int samples) {
    Target t;
    t.width = width;
    t.height = height;
    t.depth = depth;
    t.samples = kind == TargetKind::Multisampled ? samples : 1;
    t.depth_stencil = gl::create_renderbuffer();
    t.framebuffer = gl::create_framebuffer();
    const GLuint fb = t.framebuffer.get();
    attach_colour_and_ids(t, kind);
    const GLenum depth_format = depth == DepthMode::ReversedZ ? GL_DEPTH32F_STENCIL8 : GL_DEPTH24_STENCIL8;
    if (kind == TargetKind::Multisampled)
        glNamedRenderbufferStorageMultisample(t.depth_stencil.get(), t.samples, depth_format, width, height);
    else
        glNamedRenderbufferStorage(t.depth_stencil.get(), depth_format, width, height);
    glNamedFramebufferRenderbuffer(fb, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, t.depth_stencil.get());
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fb, 2, buffers);
    const GLenum status = glCheckNamedFramebufferStatus(fb, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char buf[16];
        std::snprintf(buf, sizeof buf, "%04x", status);
        return Error{"render target " + std::to_string(width) + "x" + std::to_string(height) +
                     " is incomplete (status 0x" + buf + ")"};
    }
    return t;
}

}  // namespace

Result<Target> create_target(int width, int height, DepthMode depth) {
    return make_target(width, height, depth, TargetKind::Renderbuffers, 1);
}

Result<Target> create_sampled_target(int width, int height, DepthMode depth) {
    return make_target(width, height, depth, TargetKind::Sampled, 1);
}

Result<Target> create_multisampled_target(int width, int height, DepthMode depth, int samples) {
    return make_target(width, height, depth, TargetKind::Multisampled, samples);
}

namespace {

// glReadPixels of the bound read framebuffer (the target's), rows from the top.
image::Image read_bound(const Target& t) {
    image::Image image;
    image.width = t.width;
    image.height = t.height;
    const size_t w = static_cast<size_t>(t.width), h = static_cast<size_t>(t.height);
    std::vector<std::uint8_t> rgba(w * h * 4);
    std::vector<std::uint8_t> ids(w * h);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glNamedFramebufferReadBuffer(t.framebuffer.get(), GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glNamedFramebufferReadBuffer(t.framebuffer.get(), GL_COLOR_ATTACHMENT1);
    glReadPixels(0, 0, t.width, t.height, GL_RED_INTEGER, GL_UNSIGNED_BYTE, ids.data());

    // GL rows start at the bottom; images start at the top.
    image.rgb.resize(w * h * 3);
    image.ids.resize(w * h);
    for (size_t y = 0; y < h; ++y) {
        const size_t src = (h - 1 - y) * w;
        std::memcpy(&image.ids[y * w], &ids[src], w);
        for (size_t x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) image.rgb[(y * w + x) * 3 + c] = rgba[(src + x) * 4 + c];
    }
    return image;
}

}  // namespace

image::Image read_target(gl::StateCache& state, const Target& t) {
    state.read_framebuffer(t.framebuffer.get());
    return read_bound(t);
}

}  // namespace impossible::render
