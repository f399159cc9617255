// Big pixel grids — a ray-traced image, 640×480 cells — drawn as one OpenGL texture instead of
// a rectangle per run of cells: a frame of the image stays one quad for ImGui and the GPU,
// however many cells it has. Small grids (the course's 8×8 scan conversions) keep their
// rectangles, which a PNG of a lesson shows crisply at any zoom.
//
// A cache of textures, one per grid drawn in a frame, re-uploaded only when the grid's cells
// change. Needs the OpenGL context it was made in to be current, and must be destroyed before
// that context is.
#pragma once

#include <imgui.h>

#include <cstdint>
#include <vector>

#include "core/scene.hpp"
#include "viewer/gl.hpp"

namespace cg::viewer {

class GridTextures {
  public:
    static constexpr std::size_t kMinCells = 4096;  // from this many cells, a texture

    explicit GridTextures(const Gl& gl) : gl_(gl) {}
    ~GridTextures();
    GridTextures(const GridTextures&) = delete;
    GridTextures& operator=(const GridTextures&) = delete;

    // The texture of grid number `slot` of the scene (0, 1, …): its cells as RGBA texels, top
    // row first (a grid's row 0 is its bottom), kRoleColour cells in `role` (ImGui's ABGR).
    ImTextureID texture(std::size_t slot, const PixelGrid2& grid, ImU32 role);

  private:
    struct Entry {
        GLuint id = 0;
        int width = 0, height = 0;
        std::uint64_t hash = 0;  // of the cells and the role colour it was made from
    };
    const Gl& gl_;
    std::vector<Entry> entries_;
    std::vector<std::uint32_t> texels_;  // the upload's staging rows
};

}  // namespace cg::viewer
