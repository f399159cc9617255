// The few OpenGL calls the viewer makes itself: clearing, reading pixels back for PNGs, and
// an offscreen framebuffer for `cgsandbox render`. Dear ImGui's OpenGL backend loads its own
// functions; ours are looked up through SDL_GL_GetProcAddress too, so the executable needs no
// link-time dependency on libGL.
#pragma once

#include <SDL_opengl.h>

#include <cstdint>
#include <string>
#include <vector>

namespace cg::viewer {

// Function pointers of the current GL context. decltype of the declarations in SDL_opengl.h
// gives the exact calling convention without ever linking those symbols.
struct Gl {
    decltype(&::glViewport) Viewport = nullptr;
    decltype(&::glClearColor) ClearColor = nullptr;
    decltype(&::glClear) Clear = nullptr;
    decltype(&::glReadBuffer) ReadBuffer = nullptr;
    decltype(&::glReadPixels) ReadPixels = nullptr;
    decltype(&::glPixelStorei) PixelStorei = nullptr;
    decltype(&::glFinish) Finish = nullptr;
    decltype(&::glScissor) Scissor = nullptr;
    decltype(&::glEnable) Enable = nullptr;
    decltype(&::glDisable) Disable = nullptr;
    decltype(&::glGenTextures) GenTextures = nullptr;
    decltype(&::glDeleteTextures) DeleteTextures = nullptr;
    decltype(&::glBindTexture) BindTexture = nullptr;
    decltype(&::glTexParameteri) TexParameteri = nullptr;
    decltype(&::glTexImage2D) TexImage2D = nullptr;
    PFNGLGENFRAMEBUFFERSPROC GenFramebuffers = nullptr;
    PFNGLDELETEFRAMEBUFFERSPROC DeleteFramebuffers = nullptr;
    PFNGLBINDFRAMEBUFFERPROC BindFramebuffer = nullptr;
    PFNGLGENRENDERBUFFERSPROC GenRenderbuffers = nullptr;
    PFNGLDELETERENDERBUFFERSPROC DeleteRenderbuffers = nullptr;
    PFNGLBINDRENDERBUFFERPROC BindRenderbuffer = nullptr;
    PFNGLRENDERBUFFERSTORAGEPROC RenderbufferStorage = nullptr;
    PFNGLFRAMEBUFFERRENDERBUFFERPROC FramebufferRenderbuffer = nullptr;
    PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus = nullptr;

    // Looks everything up in the current context; throws std::runtime_error if any is missing.
    static Gl load();

    // Clears the bound framebuffer's w x h pixels to an 0xRRGGBBAA colour.
    void clear(int width, int height, std::uint32_t rgba) const;
    // Clears the rectangle [x, x + w) × [y, y + h) of a framebuffer `height` tall, in pixels
    // from its top-left corner.
    void clear_rect(int x, int y, int w, int h, int height, std::uint32_t rgba) const;
};

// An RGBA8 colour buffer to draw into instead of a window, so `render` produces exactly the
// requested size whatever the screen (Xvfb's is often smaller than the picture).
class OffscreenTarget {
  public:
    OffscreenTarget(const Gl& gl, int width, int height);  // throws std::runtime_error
    ~OffscreenTarget();
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;

    void bind() const;  // draw and read from here from now on

  private:
    void release();

    const Gl& gl_;
    GLuint framebuffer_ = 0, colour_ = 0;
};

// Reads the current read buffer's w x h pixels as RGBA rows, top row first (GL's are bottom
// first, PNG's top first).
std::vector<std::uint8_t> read_pixels(const Gl& gl, int width, int height);

// Writes RGBA rows, top first, as a PNG; throws std::runtime_error naming the path.
void write_png(const std::string& path, int width, int height,
               const std::vector<std::uint8_t>& rgba);

}  // namespace cg::viewer
