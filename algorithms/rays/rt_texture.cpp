// Sections: [the objects' parametrisations] [validate and prepare] [the surface at a hit]
#include "rays/rt_texture.hpp"

#include <cmath>
#include <glm/geometric.hpp>

#include "core/step.hpp"
#include "rays/rt_scene.hpp"

namespace cg::rt {

using glm::dvec2;
using glm::dvec3;

// ---- [the objects' parametrisations] --------------------------------------------------------

UvSurface uv_surface(const Object& o) {
    UvSurface u;
    switch (o.kind) {
        case ObjectKind::Quadric:
            u.kind = UvKind::Quadric;
            u.quadric = o.quadric;
            break;
        case ObjectKind::Plane:
            u.kind = UvKind::Plane;
            u.origin = o.p0;
            u.normal = o.normal;
            u.u_axis = o.uv.has_u_axis ? o.uv.u_axis : default_u_axis(o.normal);
            u.scale = o.uv.scale;
            break;
        case ObjectKind::Triangle:
            u.kind = UvKind::Triangle;
            u.p = {o.p0, o.p1, o.p2};
            u.uv = o.uv.uv;
            break;
        case ObjectKind::Csg:
            break;  // no parametrisation: image textures and bumps are refused on CSG objects
        case ObjectKind::Mesh:
            break;  // one per triangle (mesh_uv_surface), made at the hit
    }
    return u;
}

namespace {

// A mesh triangle's parametrisation, as a triangle object with its corners and (u, v) has.
UvSurface mesh_uv_surface(const TriangleMesh& tm, std::size_t k) {
    UvSurface u;
    u.kind = UvKind::Triangle;
    const auto& t = tm.mesh.triangles[k];
    u.p = {tm.mesh.vertices[t[0]], tm.mesh.vertices[t[1]], tm.mesh.vertices[t[2]]};
    if (!tm.mesh.uv.empty()) u.uv = {tm.mesh.uv[t[0]], tm.mesh.uv[t[1]], tm.mesh.uv[t[2]]};
    return u;
}

}  // namespace

// ---- [validate and prepare] -----------------------------------------------------------------

void validate_textures(const Scene& s) {
    long long texels = 0;
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        const MaterialTextures& t = s.materials[i].tex;
        const std::string f = "materials[" + std::to_string(i) + "]";
        if (t.has_texture) {
            validate_texture(t.texture, f + ".texture");
            texels += static_cast<long long>(t.texture.image.texels.size());
        }
        if (t.has_solid) {
            if (t.has_texture)
                throw InputError(f + ".solid_texture",
                                 "cannot be combined with \"texture\": both would colour the "
                                 "surface (choose one)");
            validate_solid(t.solid, f + ".solid_texture");
        }
        if (t.has_bump) {
            validate_height(t.bump, f + ".bump");
            if (t.bump.kind == HeightKind::Image)
                texels += static_cast<long long>(t.bump.image.image.texels.size());
        }
    }
    if (texels > kMaxSceneTexels)
        throw InputError("materials", "have textures of " + std::to_string(texels) +
                                          " texels in all; the limit is " +
                                          std::to_string(kMaxSceneTexels));
    // A parametrisation matters (and must be sound) where a texture or a bump is applied.
    for (const Object& o : s.objects) {
        const MaterialTextures& t = s.materials[o.material].tex;
        if (o.kind == ObjectKind::Csg && (t.has_texture || t.has_bump))
            throw InputError(o.field + ".material",
                             "material \"" + s.materials[o.material].name + "\" has " +
                                 (t.has_texture ? "an image texture" : "a bump map") +
                                 ", which needs (u, v) on the surface; a CSG object has none "
                                 "(its surface is pieced from its leaves): use a solid_texture, "
                                 "or a material without texture and bump");
        if (o.kind == ObjectKind::Quadric || !(t.has_texture || t.has_bump)) continue;
        if (o.kind == ObjectKind::Mesh) {
            for (std::size_t k = 0; k < o.mesh->mesh.triangles.size(); ++k)
                validate_uv_surface(mesh_uv_surface(*o.mesh, k),
                                    o.field + ".triangles[" +
                                        std::to_string(o.mesh->source_index(k)) + "]");
            continue;
        }
        std::string f = o.field;  // a triangle's field is "objects[2].vertices"
        const std::string tail = ".vertices";
        if (f.size() > tail.size() && f.compare(f.size() - tail.size(), tail.size(), tail) == 0)
            f.resize(f.size() - tail.size());
        validate_uv_surface(uv_surface(o), f);
    }
}

PreparedTextures prepare_textures(const Scene& s) {
    PreparedTextures p;
    bool any = false;
    for (const Material& m : s.materials) any = any || m.tex.any();
    if (!any) return p;  // an untextured scene prepares nothing
    p.surfaces.reserve(s.objects.size());
    for (const Object& o : s.objects) p.surfaces.push_back(prepare_uv(uv_surface(o)));
    p.mipmaps.resize(s.materials.size());
    p.solid_noise.resize(s.materials.size());
    p.bump_noise.resize(s.materials.size());
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        const MaterialTextures& t = s.materials[i].tex;
        if (t.has_texture && t.texture.filter == TexFilter::Mipmap)
            p.mipmaps[i] = build_mipmap(t.texture.image);
        if (t.has_solid && uses_noise(t.solid.kind)) p.solid_noise[i] = make_perlin(t.solid.seed);
        if (t.has_bump && t.bump.kind == HeightKind::Noise)
            p.bump_noise[i] = make_perlin(t.bump.seed);
    }
    return p;
}

// ---- [the surface at a hit] -----------------------------------------------------------------

RayDifferential pixel_differential(const View& v, int i, int j) {
    return {screen_point(v, i + 1.5, j + 0.5) - v.eye, screen_point(v, i + 0.5, j + 1.5) - v.eye};
}

namespace {

// The (u, v) step to where a neighbouring ray meets the hit's tangent plane.
double uv_step(const PreparedUv& uv, const UvFrame& f, dvec3 P, dvec3 n, dvec3 origin, dvec3 dir) {
    const double dn = glm::dot(dir, n);
    const double t = glm::dot(P - origin, n) / dn;
    if (!(std::fabs(dn) > 1e-12 * glm::length(dir)) || !(t > 0) || !std::isfinite(t))
        return 1e9;  // grazing: the footprint covers the whole texture
    dvec2 step = uv_frame(uv, origin + t * dir).uv - f.uv;
    if (uv.kind == UvKind::Quadric) step.x -= std::round(step.x);  // across the seam
    return glm::length(step);
}

}  // namespace

Surface surface_at(const Scene& s, const Prepared& p, const Hit& h, dvec3 origin, dvec3 d,
                   const RayDifferential* diff, SurfaceDetail* detail) {
    const PreparedObject& obj = p.objects[h.object];
    const Material& m = s.materials[obj.material];
    Surface sf{m.ka, m.kd, h.normal};
    const MaterialTextures& t = m.tex;
    if (!t.any()) return sf;
    (void)d;
    PreparedUv triangle_uv;  // a mesh's: its hit triangle's, made here
    if (obj.kind == ObjectKind::Mesh)
        triangle_uv = prepare_uv(mesh_uv_surface(*obj.mesh, static_cast<std::size_t>(h.triangle)));
    const PreparedUv& uv =
        obj.kind == ObjectKind::Mesh ? triangle_uv : p.textures.surfaces[h.object];
    const bool needs_frame = t.has_texture || t.has_bump;
    UvFrame frame;
    if (needs_frame) frame = uv_frame(uv, h.point);
    if (t.has_texture) {
        double footprint = 0;
        if (t.texture.filter == TexFilter::Mipmap && diff)
            footprint = std::max(uv_step(uv, frame, h.point, h.normal, origin, diff->dx),
                                 uv_step(uv, frame, h.point, h.normal, origin, diff->dy));
        const MipMap* mip =
            t.texture.filter == TexFilter::Mipmap ? &p.textures.mipmaps[obj.material] : nullptr;
        const TextureLookup look = lookup(t.texture, mip, frame.uv, footprint);
        sf.ka = m.ka * look.color;
        sf.kd = m.kd * look.color;
        if (detail) {
            detail->textured = true;
            detail->footprint = footprint;
            detail->lookup = look;
        }
    }
    if (t.has_solid) {
        const dvec3 q = obj.kind == ObjectKind::Quadric && obj.quadric.transformed
                            ? obj.quadric.linear_inv * (h.point - obj.quadric.translation)
                            : h.point;
        const SolidSample ss = solid_sample(t.solid, p.textures.solid_noise[obj.material], q);
        sf.ka = m.ka * ss.color;
        sf.kd = m.kd * ss.color;
        if (detail) {
            detail->solid = true;
            detail->solid_point = q;
            detail->solid_sample = ss;
        }
    }
    if (t.has_bump) {
        const dvec3 outward = h.entering ? h.normal : -h.normal;
        const BumpResult b =
            blinn_bump(frame, outward, t.bump, p.textures.bump_noise[obj.material]);
        sf.normal = h.entering ? b.perturbed : -b.perturbed;
        if (detail) {
            detail->bumped = true;
            detail->bump = b;
        }
    }
    if (detail) detail->frame = frame;
    return sf;
}

}  // namespace cg::rt
