#include "viewer/grid_texture.hpp"

namespace cg::viewer {

namespace {

// FNV-1a over the cells, 32 bits at a time: a changed cell changes the texture.
std::uint64_t cells_hash(const PixelGrid2& g, ImU32 role) {
    std::uint64_t h = 1469598103934665603ull ^ (std::uint64_t(g.width) << 32 | std::uint32_t(g.height));
    h = (h ^ role) * 1099511628211ull;
    for (const std::uint32_t v : g.rgba) h = (h ^ v) * 1099511628211ull;
    return h;
}

// 0xRRGGBBAA as the bytes R, G, B, A in memory (what GL_RGBA / GL_UNSIGNED_BYTE reads).
std::uint32_t texel(std::uint32_t rgba) {
    return (rgba >> 24 & 0xffu) | (rgba >> 8 & 0xff00u) | (rgba << 8 & 0xff0000u) |
           (rgba << 24 & 0xff000000u);
}

}  // namespace

GridTextures::~GridTextures() {
    for (const Entry& e : entries_)
        if (e.id) gl_.DeleteTextures(1, &e.id);
}

ImTextureID GridTextures::texture(std::size_t slot, const PixelGrid2& g, ImU32 role) {
    if (entries_.size() <= slot) entries_.resize(slot + 1);
    Entry& e = entries_[slot];
    const std::uint64_t hash = cells_hash(g, role);
    if (e.id && e.hash == hash && e.width == g.width && e.height == g.height)
        return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(e.id));

    // ImGui's colour is ABGR in a 32-bit word, i.e. the bytes R, G, B, A in memory already.
    texels_.resize(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height));
    for (int row = 0; row < g.height; ++row) {
        const std::size_t from = static_cast<std::size_t>(g.height - 1 - row) * g.width;
        const std::size_t to = static_cast<std::size_t>(row) * g.width;
        for (int i = 0; i < g.width; ++i) {
            const std::uint32_t v = g.rgba[from + i];
            texels_[to + i] = v == PixelGrid2::kRoleColour ? role : texel(v);
        }
    }
    if (!e.id) gl_.GenTextures(1, &e.id);
    gl_.BindTexture(GL_TEXTURE_2D, e.id);
    // Cells stay sharp squares when zoomed in; zoomed out, the nearest cell.
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, g.width, g.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   texels_.data());
    e.width = g.width;
    e.height = g.height;
    e.hash = hash;
    return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(e.id));
}

}  // namespace cg::viewer
