#include "rays/rt_scene_json.hpp"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "core/format.hpp"
#include "rays/csg_json.hpp"
#include "rays/mesh_json.hpp"
#include "rays/rays_json.hpp"
#include "rays/texture_json.hpp"
#include "sampling/pattern_json.hpp"

namespace cg::rt {

namespace {

using rays_json::color;

Color optional_color(const Reader& r, const char* key, Color fallback) {
    bool rgb = false;
    return r.has(key) ? color(r, key, rgb) : fallback;
}

const json& list(const Reader& r, const char* key, const char* what) {
    const json& v = r.get(key);
    if (!v.is_array())
        throw InputError(r.field(key),
                         std::string("must be a list of ") + what + ", got " + describe(v));
    return v;
}

bool optional_bool(const Reader& r, const char* key, bool fallback) {
    return r.has(key) ? r.boolean(key) : fallback;
}

Camera camera_from(const Reader& r) {
    r.only({"eye", "center", "up", "fov_y_deg", "size", "aperture", "focal_distance", "shutter"});
    Camera c;
    c.eye = r.point3("eye");
    c.center = r.point3("center");
    if (r.has("up")) c.up = r.point3("up");
    if (r.has("fov_y_deg")) c.fov_y_deg = r.number("fov_y_deg");
    if (r.has("size")) {
        const json& v = r.get("size");
        const std::string f = r.field("size");
        if (!v.is_array() || v.size() != 2)
            throw InputError(f, "must be [width, height] in whole pixels, got " + describe(v));
        for (int k = 0; k < 2; ++k)
            if (!v[k].is_number_integer())
                throw InputError(f + "[" + std::to_string(k) + "]",
                                 "must be an integer number of pixels, got " + describe(v[k]));
        const long long w = v[0].get<long long>(), h = v[1].get<long long>();
        if (w < 1 || h < 1 || w > 1 << 20 || h > 1 << 20)
            throw InputError(f, "must be at least 1×1 and at most 1048576 on a side (got " +
                                    std::to_string(w) + "×" + std::to_string(h) + ")");
        c.width = static_cast<int>(w), c.height = static_cast<int>(h);
    }
    if (r.has("aperture")) c.aperture = r.number("aperture");
    if (r.has("focal_distance")) c.focal_distance = r.number("focal_distance");
    if (r.has("shutter")) c.shutter = r.number("shutter");
    return c;
}

// A count in [1, max], naming the field.
int count_from(const Reader& r, const char* key, int max) {
    const long long n = r.integer(key);
    if (n < 1 || n > max)
        throw InputError(r.field(key), "must be between 1 and " + std::to_string(max) + " (got " +
                                           std::to_string(n) + ")");
    return static_cast<int>(n);
}

Settings settings_from(const Reader& r) {
    r.only({"max_depth", "shadows", "reflections", "refractions", "model", "ray_casting",
            "samples_per_pixel", "pattern", "filter", "seed"});
    Settings s;
    if (r.has("max_depth")) {
        const long long d = r.integer("max_depth");
        if (d < 0 || d > kMaxDepth)
            throw InputError(r.field("max_depth"), "must be between 0 and " +
                                                       std::to_string(kMaxDepth) + " (got " +
                                                       std::to_string(d) + ")");
        s.max_depth = static_cast<int>(d);
    }
    s.shadows = optional_bool(r, "shadows", true);
    s.reflections = optional_bool(r, "reflections", true);
    s.refractions = optional_bool(r, "refractions", true);
    if (r.has("model")) {
        const std::string m = r.string("model");
        if (m == "phong")
            s.model = Model::Phong;
        else if (m == "blinn-phong")
            s.model = Model::BlinnPhong;
        else
            throw InputError(r.field("model"),
                             "must be \"phong\" or \"blinn-phong\" (got \"" + m + "\")");
    }
    if (optional_bool(r, "ray_casting", false)) {
        if ((r.has("max_depth") && s.max_depth > 0) || (r.has("shadows") && s.shadows))
            throw InputError(r.field("ray_casting"),
                             "ray casting casts no secondary rays: it cannot have max_depth > 0 "
                             "or shadows");
        s.max_depth = 0;
        s.shadows = false;
    }
    if (r.has("samples_per_pixel"))
        s.samples_per_pixel = count_from(r, "samples_per_pixel", kMaxSamplesPerPixel);
    if (r.has("pattern")) s.pattern = sampling_json::pattern(r, "pattern");
    if (r.has("filter")) s.filter = sampling_json::filter(r, "filter");
    if (r.has("seed")) s.seed = sampling_json::seed(r, "seed");
    return s;
}

// A material's "texture", "solid_texture" and "bump" (rays/rt_texture.hpp).
void material_textures_from(const Reader& r, MaterialTextures& t) {
    if (r.has("texture")) {
        t.has_texture = true;
        t.texture = texture_json::texture(r.object("texture"));
    }
    if (r.has("solid_texture")) {
        t.has_solid = true;
        t.solid = texture_json::solid(r.object("solid_texture"));
    }
    if (r.has("bump")) {
        t.has_bump = true;
        t.bump = texture_json::height(r.object("bump"));
    }
}

// An object's texture parametrisation: a plane's "u_axis" and "uv_scale", a triangle's "uv".
void object_uv_from(const Reader& o, Object& obj) {
    if (o.has("u_axis")) {
        obj.uv.has_u_axis = true;
        obj.uv.u_axis = o.point3("u_axis");
    }
    if (o.has("uv_scale")) obj.uv.scale = o.number("uv_scale");
    if (o.has("uv")) {
        const std::vector<glm::dvec2> uv = o.points2("uv");
        if (uv.size() != 3)
            throw InputError(o.field("uv"), "must be 3 (u, v) pairs, one per vertex, got " +
                                                std::to_string(uv.size()));
        obj.uv.has_uv = true;
        obj.uv.uv = {uv[0], uv[1], uv[2]};
    }
}

Material material_from(const Reader& r) {
    r.only({"name", "ka", "kd", "ks", "shininess", "kr", "kt", "ior", "texture", "solid_texture",
            "bump", "gloss", "gloss_samples"});
    Material m;
    m.name = r.string("name");
    m.ka = optional_color(r, "ka", m.ka);
    m.kd = optional_color(r, "kd", m.kd);
    m.ks = optional_color(r, "ks", m.ks);
    if (r.has("shininess")) m.shininess = r.number("shininess");
    m.kr = optional_color(r, "kr", m.kr);
    m.kt = optional_color(r, "kt", m.kt);
    if (r.has("ior")) m.ior = r.number("ior");
    if (r.has("gloss")) m.gloss = r.number("gloss");
    if (r.has("gloss_samples")) {
        m.gloss_samples = count_from(r, "gloss_samples", kMaxGlossSamples);
        if (!(m.gloss > 0))
            throw InputError(r.field("gloss_samples"),
                             "needs \"gloss\" > 0: a mirror (gloss 0) reflects one ray");
    }
    material_textures_from(r, m.tex);
    return m;
}

Light light_from(const Reader& l) {
    l.only({"position", "direction", "intensity", "attenuation", "area", "samples"});
    if (l.has("position") == l.has("direction"))
        throw InputError(l.path(),
                         "needs exactly one of \"position\" (a point light) and "
                         "\"direction\" (a directional light)");
    Light light;
    light.directional = l.has("direction");
    if (light.directional)
        light.direction = l.point3("direction");
    else
        light.position = l.point3("position");
    light.intensity = optional_color(l, "intensity", light.intensity);
    if (l.has("attenuation")) {
        if (light.directional)
            throw InputError(l.field("attenuation"),
                             "applies to point lights only: a directional light is not attenuated");
        light.attenuation = l.point3("attenuation");
    }
    if (l.has("area")) {
        if (light.directional)
            throw InputError(l.field("area"),
                             "applies to point lights only: a directional light has no position");
        const Reader a = l.object("area");
        const std::string shape = a.string("shape");
        if (shape == "rectangle") {
            a.only({"shape", "u", "v"});
            light.area = Light::Area::Rectangle;
            light.edge_u = a.point3("u");
            light.edge_v = a.point3("v");
        } else if (shape == "disc") {
            a.only({"shape", "radius", "normal"});
            light.area = Light::Area::Disc;
            light.radius = a.number("radius");
            if (a.has("normal")) light.normal = a.point3("normal");
        } else {
            throw InputError(a.field("shape"),
                             "must be \"rectangle\" or \"disc\" (got \"" + shape + "\")");
        }
    }
    if (l.has("samples")) {
        if (light.area == Light::Area::None)
            throw InputError(l.field("samples"),
                             "is for an area light (\"area\"): a point light needs one shadow ray");
        light.samples = count_from(l, "samples", kMaxLightSamples);
    }
    return light;
}

// A mesh's or triangle's "normals": one per vertex, each nonzero.
std::vector<glm::dvec3> mesh_normals_from(const Reader& o, std::size_t vertices) {
    const std::vector<glm::dvec3> n = o.points3("normals");
    if (n.size() != vertices)
        throw InputError(o.field("normals"), "must give one normal per vertex: " +
                                                 std::to_string(vertices) + " vertices, " +
                                                 std::to_string(n.size()) + " normals");
    for (std::size_t k = 0; k < n.size(); ++k) {
        const double big = std::max({std::fabs(n[k].x), std::fabs(n[k].y), std::fabs(n[k].z)});
        if (!(big >= 1e-150))
            throw InputError(element(o.field("normals"), k),
                             "must not be the zero vector (or shorter than 1e-150): it is the "
                             "vertex's normal");
    }
    return n;
}

// A mesh object: its triangles from "vertices" + "triangles" (+ "uv", "normals"), from
// "generate" (rays/mesh_gen.hpp) or from an "obj" file, moved by an optional "transform"; one
// object holding them all with their hierarchy (TriangleMesh).
void mesh_objects_from(const Reader& o, const Object& obj, Scene& s) {
    const int sources = int(o.has("vertices")) + int(o.has("generate")) + int(o.has("obj"));
    if (sources != 1)
        throw InputError(o.path(), "needs exactly one of \"vertices\" (with \"triangles\"), "
                                   "\"generate\" and \"obj\"");
    mesh::Mesh m;
    std::string source;  // the field the triangles come from, for errors
    auto check_count = [&](std::size_t n, const std::string& f) {
        const std::size_t total = scene_triangles(s) + n;
        if (total > kMaxTriangles)
            throw InputError(f, "makes the scene's meshes " + std::to_string(total) +
                                    " triangles; the limit is " + std::to_string(kMaxTriangles));
    };
    if (o.has("generate")) {
        for (const char* k : {"triangles", "uv", "normals"})
            if (o.has(k))
                throw InputError(o.field(k), "comes with \"vertices\": a generated mesh makes "
                                             "its own");
        const Reader g = o.object("generate");
        source = g.path();
        check_count(mesh_json::generate_count(g), source);
        m = mesh_json::generate(g);
    } else if (o.has("obj")) {
        for (const char* k : {"triangles", "uv", "normals"})
            if (o.has(k))
                throw InputError(o.field(k), "comes with \"vertices\": an OBJ file gives its own");
        source = o.field("obj");
        m = mesh_json::read_obj(o.string("obj"), source);
        check_count(m.triangles.size(), source);
    } else {
        source = o.field("vertices");
        m.vertices = o.points3("vertices");
        if (o.has("uv")) {
            m.uv = o.points2("uv");
            if (m.uv.size() != m.vertices.size())
                throw InputError(o.field("uv"), "must give one (u, v) per vertex: " +
                                                    std::to_string(m.vertices.size()) +
                                                    " vertices, " + std::to_string(m.uv.size()) +
                                                    " pairs");
        }
        if (o.has("normals")) m.normals = mesh_normals_from(o, m.vertices.size());
        const json& tris = list(o, "triangles", "triangles [i, j, k]");
        if (tris.empty()) throw InputError(o.field("triangles"), "must list at least one triangle");
        check_count(tris.size(), o.field("triangles"));
        m.triangles.reserve(tris.size());
        for (std::size_t t = 0; t < tris.size(); ++t) {
            const std::string tf = element(o.field("triangles"), t);
            const json& ix = tris[t];
            if (!ix.is_array() || ix.size() != 3)
                throw InputError(tf, "must be three vertex indices [i, j, k], got " + describe(ix));
            std::array<std::uint32_t, 3> tri{};
            for (int k = 0; k < 3; ++k) {
                if (!ix[k].is_number_integer() || ix[k].get<long long>() < 0 ||
                    ix[k].get<long long>() >= static_cast<long long>(m.vertices.size()))
                    throw InputError(element(tf, k), "must be a vertex index from 0 to " +
                                                         std::to_string(m.vertices.size() - 1) +
                                                         ", got " + describe(ix[k]));
                tri[k] = ix[k].get<std::uint32_t>();
            }
            m.triangles.push_back(tri);
        }
    }
    if (o.has("transform")) {
        // Points by M, normals by the inverse transpose of its 3 × 3 part (an affine M only).
        const glm::dmat4 M = rays_json::matrix4(o, "transform");
        if (M[0][3] != 0 || M[1][3] != 0 || M[2][3] != 0 || M[3][3] != 1)
            throw InputError(o.field("transform"),
                             "must be affine: its last row must be [0, 0, 0, 1]");
        const glm::dmat3 A(M);
        const double det = glm::determinant(A);
        if (!(std::fabs(det) > 1e-300) || !std::isfinite(det))
            throw InputError(o.field("transform"),
                             "must be invertible: its 3 × 3 part has determinant " + given(det));
        const glm::dmat3 N = glm::transpose(glm::inverse(A));
        for (glm::dvec3& p : m.vertices) p = glm::dvec3(M * glm::dvec4(p, 1.0));
        for (glm::dvec3& n : m.normals) n = N * n;
    }
    // Zero-area triangles: refused when listed by hand, left out when generated or read (a
    // transform may squash a generated one flat too). The others keep their input numbers.
    const bool from_vertices = o.has("vertices");
    std::vector<std::array<std::uint32_t, 3>> kept;
    std::vector<std::uint32_t> numbers;
    kept.reserve(m.triangles.size());
    numbers.reserve(m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        const auto& ix = m.triangles[t];
        const glm::dvec3 p0 = m.vertices[ix[0]], p1 = m.vertices[ix[1]], p2 = m.vertices[ix[2]];
        if (mesh::degenerate(p0, p1, p2)) {
            if (from_vertices)
                throw InputError(element(o.field("triangles"), t),
                                 "is degenerate: its corners " + given(p0, 4) + ", " + given(p1, 4) +
                                     ", " + given(p2, 4) + " are collinear or coincide (zero area)");
            continue;
        }
        kept.push_back(ix);
        numbers.push_back(static_cast<std::uint32_t>(t));
    }
    if (kept.empty())
        throw InputError(source, "gives no triangle of nonzero area: every one is degenerate");
    if (kept.size() == m.triangles.size()) numbers.clear();  // none left out: k is k
    m.triangles = std::move(kept);
    Object mo = obj;
    mo.kind = ObjectKind::Mesh;
    mo.mesh = Shared<TriangleMesh>(make_triangle_mesh(std::move(m), std::move(numbers)));
    s.objects.push_back(std::move(mo));
}

int material_index(const Reader& r, const std::vector<Material>& materials) {
    const std::string name = r.string("material");
    for (std::size_t i = 0; i < materials.size(); ++i)
        if (materials[i].name == name) return static_cast<int>(i);
    std::string names;
    for (const Material& m : materials) names += (names.empty() ? "" : ", ") + m.name;
    throw InputError(r.field("material"),
                     "no material \"" + name + "\" (materials: " + names + ")");
}

void objects_from(const Reader& r, const std::vector<Material>& materials, Scene& s) {
    const json& v = list(r, "objects", "objects");
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Reader o(v[i], element("objects", i));
        Object obj;
        obj.field = o.path();
        const std::string type = o.string("type");
        obj.name = o.has("name") ? o.string("name") : o.path();
        if (!o.has("material"))
            throw InputError(o.field("material"),
                             "is missing: every object needs a material's name");
        obj.material = material_index(o, materials);
        if (o.has("velocity")) obj.velocity = o.point3("velocity");
        if (type == "plane") {
            o.only(
                {"type", "name", "material", "point", "normal", "u_axis", "uv_scale", "velocity"});
            object_uv_from(o, obj);
            obj.kind = ObjectKind::Plane;
            obj.p0 = o.point3("point");
            obj.normal = o.point3("normal");
            s.objects.push_back(obj);
        } else if (type == "triangle") {
            o.only({"type", "name", "material", "vertices", "uv", "normals", "velocity"});
            object_uv_from(o, obj);
            obj.kind = ObjectKind::Triangle;
            const std::vector<glm::dvec3> p = o.points3("vertices");
            if (p.size() != 3)
                throw InputError(o.field("vertices"),
                                 "must be 3 points, got " + std::to_string(p.size()));
            obj.p0 = p[0], obj.p1 = p[1], obj.p2 = p[2];
            if (o.has("normals")) {
                const std::vector<glm::dvec3> n = mesh_normals_from(o, 3);
                obj.smooth = true;
                obj.n0 = n[0], obj.n1 = n[1], obj.n2 = n[2];
            }
            obj.field = o.field("vertices");
            s.objects.push_back(obj);
        } else if (type == "mesh") {
            o.only({"type", "name", "material", "vertices", "triangles", "uv", "normals",
                    "generate", "obj", "transform", "velocity"});
            mesh_objects_from(o, obj, s);
        } else if (type == "csg") {
            o.only({"type", "name", "material", "tree", "velocity"});
            obj.kind = ObjectKind::Csg;
            obj.csg = csg_json::tree(o.get("tree"), o.field("tree"));
            s.objects.push_back(obj);
        } else {
            o.only({"type", "name", "material", "params", "transform", "zmin", "zmax", "velocity"});
            const bool quadric = type == "sphere" || type == "ellipsoid" || type == "paraboloid" ||
                                 type == "hyperboloid" || type == "cone" || type == "cylinder";
            if (!quadric)
                throw InputError(o.field("type"),
                                 std::string("must be one of ") + rays_json::kQuadricTypes +
                                     ", plane, triangle, mesh, csg (got \"" + type + "\")");
            obj.kind = ObjectKind::Quadric;
            obj.quadric = rays_json::quadric(o);
            s.objects.push_back(obj);
        }
        if (s.objects.size() > kMaxObjects)
            throw InputError("objects", "has more than " + std::to_string(kMaxObjects) +
                                            " objects (a mesh is one, however many triangles it has)");
    }
}

}  // namespace

Scene scene_from_json(const json& j, std::initializer_list<const char*> allow) {
    const Reader r(j);
    for (auto it = j.begin(); it != j.end(); ++it) {
        static const char* known[] = {"camera",    "settings", "background", "ambient",
                                      "materials", "lights",   "objects"};
        const bool ok =
            std::any_of(std::begin(known), std::end(known),
                        [&](const char* k) { return it.key() == k; }) ||
            std::any_of(allow.begin(), allow.end(), [&](const char* k) { return it.key() == k; });
        if (!ok)
            throw InputError(it.key(),
                             "is not a field of a scene (fields: camera, settings, "
                             "background, ambient, materials, lights, objects)");
    }
    Scene s;
    s.camera = camera_from(r.object("camera"));
    if (r.has("settings")) s.settings = settings_from(r.object("settings"));
    s.background = optional_color(r, "background", s.background);
    s.ambient = optional_color(r, "ambient", s.ambient);
    const json& mats = list(r, "materials", "materials");
    if (mats.empty()) throw InputError("materials", "must list at least one material");
    for (std::size_t i = 0; i < mats.size(); ++i) {
        s.materials.push_back(material_from(Reader(mats[i], element("materials", i))));
        for (std::size_t k = 0; k < i; ++k)
            if (s.materials[k].name == s.materials[i].name)
                throw InputError(element("materials", i) + ".name",
                                 "\"" + s.materials[i].name + "\" names two materials");
    }
    if (r.has("lights")) {
        const json& lights = list(r, "lights", "lights");
        if (lights.size() > kMaxLights)
            throw InputError("lights", "has " + std::to_string(lights.size()) +
                                           " lights; the limit is " + std::to_string(kMaxLights));
        for (std::size_t i = 0; i < lights.size(); ++i)
            s.lights.push_back(light_from(Reader(lights[i], element("lights", i))));
    }
    objects_from(r, s.materials, s);
    return s;
}

std::string image_checksum(const std::vector<std::uint32_t>& rgba, int width, int height) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (int j = height - 1; j >= 0; --j)
        for (int i = 0; i < width; ++i) {
            const std::uint32_t v = rgba[static_cast<std::size_t>(j) * width + i];
            for (int shift = 24; shift >= 0; shift -= 8) {
                h ^= (v >> shift) & 0xff;
                h *= 0x100000001b3ull;
            }
        }
    static const char* digits = "0123456789abcdef";
    std::string s(16, '0');
    for (int k = 15; k >= 0; --k, h >>= 4) s[k] = digits[h & 15];
    return s;
}

json scene_to_json(const Scene& s) {
    auto colour = [](const Color& c) {
        return c.x == c.y && c.y == c.z ? nice_number(c.x) : nice_point(c);
    };
    json camera{{"eye", nice_point(s.camera.eye)},
                {"center", nice_point(s.camera.center)},
                {"up", nice_point(s.camera.up)},
                {"fov_y_deg", nice_number(s.camera.fov_y_deg)},
                {"size", {s.camera.width, s.camera.height}}};
    if (s.camera.aperture > 0) camera["aperture"] = nice_number(s.camera.aperture);
    if (s.camera.focal_distance > 0)
        camera["focal_distance"] = nice_number(s.camera.focal_distance);
    if (s.camera.shutter > 0) camera["shutter"] = nice_number(s.camera.shutter);
    json settings{{"max_depth", s.settings.max_depth},
                  {"shadows", s.settings.shadows},
                  {"reflections", s.settings.reflections},
                  {"refractions", s.settings.refractions},
                  {"model", s.settings.model == Model::Phong ? "phong" : "blinn-phong"}};
    if (s.settings.samples_per_pixel != 1 || s.settings.pattern != Settings{}.pattern ||
        s.settings.filter != Settings{}.filter || s.settings.seed != Settings{}.seed) {
        settings["samples_per_pixel"] = s.settings.samples_per_pixel;
        settings["pattern"] = sampling::pattern_id(s.settings.pattern);
        settings["filter"] = sampling::filter_id(s.settings.filter);
        settings["seed"] = s.settings.seed;
    }
    json materials = json::array();
    for (const Material& m : s.materials) {
        json mj{{"name", m.name},
                {"ka", colour(m.ka)},
                {"kd", colour(m.kd)},
                {"ks", colour(m.ks)},
                {"shininess", nice_number(m.shininess)},
                {"kr", colour(m.kr)},
                {"kt", colour(m.kt)},
                {"ior", nice_number(m.ior)}};
        if (m.gloss > 0) mj["gloss"] = nice_number(m.gloss);
        if (m.gloss_samples != 1) mj["gloss_samples"] = m.gloss_samples;
        if (m.tex.has_texture) mj["texture"] = texture_json::texture_json(m.tex.texture);
        if (m.tex.has_solid) mj["solid_texture"] = texture_json::solid_json(m.tex.solid);
        if (m.tex.has_bump) mj["bump"] = texture_json::height_json(m.tex.bump);
        materials.push_back(std::move(mj));
    }
    json lights = json::array();
    for (const Light& l : s.lights) {
        json j = json::object();
        if (l.directional)
            j["direction"] = nice_point(l.direction);
        else
            j["position"] = nice_point(l.position);
        j["intensity"] = colour(l.intensity);
        if (!l.directional && l.attenuation != glm::dvec3(1, 0, 0))
            j["attenuation"] = nice_point(l.attenuation);
        if (l.area == Light::Area::Rectangle)
            j["area"] = json{
                {"shape", "rectangle"}, {"u", nice_point(l.edge_u)}, {"v", nice_point(l.edge_v)}};
        else if (l.area == Light::Area::Disc)
            j["area"] = json{{"shape", "disc"},
                             {"radius", nice_number(l.radius)},
                             {"normal", nice_point(l.normal)}};
        if (l.area != Light::Area::None) j["samples"] = l.samples;
        lights.push_back(std::move(j));
    }
    json objects = json::array();
    for (const Object& o : s.objects) {
        json j;
        switch (o.kind) {
            case ObjectKind::Quadric:
                j = rays_json::quadric_json(o.quadric);
                break;
            case ObjectKind::Plane:
                j = json{{"type", "plane"},
                         {"point", nice_point(o.p0)},
                         {"normal", nice_point(o.normal)}};
                if (o.uv.has_u_axis) j["u_axis"] = nice_point(o.uv.u_axis);
                if (o.uv.scale != 1) j["uv_scale"] = nice_number(o.uv.scale);
                break;
            case ObjectKind::Triangle:
                j = json{{"type", "triangle"},
                         {"vertices", {nice_point(o.p0), nice_point(o.p1), nice_point(o.p2)}}};
                if (o.uv.has_uv)
                    j["uv"] = {nice_point(o.uv.uv[0]), nice_point(o.uv.uv[1]),
                               nice_point(o.uv.uv[2])};
                if (o.smooth) j["normals"] = {nice_point(o.n0), nice_point(o.n1), nice_point(o.n2)};
                break;
            case ObjectKind::Csg:
                j = json{{"type", "csg"}, {"tree", csg_json::tree_json(o.csg)}};
                break;
            case ObjectKind::Mesh: {  // listed vertex by vertex (a generated one too)
                const mesh::Mesh& m = o.mesh->mesh;
                json v = json::array(), t = json::array();
                for (const glm::dvec3& p : m.vertices) v.push_back(nice_point(p));
                for (const auto& ix : m.triangles) t.push_back({ix[0], ix[1], ix[2]});
                j = json{{"type", "mesh"}, {"vertices", std::move(v)}, {"triangles", std::move(t)}};
                if (!m.normals.empty()) {
                    json n = json::array();
                    for (const glm::dvec3& p : m.normals) n.push_back(nice_point(p));
                    j["normals"] = std::move(n);
                }
                if (!m.uv.empty()) {
                    json uv = json::array();
                    for (const glm::dvec2& p : m.uv) uv.push_back(nice_point(p));
                    j["uv"] = std::move(uv);
                }
                break;
            }
        }
        j["name"] = o.name;
        j["material"] = s.materials[o.material].name;
        if (o.velocity != glm::dvec3(0.0)) j["velocity"] = nice_point(o.velocity);
        objects.push_back(std::move(j));
    }
    return json{{"camera", std::move(camera)},        {"settings", std::move(settings)},
                {"background", colour(s.background)}, {"ambient", colour(s.ambient)},
                {"materials", std::move(materials)},  {"lights", std::move(lights)},
                {"objects", std::move(objects)}};
}

}  // namespace cg::rt
