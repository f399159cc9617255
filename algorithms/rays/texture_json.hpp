// JSON for textures, shared by texture-map, bump-map, solid-texture and the tracer's scene file.
// Read strictly (errors name the field), written back as given.
//
//   texture  {"image": "earth.png"            an image file (PNG, JPEG, BMP, … — what stb_image
//                                             reads), 8-bit channels as value/255, no gamma
//            | "grid": {"width": W, "height": H,
//                       "texels": H rows of W colours, the first row at v = 1 (the top, as an
//                                 image is stored); a colour is a number (grey) or [r, g, b]}
//            | "checker": {"size": n | [n_u, n_v] (default 8), "colors": [c0, c1]
//                          (default [0.1, 0.9])},      one texel per square
//             "filter": "nearest" | "bilinear" | "mipmap" (default "bilinear"),
//             "wrap": "repeat" | "clamp" (default "repeat")}
//   height   {"type": "sines" | "noise" | "image", "amplitude" (default 0.02),
//             "frequency": f | [f_u, f_v] (sines, noise; default 4), "seed" (noise),
//             "image" | "grid" | "checker" and "wrap" as a texture's (image; grey = mean of
//             r, g, b), "step": h of the finite differences (default 1e-4)}
//   solid    {"type": "checker" | "stripes" | "wood" | "marble", "colors": [c0, c1],
//             "size" (checker), "axis", "period" (stripes, wood, marble), "amplitude",
//             "frequency", "seed" (wood, marble), "octaves" (marble)}
//   surface  a quadric {"type": "sphere" | …, "params", "transform", "zmin", "zmax"},
//            {"type": "plane", "point", "normal", "u_axis" (optional), "uv_scale" (default 1)} or
//            {"type": "triangle", "vertices": [3 points], "uv": [3 (u, v)] (optional)}
//
// Image files: a relative path is taken relative to the folder of the input or scene file that
// names it (the CLI rebases every "image" path when it reads a file: rebase_image_paths), and
// relative to the working directory when the input comes from standard input or from inside
// the program. A missing or unreadable file is an error naming the field:
//   materials[0].texture.image: cannot read "earth.png": no such file
#pragma once

#include <string>

#include "io/json.hpp"
#include "rays/bump.hpp"
#include "rays/noise.hpp"
#include "rays/texture.hpp"
#include "rays/uv_map.hpp"

namespace cg::texture_json {

// `r` is the texture object; `extra` lists the other fields it may have.
Texture texture(const Reader& r, std::initializer_list<const char*> extra = {});
json texture_json(const Texture& t);
// The image part only ("image" | "grid" | "checker", and "wrap"): for height images.
void image_source(const Reader& r, Texture& t);
void image_source_json(const Texture& t, json& j);

HeightField height(const Reader& r);
json height_json(const HeightField& h);

SolidTexture solid(const Reader& r, std::initializer_list<const char*> extra = {});
json solid_json(const SolidTexture& t);

UvSurface surface(const Reader& r);
json surface_json(const UvSurface& s);

// Reads an image file into a texture image (row 0 at the bottom). Throws InputError(field, …).
TextureImage read_image_file(const std::string& path, const std::string& field);

}  // namespace cg::texture_json

namespace cg {
// Every string under a key "image" (or "obj", a mesh's file) that is a relative path becomes
// `dir`/path (`dir` empty or "." leaves them): what the CLI does to an input or scene read from
// a file in `dir`.
void rebase_image_paths(json& j, const std::string& dir);
// The folder part of a file path ("scenes/a.json" → "scenes", "a.json" → "").
std::string folder_of(const std::string& path);
}  // namespace cg
