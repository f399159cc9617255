// Textures in the ray tracer: what a material and an object add to the scene, and the surface a
// hit sees once its material's textures are applied (shared by the plain tracer and the
// stepped ray tree, so both shade with the same numbers).
//
// A material may have
//   "texture"        a colour texture (rays/texture.hpp) on the object's parametrisation
//                    (rays/uv_map.hpp): the colour T it returns multiplies k_a and k_d;
//   "solid_texture"  a solid texture (rays/noise.hpp) evaluated at the hit point — in the
//                    quadric's model space, so it moves with the object; planes and triangles
//                    in world space —: its colour multiplies k_a and k_d (not with "texture");
//   "bump"           a height field (rays/bump.hpp): Blinn's perturbed normal replaces the
//                    normal in the lighting (diffuse and specular). Shadow, mirror and
//                    refracted rays keep the geometric normal, so the silhouette, the shadows
//                    and the reflections stay smooth: bumps are a lighting effect.
// An object adds its parametrisation: a plane's "u_axis" and "uv_scale", a triangle's or a
// mesh's per-vertex "uv"; quadrics have theirs.
//
// Mipmapped textures need the pixel's footprint: a primary ray carries the rays through the
// neighbouring pixel centres (i + 1, j) and (i, j + 1) (a ray differential); at the hit they are
// intersected with the tangent plane, mapped to (u, v), and the footprint is the longer of the
// two (u, v) steps (across the u seam of a quadric the shorter way round). Secondary rays carry
// no differential and read the finest level.
#pragma once

#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "rays/bump.hpp"
#include "rays/noise.hpp"
#include "rays/texture.hpp"
#include "rays/uv_map.hpp"

namespace cg::rt {

using Color = glm::dvec3;

struct MaterialTextures {
    bool has_texture = false;
    Texture texture;
    bool has_solid = false;
    SolidTexture solid;
    bool has_bump = false;
    HeightField bump;
    bool any() const { return has_texture || has_solid || has_bump; }
    bool operator==(const MaterialTextures&) const = default;
};

struct ObjectUv {
    bool has_u_axis = false;  // a plane's u axis (default: default_u_axis(normal))
    glm::dvec3 u_axis{1, 0, 0};
    double scale = 1;     // a plane's uv_scale
    bool has_uv = false;  // a triangle's corner (u, v) (default (0,0), (1,0), (0,1))
    std::array<glm::dvec2, 3> uv{glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0, 1)};
    bool operator==(const ObjectUv&) const = default;
};

// Computed once per scene: each object's parametrisation, each mipmapped material's pyramid
// and each noisy material's permutation.
struct PreparedTextures {
    std::vector<PreparedUv> surfaces;  // per object
    std::vector<MipMap> mipmaps;       // per material (empty unless its filter is mipmap)
    std::vector<Perlin> solid_noise;   // per material
    std::vector<Perlin> bump_noise;    // per material
    bool operator==(const PreparedTextures&) const = default;
};

// The rays through the pixel's right and upper neighbours' centres (same origin as the
// primary ray), for the texture footprint.
struct RayDifferential {
    glm::dvec3 dx{0.0}, dy{0.0};
};

// What the lighting uses at a hit.
struct Surface {
    Color ka{0.0}, kd{0.0};
    glm::dvec3 normal{0.0};  // the shading normal, facing the ray
    bool operator==(const Surface&) const = default;
};

// Everything the texture steps show.
struct SurfaceDetail {
    UvFrame frame;
    double footprint = 0;
    bool textured = false;
    TextureLookup lookup;
    bool solid = false;
    glm::dvec3 solid_point{0.0};
    SolidSample solid_sample;
    bool bumped = false;
    BumpResult bump;
    bool operator==(const SurfaceDetail&) const = default;
};

struct Scene;
struct Prepared;
struct Hit;
struct Object;
struct View;

UvSurface uv_surface(const Object& o);
// Throws InputError naming the field ("materials[1].texture.filter", "objects[0].u_axis"), and
// refuses scenes whose textures hold more than kMaxSceneTexels texels in all.
void validate_textures(const Scene& s);
constexpr long long kMaxSceneTexels = 8LL * 1024 * 1024;
PreparedTextures prepare_textures(const Scene& s);

RayDifferential pixel_differential(const View& v, int i, int j);
// The hit's surface: k_a, k_d and the normal, textured and bumped as its material says (the
// material's own when it has no textures). `diff` is the primary ray's differential (or null).
Surface surface_at(const Scene& s, const Prepared& p, const Hit& h, glm::dvec3 origin, glm::dvec3 d,
                   const RayDifferential* diff, SurfaceDetail* detail = nullptr);

}  // namespace cg::rt
