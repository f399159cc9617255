#include "rays/mesh_json.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/format.hpp"
#include "sampling/pattern_json.hpp"

namespace cg::mesh_json {

namespace {

struct MeshGenerateSpec {
    enum class Shape { Sphere, Terrain, Patch } shape = Shape::Sphere;
    mesh::SphereParams sphere;
    mesh::TerrainParams terrain;
    mesh::PatchParams patch;
};

int mesh_count_field(const Reader& r, const char* key, int fallback) {
    if (!r.has(key)) return fallback;
    const long long n = r.integer(key);
    if (n < -1000000000LL || n > 1000000000LL)
        throw InputError(r.field(key), "is far too large (got " + std::to_string(n) + ")");
    return static_cast<int>(n);
}

MeshGenerateSpec mesh_generate_spec(const Reader& g) {
    MeshGenerateSpec m;
    const std::string shape = g.string("shape");
    if (shape == "sphere") {
        g.only({"shape", "center", "radius", "segments"});
        m.shape = MeshGenerateSpec::Shape::Sphere;
        if (g.has("center")) m.sphere.center = g.point3("center");
        if (g.has("radius")) m.sphere.radius = g.number("radius");
        m.sphere.segments = mesh_count_field(g, "segments", m.sphere.segments);
        mesh::validate(m.sphere, g.path());
    } else if (shape == "terrain") {
        g.only({"shape", "center", "size", "resolution", "height", "roughness", "seed"});
        m.shape = MeshGenerateSpec::Shape::Terrain;
        if (g.has("center")) m.terrain.center = g.point3("center");
        if (g.has("size")) m.terrain.size = g.point2("size");
        m.terrain.resolution = mesh_count_field(g, "resolution", m.terrain.resolution);
        if (g.has("height")) m.terrain.height = g.number("height");
        if (g.has("roughness")) m.terrain.roughness = g.number("roughness");
        if (g.has("seed")) m.terrain.seed = sampling_json::seed(g, "seed");
        mesh::validate(m.terrain, g.path());
    } else if (shape == "patch") {
        g.only({"shape", "control_points", "segments"});
        m.shape = MeshGenerateSpec::Shape::Patch;
        const json& rows = g.get("control_points");
        const std::string f = g.field("control_points");
        if (!rows.is_array() || rows.size() != 4)
            throw InputError(
                f, "must be 4 rows of 4 control points (a bicubic patch), got " + describe(rows));
        for (std::size_t i = 0; i < 4; ++i) {
            const json& row = rows[i];
            const std::string rf = element(f, i);
            if (!row.is_array() || row.size() != 4)
                throw InputError(rf, "must be a row of 4 points [x, y, z], got " + describe(row));
            for (std::size_t j = 0; j < 4; ++j)
                m.patch.control_points[i][j] = as_point3(row[j], element(rf, j));
        }
        m.patch.segments = mesh_count_field(g, "segments", m.patch.segments);
        mesh::validate(m.patch, g.path());
    } else {
        throw InputError(g.field("shape"),
                         "must be \"sphere\", \"terrain\" or \"patch\" (got \"" + shape + "\")");
    }
    return m;
}

}  // namespace

std::size_t generate_count(const Reader& g) {
    const MeshGenerateSpec m = mesh_generate_spec(g);
    switch (m.shape) {
        case MeshGenerateSpec::Shape::Sphere:
            return mesh::sphere_triangles(m.sphere.segments);
        case MeshGenerateSpec::Shape::Terrain:
            return mesh::terrain_triangles(m.terrain.resolution);
        case MeshGenerateSpec::Shape::Patch:
            return mesh::patch_triangles(m.patch.segments);
    }
    return 0;
}

mesh::Mesh generate(const Reader& g) {
    const MeshGenerateSpec m = mesh_generate_spec(g);
    switch (m.shape) {
        case MeshGenerateSpec::Shape::Sphere:
            return mesh::sphere(m.sphere);
        case MeshGenerateSpec::Shape::Terrain:
            return mesh::terrain(m.terrain);
        case MeshGenerateSpec::Shape::Patch:
            return mesh::patch(m.patch);
    }
    return {};
}

// ---- OBJ files -------------------------------------------------------------------------------

namespace {

constexpr std::uintmax_t kMaxObjBytes = 512ull << 20;

struct MeshObjError {
    std::size_t line;
    std::string reason;
};

// A decimal number as OBJ writes them (and tinyobjloader reads them): [+-] digits [. digits]
// [e [+-] digits], or starting with the point. No hexadecimal, "inf" or "nan".
bool mesh_obj_decimal(const std::string& t) {
    std::size_t i = 0, digits = 0;
    auto is_digit = [&](std::size_t k) { return k < t.size() && t[k] >= '0' && t[k] <= '9'; };
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    while (is_digit(i)) ++i, ++digits;
    if (i < t.size() && t[i] == '.') {
        ++i;
        while (is_digit(i)) ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        ++i;
        if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
        if (!is_digit(i)) return false;
        while (is_digit(i)) ++i;
    }
    return i == t.size();
}

double mesh_obj_number(const std::string& tok, std::size_t line) {
    if (!mesh_obj_decimal(tok)) throw MeshObjError{line, "\"" + tok + "\" is not a number"};
    const char* s = tok.c_str();
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(s, &end);
    if (end == s || *end != '\0') throw MeshObjError{line, "\"" + tok + "\" is not a number"};
    if (!std::isfinite(x) || std::fabs(x) > 1e12)
        throw MeshObjError{line,
                           "\"" + tok + "\" is not a finite number of magnitude at most 1e12"};
    return x;
}

// One index of a face's vertex ("3", "-1"): 1-based, negative from the end; must refer to one
// of the `count` defined so far. Returns the 0-based index.
long long mesh_obj_index(const std::string& tok, const char* what, std::size_t count,
                         std::size_t line) {
    const char* s = tok.c_str();
    char* end = nullptr;
    errno = 0;
    const long long k = std::strtoll(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE)
        throw MeshObjError{line, "face index \"" + tok + "\" is not an integer"};
    if (k == 0)
        throw MeshObjError{line, std::string("face index 0: OBJ ") + what +
                                     " indices start at 1 (negative ones count from the last)"};
    const long long n = static_cast<long long>(count);
    const long long i = k > 0 ? k - 1 : n + k;
    if (i < 0 || i >= n)
        throw MeshObjError{line, "face index " + tok + " refers to " + what + " " +
                                     std::to_string(k) + ", but only " + std::to_string(n) +
                                     " are defined before this line"};
    return i;
}

bool mesh_obj_is(const std::string& kw, std::initializer_list<const char*> list) {
    for (const char* k : list)
        if (kw == k) return true;
    return false;
}

// The checks tinyobjloader does not make (it skips or guesses), with line numbers.
void mesh_obj_scan(const std::string& text) {
    std::size_t v = 0, vt = 0, vn = 0, faces = 0, line = 0, pos = 0;
    std::vector<std::string> tok;
    while (pos < text.size()) {
        // Lines end as tinyobjloader ends them: at "\n", "\r\n" or a lone "\r".
        std::size_t eol = text.find_first_of("\r\n", pos);
        if (eol == std::string::npos) eol = text.size();
        std::string s = text.substr(pos, eol - pos);
        pos = eol + (eol + 1 < text.size() && text[eol] == '\r' && text[eol + 1] == '\n' ? 2 : 1);
        ++line;
        if (s.find('\0') != std::string::npos)
            throw MeshObjError{line, "is not text (a NUL byte): not an OBJ file"};
        if (const auto hash = s.find('#'); hash != std::string::npos) s.resize(hash);
        // Fields are separated by spaces and tabs only (other control characters are refused
        // as part of a field).
        tok.clear();
        for (std::size_t k = 0; k < s.size();) {
            const std::size_t b = s.find_first_not_of(" \t", k);
            if (b == std::string::npos) break;
            const std::size_t e = std::min(s.find_first_of(" \t", b), s.size());
            tok.push_back(s.substr(b, e - b));
            k = e;
        }
        if (tok.empty()) continue;
        const std::string& kw = tok[0];
        const std::size_t args = tok.size() - 1;
        if (kw == "v") {
            if (args != 3 && args != 4 && args != 6 && args != 7)
                throw MeshObjError{line, "a vertex \"v\" needs x y z (then w, or r g b), got " +
                                             std::to_string(args) + " numbers"};
            for (std::size_t k = 1; k <= args; ++k) mesh_obj_number(tok[k], line);
            ++v;
        } else if (kw == "vt") {
            if (args < 1 || args > 3)
                throw MeshObjError{line, "a texture coordinate \"vt\" needs 1 to 3 numbers, got " +
                                             std::to_string(args)};
            for (std::size_t k = 1; k <= args; ++k) mesh_obj_number(tok[k], line);
            ++vt;
        } else if (kw == "vn") {
            if (args != 3)
                throw MeshObjError{line,
                                   "a normal \"vn\" needs 3 numbers, got " + std::to_string(args)};
            double big = 0;
            for (std::size_t k = 1; k <= 3; ++k)
                big = std::max(big, std::fabs(mesh_obj_number(tok[k], line)));
            if (!(big >= 1e-30))
                throw MeshObjError{line,
                                   "a normal \"vn\" must not be the zero vector (or "
                                   "shorter than 1e-30)"};
            ++vn;
        } else if (kw == "f") {
            if (args < 3)
                throw MeshObjError{line,
                                   "a face needs at least 3 vertices, got " + std::to_string(args)};
            if (args > 255)
                throw MeshObjError{
                    line, "a face has " + std::to_string(args) + " vertices; the limit is 255"};
            for (std::size_t k = 1; k <= args; ++k) {
                const std::string& t = tok[k];
                const auto s1 = t.find('/');
                mesh_obj_index(t.substr(0, s1), "vertex", v, line);
                if (s1 == std::string::npos) continue;
                const auto s2 = t.find('/', s1 + 1);
                const std::string a = t.substr(s1 + 1, s2 == std::string::npos ? s2 : s2 - s1 - 1);
                if (!a.empty()) mesh_obj_index(a, "texture coordinate", vt, line);
                if (s2 == std::string::npos) continue;
                const std::string b = t.substr(s2 + 1);
                if (b.find('/') != std::string::npos)
                    throw MeshObjError{line, "face vertex \"" + t + "\" has more than v/vt/vn"};
                if (!b.empty()) mesh_obj_index(b, "normal", vn, line);
            }
            ++faces;
        } else if (mesh_obj_is(kw, {"curv", "curv2", "surf", "cstype", "deg", "bmat", "step",
                                    "parm", "trim", "hole", "scrv", "sp", "end", "con", "vp"})) {
            throw MeshObjError{line, "\"" + kw +
                                         "\" is free-form geometry (curves and surfaces), which "
                                         "the tracer does not read: only polygon faces"};
        } else if (!mesh_obj_is(kw, {"l", "p", "o", "g", "s", "mg", "usemtl", "mtllib", "lod",
                                     "bevel", "c_interp", "d_interp", "usemap", "maplib",
                                     "shadow_obj", "trace_obj", "ctech", "stech"})) {
            throw MeshObjError{line, "\"" + kw + "\" is not an OBJ statement"};
        }
    }
    if (faces == 0) throw MeshObjError{0, "has no faces: an empty mesh"};
}

}  // namespace

mesh::Mesh read_obj(const std::string& path, const std::string& field) {
    const std::string file = "\"" + path + "\"";
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status))
        throw InputError(field, "cannot read " + file + ": no such file");
    if (!std::filesystem::is_regular_file(status))
        throw InputError(field, "cannot read " + file + ": not a regular file");
    const auto bytes = std::filesystem::file_size(path, ec);
    if (ec || bytes > kMaxObjBytes)
        throw InputError(field, "cannot read " + file + ": larger than 512 MB");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(field, "cannot read " + file + ": " + std::strerror(errno));
    std::string text(static_cast<std::size_t>(bytes), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (!in) throw InputError(field, "cannot read " + file + ": a read error");
    try {
        mesh_obj_scan(text);
    } catch (const MeshObjError& e) {
        throw InputError(
            field, file + (e.line ? " line " + std::to_string(e.line) : "") + ": " + e.reason);
    }
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, "", config))
        throw InputError(field, file + ": tinyobjloader refused it: " + reader.Error());
    const tinyobj::attrib_t& a = reader.GetAttrib();
    bool normals = true, uv = true;
    std::size_t corners = 0;
    for (const tinyobj::shape_t& sh : reader.GetShapes())
        for (const tinyobj::index_t& ix : sh.mesh.indices) {
            normals = normals && ix.normal_index >= 0;
            uv = uv && ix.texcoord_index >= 0;
            ++corners;
        }
    // One vertex per triangle corner: OBJ indexes positions, normals and (u, v) separately.
    mesh::Mesh m;
    m.vertices.reserve(corners);
    if (normals) m.normals.reserve(corners);
    if (uv) m.uv.reserve(corners);
    for (const tinyobj::shape_t& sh : reader.GetShapes()) {
        std::size_t k = 0;
        for (const unsigned char fv : sh.mesh.num_face_vertices) {
            if (fv != 3) {  // triangulated: cannot happen
                k += fv;
                continue;
            }
            glm::dvec3 p[3], n[3];
            glm::dvec2 t[3];
            // Every index checked against what tinyobjloader read, whatever the pre-scan said
            // (fuzzing found a file whose (u, v) index ran past the texcoords it kept).
            auto at = [&](int index, std::size_t width, std::size_t size, const char* what) {
                const std::size_t i = width * static_cast<std::size_t>(index);
                if (index < 0 || i + width > size)
                    throw InputError(field, file + ": a face refers to a " + what +
                                                " the file does not define");
                return i;
            };
            if (k + 3 > sh.mesh.indices.size())
                throw InputError(field, file + ": a face lists fewer corners than it declares");
            for (int c = 0; c < 3; ++c) {
                const tinyobj::index_t& ix = sh.mesh.indices[k + c];
                const std::size_t vi = at(ix.vertex_index, 3, a.vertices.size(), "vertex (v)");
                p[c] = {a.vertices[vi], a.vertices[vi + 1], a.vertices[vi + 2]};
                if (normals) {
                    const std::size_t ni = at(ix.normal_index, 3, a.normals.size(), "normal (vn)");
                    n[c] = {a.normals[ni], a.normals[ni + 1], a.normals[ni + 2]};
                }
                if (uv) {
                    const std::size_t ti =
                        at(ix.texcoord_index, 2, a.texcoords.size(), "texture coordinate (vt)");
                    t[c] = {a.texcoords[ti], a.texcoords[ti + 1]};
                }
            }
            k += 3;
            if (mesh::degenerate(p[0], p[1], p[2])) continue;
            const auto base = static_cast<std::uint32_t>(m.vertices.size());
            for (int c = 0; c < 3; ++c) {
                m.vertices.push_back(p[c]);
                if (normals) m.normals.push_back(n[c]);
                if (uv) m.uv.push_back(t[c]);
            }
            m.triangles.push_back({base, base + 1, base + 2});
        }
    }
    if (m.triangles.empty())
        throw InputError(field, file + ": has no triangles of nonzero area: an empty mesh");
    return m;
}

}  // namespace cg::mesh_json
