// The ray tracer's scene file (JSON). A colour is a number (grey) or [r, g, b].
//
//   {"camera":    {"eye": [x, y, z], "center": [x, y, z], "up": [x, y, z] (default [0, 1, 0]),
//                  "fov_y_deg": θ (default 45), "size": [width, height] (default [64, 48]),
//                  "aperture": lens radius (default 0, a pinhole), "focal_distance": d (default
//                  |center − eye|), "shutter": time span (default 0)},
//    "settings":  {"max_depth": n (default 3), "shadows", "reflections", "refractions": bool
//                  (default true), "model": "phong" | "blinn-phong" (default "phong"),
//                  "ray_casting": bool (true: no secondary rays at all, no shadows),
//                  "samples_per_pixel": n (default 1), "pattern": "regular" | "random" |
//                  "jittered" | "poisson" (default jittered), "filter": "box" | "tent" |
//                  "gaussian" (default box), "seed": integer (default 1)} (optional),
//    "background": colour (default 0), "ambient": colour I_a (default 0.1),
//    "materials": [{"name": "red", "ka", "kd", "ks": colours, "shininess": p,
//                   "kr": colour (mirror share, default 0), "kt": colour (refracted share,
//                   default 0), "ior": index (default 1), "gloss": Phong exponent of glossy
//                   reflection (default 0: a mirror), "gloss_samples": rays (default 1)}, …]
//                   (defaults 0.1, 0.7, 0.3, 20),
//    "lights":    [{"position": [x, y, z] | "direction": [x, y, z] (the way the light travels),
//                   "intensity": colour, "attenuation": [c1, c2, c3] (point lights),
//                   "area": {"shape": "rectangle", "u": [x, y, z], "v": [x, y, z]} |
//                           {"shape": "disc", "radius": r, "normal": [x, y, z]} (point lights),
//                   "samples": shadow rays over the area (default 1)}, …],
//    "objects":   [{"type": a quadric type (see rays_json.hpp) with its "params", "transform",
//                   "zmin", "zmax"} | {"type": "plane", "point": [x, y, z], "normal": [x, y, z]} |
//                  {"type": "triangle", "vertices": [[x, y, z] × 3], "normals" (3, optional)} |
//                  {"type": "mesh", "vertices": [[x, y, z], …], "triangles": [[i, j, k], …],
//                   "uv", "normals": one per vertex (optional)} |
//                  {"type": "mesh", "generate": {"shape": "sphere" | "terrain" | "patch", …}} |
//                  {"type": "mesh", "obj": "file.obj"} (rays/mesh_json.hpp; a mesh may have an
//                   affine "transform") |
//                  {"type": "csg", "tree": NODE (rays/csg_json.hpp: union, intersection and
//                   difference of quadric solids and boxes), one solid of one material},
//                  each with "material": a material's name, an optional "name" and an optional
//                  "velocity": [x, y, z] (motion blur over the camera's shutter time)],
//    "stepping":  {…} (the ray-tracer algorithm's; ignored by render-scene)}
//
// A mesh becomes one triangle object per entry of "triangles" (vertex indices, counter-
// clockwise seen from the front), smooth when it has vertex normals. Errors name the field:
// "objects[2].material: no material \"glas\" (materials: glass, red)".
#pragma once

#include "io/json.hpp"
#include "rays/rt_scene.hpp"

namespace cg::rt {

// Reads a scene object strictly (the fields above, their types and names; `allow` lists other
// top-level fields the caller reads itself, such as "stepping"). The values are checked by
// rt::validate, which a run calls at its start (RayTracer::start, render-scene).
Scene scene_from_json(const json& j, std::initializer_list<const char*> allow = {});
json scene_to_json(const Scene& s);

// FNV-1a (64-bit, hex) over the RGBA bytes of an image (row 0 at the bottom, as rt::Image),
// taken top row first: a fingerprint of exactly what its PNG holds.
std::string image_checksum(const std::vector<std::uint32_t>& rgba, int width, int height);

}  // namespace cg::rt
