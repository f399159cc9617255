#include "viewer/gl.hpp"

#include <SDL.h>
#include <stb_image_write.h>  // the implementation is in libstb

#include <algorithm>
#include <stdexcept>

namespace cg::viewer {

namespace {

template <class F>
void lookup(F& f, const char* name) {
    f = reinterpret_cast<F>(SDL_GL_GetProcAddress(name));
    if (!f) throw std::runtime_error(std::string("OpenGL function ") + name + " is not available");
}

}  // namespace

Gl Gl::load() {
    Gl gl;
    lookup(gl.Viewport, "glViewport");
    lookup(gl.ClearColor, "glClearColor");
    lookup(gl.Clear, "glClear");
    lookup(gl.ReadBuffer, "glReadBuffer");
    lookup(gl.ReadPixels, "glReadPixels");
    lookup(gl.PixelStorei, "glPixelStorei");
    lookup(gl.Finish, "glFinish");
    lookup(gl.Scissor, "glScissor");
    lookup(gl.Enable, "glEnable");
    lookup(gl.Disable, "glDisable");
    lookup(gl.GenTextures, "glGenTextures");
    lookup(gl.DeleteTextures, "glDeleteTextures");
    lookup(gl.BindTexture, "glBindTexture");
    lookup(gl.TexParameteri, "glTexParameteri");
    lookup(gl.TexImage2D, "glTexImage2D");
    lookup(gl.GenFramebuffers, "glGenFramebuffers");
    lookup(gl.DeleteFramebuffers, "glDeleteFramebuffers");
    lookup(gl.BindFramebuffer, "glBindFramebuffer");
    lookup(gl.GenRenderbuffers, "glGenRenderbuffers");
    lookup(gl.DeleteRenderbuffers, "glDeleteRenderbuffers");
    lookup(gl.BindRenderbuffer, "glBindRenderbuffer");
    lookup(gl.RenderbufferStorage, "glRenderbufferStorage");
    lookup(gl.FramebufferRenderbuffer, "glFramebufferRenderbuffer");
    lookup(gl.CheckFramebufferStatus, "glCheckFramebufferStatus");
    return gl;
}

void Gl::clear(int width, int height, std::uint32_t rgba) const {
    auto channel = [&](int shift) { return static_cast<float>((rgba >> shift) & 0xffu) / 255.0f; };
    Viewport(0, 0, width, height);
    ClearColor(channel(24), channel(16), channel(8), channel(0));
    Clear(GL_COLOR_BUFFER_BIT);
}

void Gl::clear_rect(int x, int y, int w, int h, int height, std::uint32_t rgba) const {
    if (w <= 0 || h <= 0) return;
    auto channel = [&](int shift) { return static_cast<float>((rgba >> shift) & 0xffu) / 255.0f; };
    Enable(GL_SCISSOR_TEST);
    Scissor(x, height - y - h, w, h);  // GL counts rows from the bottom
    ClearColor(channel(24), channel(16), channel(8), channel(0));
    Clear(GL_COLOR_BUFFER_BIT);
    Disable(GL_SCISSOR_TEST);
}

OffscreenTarget::OffscreenTarget(const Gl& gl, int width, int height) : gl_(gl) {
    gl_.GenFramebuffers(1, &framebuffer_);
    gl_.GenRenderbuffers(1, &colour_);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, colour_);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    bind();
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        release();
        throw std::runtime_error("cannot create an offscreen image of " + std::to_string(width) +
                                 "x" + std::to_string(height) + " pixels");
    }
}

OffscreenTarget::~OffscreenTarget() {
    release();
}

void OffscreenTarget::release() {
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (colour_) gl_.DeleteRenderbuffers(1, &colour_);
    if (framebuffer_) gl_.DeleteFramebuffers(1, &framebuffer_);
    colour_ = framebuffer_ = 0;
}

void OffscreenTarget::bind() const {
    gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
}

std::vector<std::uint8_t> read_pixels(const Gl& gl, int width, int height) {
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    std::vector<std::uint8_t> pixels(row * static_cast<std::size_t>(height));
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    for (int y = 0; y < height / 2; ++y) {
        auto top = pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y));
        auto bottom = pixels.begin() +
                      static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height - 1 - y));
        std::swap_ranges(top, top + static_cast<std::ptrdiff_t>(row), bottom);
    }
    // The window's alpha is whatever blending left there; a PNG of the screen is opaque.
    for (std::size_t i = 3; i < pixels.size(); i += 4) pixels[i] = 255;
    return pixels;
}

void write_png(const std::string& path, int width, int height,
               const std::vector<std::uint8_t>& rgba) {
    if (!stbi_write_png(path.c_str(), width, height, 4, rgba.data(), width * 4))
        throw std::runtime_error("cannot write PNG file " + path);
}

}  // namespace cg::viewer
