// Pictures shared by texture-map and bump-map: a texture image as a pixel grid, the texels a
// lookup reads, a surface painted with a texture or lit with given normals, a point's frame.
#pragma once

#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "core/scene.hpp"
#include "rays/texture.hpp"
#include "rays/uv_map.hpp"

namespace cg::texdraw {

// The image as an image panel titled "<label>: W × H texels", one cell per texel (a large image
// every k-th texel, k returned: texel (i, j) is then at cell (i/k, j/k)).
Panel& add_image(const TextureImage& im, Scene& scene, const std::string& label, int& shown);
// A texel outlined in its panel, its label (a weight) inside it.
void outline_texel(glm::ivec2 texel, int shown, const std::string& label, Role role, Panel& panel);

// The (u, v) range drawn around a point: the whole surface for spheres and cut quadrics, one
// texture repeat each way for planes and uncut quadrics.
void uv_domain(const PreparedUv& p, const UvSurface& s, glm::dvec2 uv, glm::dvec2& lo,
               glm::dvec2& hi);

// The surface over its domain as faces coloured by `color(uv)` (a triangle: its own area),
// shifted by `offset`.
void add_surface(const PreparedUv& p, const UvSurface& s, glm::dvec2 lo, glm::dvec2 hi, int nu,
                 int nv, const std::function<glm::dvec3(glm::dvec2 uv, glm::dvec3 P)>& color,
                 glm::dvec3 offset, float alpha, Scene& scene);
// The surface painted with the texture (nearest lookups of level 0).
void add_textured_surface(const PreparedUv& p, const UvSurface& s, glm::dvec2 uv, const Texture& t,
                          const void* unused, Scene& scene);
// The point, and (with a frame) the u and v directions there, at least 30 px long.
void add_point_frame(const PreparedUv& p, glm::dvec3 P, const UvFrame* frame, Scene& scene);
// A size for arrows and offsets around the surface.
double surface_size(const PreparedUv& p, const UvSurface& s);

}  // namespace cg::texdraw
