// Sections: [helpers] [spec] [validate] [the arithmetic] [advance] [render and result]
//           [narrate]; the picture is in shading_draw.cpp
#include "shading/shading.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "affine/vertex_normals.hpp"
#include "core/format.hpp"
#include "raster/orient2d.hpp"
#include "rays/quadric.hpp"  // unit()

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using Color = Shading::Color;
using Face = Shading::Face;
using Input = Shading::Input;
using Model = Shading::Model;
using Phase = Shading::Phase;
using Sample = Shading::Sample;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineNormals = 1,
    kLineVertexColors,
    kLineTriangle,
    kLineDegenerate,
    kLineFlat,
    kLineScanline,
    kLineSpan,
    kLineDepth,
    kLineWrite,
    kLineDone,
};

dvec2 xy(dvec3 p) {
    return {p.x, p.y};
}

std::string ctext(const Color& c, bool rgb, int digits = 4) {
    return rgb ? num(c, digits) : num(c.x, digits);
}
std::string ctex(const Color& c, bool rgb, int digits = 4) {
    return rgb ? tex(c, digits) : tex(c.x, digits);
}
Value cvalue(const Color& c, bool rgb) {
    if (rgb) return vec(c);
    return c.x;
}

std::string vname(int v) {
    return "V" + std::to_string(v);
}

std::string plural(long long n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const char* Shading::model_id(Model m) {
    switch (m) {
        case Model::Flat:
            return "flat";
        case Model::Gouraud:
            return "gouraud";
        case Model::Phong:
            return "phong";
    }
    return "phong";
}

const Spec& Shading::spec() {
    static const Spec spec{
        "shading",
        "Flat, Gouraud and Phong shading",
        "Lighting",
        {
            "vertex normals n_V: given, normalised; else Σ over V's faces of (P1 − P0) × (P2 − P0) "
            "turned to face the viewer, normalised",
            "Gouraud: c_V ← lighting(P_V, n_V) at every vertex",
            "for each triangle, in index order:",
            "    if its area on the screen is 0: it covers nothing, next",
            "    flat: c ← lighting(centroid, face normal n_f)        ▷ its one evaluation",
            "    for each scanline j it covers (scan-triangle's spans, top-left rule):",
            "        x_left, x_right at y = j + ½; z and c (Gouraud) or n (Phong) at both ends",
            "        for each pixel i of the span:  λ ← barycentric of (i + ½, j + ½);  z ← Σ λ_k "
            "z_k",
            "            if z < depth[i, j]:  depth ← z;  colour ← c (flat) | Σ λ_k c_k (Gouraud) "
            "| "
            "lighting(P, normalise(Σ λ_k n_k)) (Phong)",
            "done: the image (colours unclamped; a display clamps them to [0, 1])",
        },
        {
            {"normals-given", "the vertex normals as given, normalised"},
            {"normals-averaged", "each vertex normal: the area-weighted average of its faces'"},
            {"vertex-colors", "Gouraud: the lighting evaluated once at every vertex"},
            {"triangle", "a triangle set up: its vertices, its area, the scanlines it covers"},
            {"flat-face", "flat: the triangle's one lighting evaluation, at its centroid"},
            {"degenerate", "a triangle with no area on the screen: it covers no pixel"},
            {"span", "a scanline's span: the quantities at its ends, its pixels depth-tested"},
            {"empty-span", "a scanline whose span holds no pixel centre inside the image"},
            {"pixel-flat", "the chosen pixel: depth, then the triangle's one colour"},
            {"pixel-gouraud", "the chosen pixel: depth, then the vertex colours interpolated"},
            {"pixel-phong", "the chosen pixel: the normal interpolated, normalised, lit"},
            {"pixel-hidden", "the chosen pixel: a nearer triangle is already there"},
            {"done", "every triangle is drawn"},
        },
        {},  // no sliders
        {
            .predict = {
                {"flat-face", {"flat_color"}},
                {"span", {"x_left", "x_right"}},
                {"pixel-flat", {"color"}},
                {"pixel-gouraud", {"lambda", "color"}},
                {"pixel-phong", {"lambda", "color"}},
            },
            .mistakes = {
                {"span", "i_first", "off-by-one", "started the span one pixel off"},
                {"span", "x_left", "keep", "forgot to step x_left along its edge"},
                {"pixel-phong", "lambda", "reverse",
                 "paired the weights with the vertices backwards"},
                {"pixel-phong", "", "event:pixel-gouraud", "interpolated colours, not normals"},
            },
            .costs = {"evaluations"},
            .variants = {
                {"flat", "/model", "\"flat\""},
                {"gouraud", "/model", "\"gouraud\""},
                {"phong", "/model", "\"phong\""},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

// Appended piece by piece: GCC 12 inlines "[" + s + "]" into its callers and then warns
// falsely that the copies overlap (-Wrestrict, GCC bug 105329).
std::string index_text(long long k) {
    std::string text = "[";
    text += std::to_string(k);
    text += ']';
    return text;
}

void check_size(long long v, const char* field) {
    const std::string max = std::to_string(Shading::kMaxSize);
    if (v < 1 || v > Shading::kMaxSize)
        throw InputError(field, "must be a whole number of pixels from 1 to " + max + " (got " +
                                    std::to_string(v) + ")");
}

// A light's or the eye's position: far enough inside double range that distances to the mesh
// and their squares stay finite.
void check_position(dvec3 p, const std::string& field) {
    for (int d = 0; d < 3; ++d)
        if (!std::isfinite(p[d]) || std::fabs(p[d]) > Shading::kMaxLightCoordinate)
            throw InputError(field + index_text(d),
                             "must lie within ±1e100 (got " + given(p[d]) + ")");
}

struct Box {
    dvec3 lo{0.0}, hi{0.0};
};

Box bounds(const std::vector<dvec3>& v) {
    Box b{v[0], v[0]};
    for (const dvec3& p : v) b.lo = glm::min(b.lo, p), b.hi = glm::max(b.hi, p);
    return b;
}

// Everything but the vertex normals (vertex_normals checks those).
void check_input(const Input& in) {
    check_size(in.width, "width");
    check_size(in.height, "height");
    if (in.width * in.height > Shading::kMaxPixels)
        throw InputError(
            "width", "the image would have " + std::to_string(in.width * in.height) +
                         " pixels, more than the limit of " + std::to_string(Shading::kMaxPixels) +
                         " (" + std::to_string(in.width) + " × " + std::to_string(in.height) + ")");
    const auto& mesh = in.mesh;
    const long long n_vertices = static_cast<long long>(mesh.vertices.size());
    if (n_vertices > Shading::kMaxVertices)
        throw InputError("mesh.vertices", "at most " + std::to_string(Shading::kMaxVertices) +
                                              " vertices (the limit; got " +
                                              std::to_string(n_vertices) + ")");
    for (long long k = 0; k < n_vertices; ++k)
        for (int d = 0; d < 3; ++d) {
            const double v = mesh.vertices[k][d];
            auto field = [&] { return "mesh.vertices" + index_text(k) + index_text(d); };
            if (!std::isfinite(v))
                throw InputError(field(), "must be a finite number (got " + given(v) + ")");
            if (std::fabs(v) > Shading::kMaxCoordinate)
                throw InputError(field(), "must lie within ±1e9 (got " + given(v) + ")");
            // The exact inside test multiplies x and y; far below a pixel they could underflow.
            if (d < 2 && v != 0 && std::fabs(v) < 1e-100)
                throw InputError(field(),
                                 "must be 0 or at least 1e-100 in size (got " + given(v) + ")");
        }
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.vertices.size())
        throw InputError("mesh.normals", "must give one normal per vertex, " +
                                             std::to_string(n_vertices) + " in all (got " +
                                             std::to_string(mesh.normals.size()) + ")");
    for (std::size_t k = 0; k < mesh.normals.size(); ++k) {
        auto field = [&] { return "mesh.normals" + index_text(static_cast<long long>(k)); };
        for (int d = 0; d < 3; ++d)
            if (!std::isfinite(mesh.normals[k][d]))
                throw InputError(field() + index_text(d),
                                 "must be a finite number (got " + given(mesh.normals[k][d]) + ")");
        if (mesh.normals[k] == dvec3(0.0))
            throw InputError(field(), "must not be the zero vector: a vertex needs a direction");
    }
    const long long n_triangles = static_cast<long long>(mesh.triangles.size());
    if (n_triangles > Shading::kMaxTriangles)
        throw InputError("mesh.triangles", "at most " + std::to_string(Shading::kMaxTriangles) +
                                               " triangles (the limit; got " +
                                               std::to_string(n_triangles) + ")");
    double work = 0;
    for (long long k = 0; k < n_triangles; ++k) {
        for (int m = 0; m < 3; ++m) {
            const long long v = mesh.triangles[k][m];
            if (v < 0 || v >= n_vertices)
                throw InputError(
                    "mesh.triangles" + index_text(k) + index_text(m),
                    n_vertices == 0
                        ? "names vertex " + std::to_string(v) + ", but mesh.vertices is empty"
                        : "must be a vertex index from 0 to " + std::to_string(n_vertices - 1) +
                              " (got " + std::to_string(v) + ")");
        }
        // The pixels of its bounding box inside the image (plus one per row: the scanlines).
        dvec3 lo = mesh.vertices[mesh.triangles[k][0]], hi = lo;
        for (int m = 1; m < 3; ++m) {
            lo = glm::min(lo, mesh.vertices[mesh.triangles[k][m]]);
            hi = glm::max(hi, mesh.vertices[mesh.triangles[k][m]]);
        }
        const double w = std::clamp(std::ceil(hi.x), 0.0, double(in.width)) -
                         std::clamp(std::floor(lo.x), 0.0, double(in.width));
        const double h = std::clamp(std::ceil(hi.y), 0.0, double(in.height)) -
                         std::clamp(std::floor(lo.y), 0.0, double(in.height));
        work += h * (w + 1);
    }
    if (work > Shading::kMaxWork)
        throw InputError("mesh.triangles",
                         "the triangles' bounding boxes hold " + given(work, 10) +
                             " pixels in all (inside the image), more than the limit of " +
                             given(Shading::kMaxWork, 10) + ": the run would take too long");

    const PhongLighting::Input& L = in.lighting;
    check_position(L.eye, "lighting.eye");
    for (std::size_t i = 0; i < L.lights.size(); ++i)
        if (!L.lights[i].directional)
            check_position(L.lights[i].position,
                           "lighting.lights" + index_text(static_cast<long long>(i)) + ".position");
    try {
        PhongLighting::validate_lighting(L);
    } catch (const InputError& e) {
        throw InputError("lighting." + e.field(), e.reason());
    }
    // A point light close to the mesh is bright by its attenuation: 1/(c1 + c2 r + c3 r²) at the
    // nearest the mesh can be (its bounding box) must keep every colour finite.
    if (!mesh.vertices.empty()) {
        const Box box = bounds(mesh.vertices);
        const double kd_ks =
            std::max({L.material.kd.x + L.material.ks.x, L.material.kd.y + L.material.ks.y,
                      L.material.kd.z + L.material.ks.z});
        for (std::size_t i = 0; i < L.lights.size(); ++i) {
            const PhongLighting::Light& light = L.lights[i];
            if (light.directional) continue;
            const double r =
                glm::length(glm::clamp(light.position, box.lo, box.hi) - light.position);
            const dvec3 c = light.attenuation;
            const double den = c.x + c.y * r + c.z * r * r;
            const double most =
                std::max({light.intensity.x, light.intensity.y, light.intensity.z}) * kd_ks / den;
            if (!(most <= 1e200))
                throw InputError(
                    "lighting.lights" + index_text(static_cast<long long>(i)) + ".attenuation",
                    "makes the light too bright near the mesh: 1/(c1 + c2 r + c3 r²) "
                    "at r = " +
                        given(r) +
                        " (the nearest the mesh's bounding box "
                        "comes) is " +
                        given(1 / den) + ", and the colours could overflow");
        }
    }
    if (in.has_pixel) {
        if (in.pixel[0] < 0 || in.pixel[0] >= in.width)
            throw InputError("pixel[0]", "must be a column of the image, 0 to " +
                                             std::to_string(in.width - 1) + " (got " +
                                             std::to_string(in.pixel[0]) + ")");
        if (in.pixel[1] < 0 || in.pixel[1] >= in.height)
            throw InputError("pixel[1]", "must be a row of the image, 0 to " +
                                             std::to_string(in.height - 1) + " (got " +
                                             std::to_string(in.pixel[1]) + ")");
    }
}

// (P1 − P0) × (P2 − P0), turned to face the viewer (z ≤ 0): twice the face's area long.
dvec3 face_cross(const std::array<dvec3, 3>& p) {
    const dvec3 c = glm::cross(p[1] - p[0], p[2] - p[0]);
    return orient2d(xy(p[0]), xy(p[1]), xy(p[2])) > 0 ? -c : c;
}

std::array<dvec3, 3> corners(const Input& in, long long k) {
    const auto& t = in.mesh.triangles[static_cast<std::size_t>(k)];
    return {in.mesh.vertices[t[0]], in.mesh.vertices[t[1]], in.mesh.vertices[t[2]]};
}

bool has_area(const std::array<dvec3, 3>& p) {
    return orient2d(xy(p[0]), xy(p[1]), xy(p[2])) != 0;
}

struct MeshNormals {
    std::vector<dvec3> normals;  // unit; 0 for a vertex of no triangle with area
    std::vector<bool> lit;       // the vertex belongs to a triangle with area
};

// The unit vertex normals: given, or the area-weighted average of the faces around each
// vertex. Throws when a needed average is zero.
MeshNormals vertex_normals(const Input& in) {
    const auto& mesh = in.mesh;
    MeshNormals out;
    out.normals.assign(mesh.vertices.size(), dvec3(0.0));
    out.lit.assign(mesh.vertices.size(), false);
    if (in.model == Model::Flat) return out;
    // The faces' N, turned to the viewer (0: no area on the screen, left out).
    std::vector<dvec3> N(mesh.triangles.size(), dvec3(0.0));
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        const auto p = corners(in, static_cast<long long>(k));
        if (!has_area(p)) continue;
        if (mesh.normals.empty()) N[k] = face_cross(p);
        for (long long v : mesh.triangles[k]) out.lit[v] = true;
    }
    // No normals given: vertex-normals' area weighting (affine/vertex_normals.hpp).
    if (mesh.normals.empty())
        out.normals = cg::VertexNormals::area_weighted(mesh.vertices.size(), mesh.triangles, N);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (!out.lit[v]) continue;  // its faces have no area, so its sum stayed 0
        if (!mesh.normals.empty()) out.normals[v] = unit(mesh.normals[v]);
        if (out.normals[v] == dvec3(0.0))
            throw InputError("mesh.vertices" + index_text(static_cast<long long>(v)),
                             "its normal, the area-weighted average of its faces' normals, comes "
                             "out zero (the faces around it cancel); give mesh.normals");
    }
    return out;
}

// The chosen pixel: the given one, or the one under the centroid of the largest triangle (on
// the screen) whose centroid is inside the image, or the image's centre.
std::array<int, 2> chosen_pixel(const Input& in) {
    if (in.has_pixel) return {static_cast<int>(in.pixel[0]), static_cast<int>(in.pixel[1])};
    std::array<int, 2> best{static_cast<int>(in.width / 2), static_cast<int>(in.height / 2)};
    double best_area = 0;
    for (std::size_t k = 0; k < in.mesh.triangles.size(); ++k) {
        const auto p = corners(in, static_cast<long long>(k));
        if (!has_area(p)) continue;
        const double area = std::fabs(glm::cross(p[1] - p[0], p[2] - p[0]).z);
        const dvec3 c = (p[0] + p[1] + p[2]) / 3.0;
        if (c.x < 0 || c.y < 0 || c.x >= double(in.width) || c.y >= double(in.height)) continue;
        if (area > best_area) {
            best_area = area;
            best = {static_cast<int>(std::floor(c.x)), static_cast<int>(std::floor(c.y))};
        }
    }
    return best;
}

}  // namespace

void Shading::validate(const Input& in) {
    check_input(in);
    vertex_normals(in);
}

// ---- [the arithmetic] -----------------------------------------------------------------------
// Shared by the state machine, render() and the narration, so that all three compute the same
// numbers in the same order.

namespace {

// Triangle k made ready: its vertices, the scanline set-up, its normal; flat: its colour.
Face make_face(const Input& in, int k, long long& evaluations) {
    Face f;
    f.k = k;
    for (int m = 0; m < 3; ++m) {
        f.idx[m] = static_cast<int>(in.mesh.triangles[k][m]);
        f.p[m] = in.mesh.vertices[f.idx[m]];
    }
    f.setup =
        raster::setup_triangle(xy(f.p[0]), xy(f.p[1]), xy(f.p[2]), static_cast<int>(in.height));
    if (f.setup.orient == 0) return f;
    f.area2 = (f.p[1].x - f.p[0].x) * (f.p[2].y - f.p[0].y) -
              (f.p[2].x - f.p[0].x) * (f.p[1].y - f.p[0].y);
    f.normal = unit(face_cross(f.p));
    if (f.normal == dvec3(0.0)) f.normal = dvec3(0, 0, -1);  // a sliver below rounding
    if (in.model == Model::Flat) {
        f.flat =
            PhongLighting::shade(in.lighting, (f.p[0] + f.p[1] + f.p[2]) / 3.0, f.normal).intensity;
        ++evaluations;
    }
    return f;
}

// The barycentric coordinates of q in the face's (x, y) projection.
inline std::array<double, 3> barycentric(const Face& f, dvec2 q) {
    if (f.area2 == 0) return {1.0 / 3, 1.0 / 3, 1.0 / 3};  // a sliver whose area rounds to 0
    auto e = [&](dvec3 a, dvec3 b) {
        return (a.x - q.x) * (b.y - q.y) - (b.x - q.x) * (a.y - q.y);
    };
    return {e(f.p[1], f.p[2]) / f.area2, e(f.p[2], f.p[0]) / f.area2, e(f.p[0], f.p[1]) / f.area2};
}

template <class T>
T mix(const std::array<double, 3>& l, const T& a, const T& b, const T& c) {
    return l[0] * a + l[1] * b + l[2] * c;
}

double depth_at(const Face& f, const std::array<double, 3>& l) {
    return mix(l, f.p[0].z, f.p[1].z, f.p[2].z);
}

// Phong: the interpolated normal (not yet normalised: shade normalises it), or the face's
// where the vertex normals cancel.
dvec3 normal_at(const Face& f, const std::vector<dvec3>& normals, const std::array<double, 3>& l) {
    const dvec3 n = mix(l, normals[f.idx[0]], normals[f.idx[1]], normals[f.idx[2]]);
    return n == dvec3(0.0) ? f.normal : n;
}

struct SpanCount {
    int written = 0, hidden = 0;
};

// Draws scanline j's pixels i_first ≤ i < i_end of face f into `row` with the depth test.
[[gnu::always_inline]] inline SpanCount draw_span(const Input& in, const Face& f,
                                                  const std::vector<dvec3>& normals,
                                                  const std::vector<Color>& vertex_colors, int j,
                                                  int i_first, int i_end, Sample* row,
                                                  long long& evaluations) {
    SpanCount count;
    const double y = j + 0.5;
    for (int i = i_first; i < i_end; ++i) {
        const dvec2 q{i + 0.5, y};
        const auto l = barycentric(f, q);
        const double z = depth_at(f, l);
        Sample& s = row[i];
        if (!(z < s.z)) {
            ++count.hidden;
            continue;
        }
        ++count.written;
        s.z = z;
        s.triangle = f.k;
        switch (in.model) {
            case Model::Flat:
                s.color = f.flat;
                break;
            case Model::Gouraud:
                s.color = mix(l, vertex_colors[f.idx[0]], vertex_colors[f.idx[1]],
                              vertex_colors[f.idx[2]]);
                break;
            case Model::Phong:
                s.color =
                    PhongLighting::shade(in.lighting, {q, z}, normal_at(f, normals, l)).intensity;
                ++evaluations;
                break;
        }
    }
    return count;
}

std::vector<Color> light_vertices(const Input& in, const std::vector<dvec3>& normals,
                                  const std::vector<bool>& lit, long long& evaluations) {
    std::vector<Color> colors(in.mesh.vertices.size(), Color(0.0));
    for (std::size_t v = 0; v < colors.size(); ++v)
        if (lit[v]) {
            colors[v] =
                PhongLighting::shade(in.lighting, in.mesh.vertices[v], normals[v]).intensity;
            ++evaluations;
        }
    return colors;
}

}  // namespace

// ---- [advance] ------------------------------------------------------------------------------

void Shading::Image::reset(int width, int height) {
    width_ = width;
    rows_.clear();
    rows_.reserve(static_cast<std::size_t>(height));
    const auto blank = std::make_shared<std::vector<Sample>>(static_cast<std::size_t>(width));
    for (int j = 0; j < height; ++j) rows_.push_back(blank);  // shared until written
}

std::vector<Sample>& Shading::Image::row_for_writing(int j) {
    auto& row = rows_[static_cast<std::size_t>(j)];
    if (row.use_count() > 1) row = std::make_shared<std::vector<Sample>>(*row);
    return *row;
}

bool Shading::Image::operator==(const Image& o) const {
    if (width_ != o.width_ || rows_.size() != o.rows_.size()) return false;
    for (std::size_t j = 0; j < rows_.size(); ++j)
        if (rows_[j] != o.rows_[j] && *rows_[j] != *o.rows_[j]) return false;
    return true;
}

Shading::State Shading::start(const Input& in) {
    check_input(in);
    MeshNormals vn = vertex_normals(in);
    State s;
    s.in = Shared<Input>(in);
    const auto pixel = chosen_pixel(in);
    s.pixel_i = pixel[0], s.pixel_j = pixel[1];
    s.normals = Shared<std::vector<dvec3>>(std::move(vn.normals));
    s.lit = Shared<std::vector<bool>>(std::move(vn.lit));
    s.image.reset(static_cast<int>(in.width), static_cast<int>(in.height));
    s.phase = in.model == Model::Flat
                  ? (in.mesh.triangles.empty() ? Phase::Finish : Phase::Triangle)
                  : Phase::Normals;
    s.last = s.phase;
    return s;
}

namespace {

// After triangle s.face (or its last span, or its chosen pixel): the next triangle, or the end.
void next_triangle(Shading::State& s) {
    s.phase = s.face.k + 1 < static_cast<int>(s.in->mesh.triangles.size()) ? Phase::Triangle
                                                                           : Phase::Finish;
}

void after_span(Shading::State& s) {
    if (s.j + 1 < s.face.setup.j_end)
        s.phase = Phase::Span;
    else
        next_triangle(s);
}

}  // namespace

void Shading::advance(State& s) {
    const Input& in = *s.in;
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Normals:  // The vertex normals (computed by start, which refuses bad ones)
            s.phase = in.model == Model::Gouraud  ? Phase::VertexColors
                      : in.mesh.triangles.empty() ? Phase::Finish
                                                  : Phase::Triangle;
            return;
        case Phase::VertexColors: {  // Gouraud: the lighting at every vertex
            s.vertex_colors =
                Shared<std::vector<Color>>(light_vertices(in, *s.normals, *s.lit, s.evaluations));
            s.phase = in.mesh.triangles.empty() ? Phase::Finish : Phase::Triangle;
            return;
        }
        case Phase::Triangle: {  // Set up the next triangle (flat: its one evaluation)
            s.face = make_face(in, s.face.k + 1, s.evaluations);
            s.j = s.face.setup.j_begin - 1;
            s.written = s.hidden = 0;
            if (s.face.setup.orient != 0 && s.face.setup.j_begin < s.face.setup.j_end)
                s.phase = Phase::Span;
            else
                next_triangle(s);
            return;
        }
        case Phase::Span: {  // One scanline's span, depth-tested pixel by pixel
            const raster::TriangleSetup& t = s.face.setup;
            const raster::TriangleRow r =
                raster::row_at(t.v, t.m, t.orient, ++s.j, static_cast<int>(in.width));
            s.x_left = r.x_left, s.x_right = r.x_right;
            s.i_first = r.i_first, s.i_end = r.i_end;
            s.written = s.hidden = 0;
            const bool chosen = s.j == s.pixel_j && s.pixel_i >= r.i_first && s.pixel_i < r.i_end;
            if (r.i_first < r.i_end) {
                std::vector<Sample>& row = s.image.row_for_writing(s.j);
                if (chosen) {
                    s.pixel_z_old = row[s.pixel_i].z;
                    s.pixel_owner_old = row[s.pixel_i].triangle;
                }
                const SpanCount c = draw_span(in, s.face, *s.normals, *s.vertex_colors, s.j,
                                              r.i_first, r.i_end, row.data(), s.evaluations);
                s.written = c.written, s.hidden = c.hidden;
                s.covered += c.written;
                if (chosen) {
                    s.pixel_won = row[s.pixel_i].triangle == s.face.k;
                    s.pixel_z = depth_at(s.face, barycentric(s.face, {s.pixel_i + 0.5, s.j + 0.5}));
                }
            }
            if (chosen)
                s.phase = Phase::Pixel;
            else
                after_span(s);
            return;
        }
        case Phase::Pixel:  // The chosen pixel in full (drawn with its span)
            after_span(s);
            return;
        case Phase::Finish:
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

void Shading::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [render and result] --------------------------------------------------------------------

// Flattened like run_to_end, so that the comparison is between two fully inlined loops.
[[gnu::flatten]] Shading::Result Shading::render(const Input& in) {
    check_input(in);
    const MeshNormals vn = vertex_normals(in);
    Result r;
    r.model = in.model;
    r.width = static_cast<int>(in.width), r.height = static_cast<int>(in.height);
    r.pixel = chosen_pixel(in);
    r.rgb = in.lighting.rgb;
    r.image.reset(r.width, r.height);
    if (in.model == Model::Gouraud)
        r.vertex_colors = light_vertices(in, vn.normals, vn.lit, r.evaluations);
    for (int k = 0; k < static_cast<int>(in.mesh.triangles.size()); ++k) {
        const Face f = make_face(in, k, r.evaluations);
        const raster::TriangleSetup& t = f.setup;
        if (t.orient == 0) continue;
        for (int j = t.j_begin; j < t.j_end; ++j) {
            const raster::TriangleRow row = raster::row_at(t.v, t.m, t.orient, j, r.width);
            if (row.i_first < row.i_end)
                draw_span(in, f, vn.normals, r.vertex_colors, j, row.i_first, row.i_end,
                          r.image.row_for_writing(j).data(), r.evaluations);
        }
    }
    if (in.model != Model::Flat) {
        r.normals = vn.normals;
        r.lit = vn.lit;
    }
    return r;
}

Shading::Result Shading::result(const State& s) {
    const Input& in = *s.in;
    Result r;
    r.model = in.model;
    r.width = s.image.width(), r.height = s.image.height();
    r.pixel = {s.pixel_i, s.pixel_j};
    r.rgb = in.lighting.rgb;
    r.image = s.image;
    if (in.model == Model::Gouraud) r.vertex_colors = *s.vertex_colors;
    if (in.model != Model::Flat) {
        r.normals = *s.normals;
        r.lit = *s.lit;
    }
    r.evaluations = s.evaluations;
    return r;
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

constexpr int kListed = 4;  // vertices listed by name in a narration, the rest counted

}  // namespace

std::string Shading::model_name(Model m) {
    switch (m) {
        case Model::Flat:
            return "flat";
        case Model::Gouraud:
            return "Gouraud";
        case Model::Phong:
            return "Phong";
    }
    return "";
}

namespace {

// The vertices worth naming: the chosen pixel's triangle's when the run has one, else the
// first few lit ones.
std::vector<int> listed_vertices(const Shading::State& s) {
    const Input& in = *s.in;
    std::vector<int> out;
    for (std::size_t k = 0; k < in.mesh.triangles.size() && out.empty(); ++k) {
        const auto p = corners(in, static_cast<long long>(k));
        if (!has_area(p)) continue;
        const raster::TriangleSetup t =
            raster::setup_triangle(xy(p[0]), xy(p[1]), xy(p[2]), static_cast<int>(in.height));
        if (s.pixel_j < t.j_begin || s.pixel_j >= t.j_end) continue;
        const raster::TriangleRow r =
            raster::row_at(t.v, t.m, t.orient, s.pixel_j, static_cast<int>(in.width));
        if (s.pixel_i >= r.i_first && s.pixel_i < r.i_end)
            for (long long v : in.mesh.triangles[k]) out.push_back(static_cast<int>(v));
    }
    for (std::size_t v = 0; v < s.lit->size() && out.size() < std::size_t(kListed); ++v)
        if ((*s.lit)[v] && std::find(out.begin(), out.end(), int(v)) == out.end())
            out.push_back(static_cast<int>(v));
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

void narrate_normals(const Shading::State& s, StepInfo& info) {
    const Input& in = *s.in;
    const auto& normals = *s.normals;
    const std::vector<int> shown = listed_vertices(s);
    long long lit = 0;
    for (bool b : *s.lit) lit += b;
    info.line = kLineNormals;
    if (!in.mesh.normals.empty()) {
        info.event = "normals-given";
        info.narration = "The vertex normals are given; each is normalised: ";
        for (std::size_t a = 0; a < shown.size(); ++a) {
            const int v = shown[a];
            info.narration += (a ? "; " : "") + std::string("n_") + std::to_string(v) + " = " +
                              num(in.mesh.normals[v], 4) + "/" +
                              num(length_of(in.mesh.normals[v]), 4) + " = " + num(normals[v], 4);
            info.math += (a ? ",\\quad " : "") + std::string("n_{") + std::to_string(v) +
                         "} = " + tex(normals[v], 4);
        }
    } else {
        info.event = "normals-averaged";
        info.narration =
            "No normals are given, so each vertex takes the area-weighted average "
            "of its faces' normals (P1 − P0) × (P2 − P0), each turned to face the "
            "viewer (z < 0) and as long as twice the face's area: ";
        for (std::size_t a = 0; a < shown.size(); ++a) {
            const int v = shown[a];
            std::string faces, sum;
            int n_faces = 0;
            for (std::size_t k = 0; k < in.mesh.triangles.size(); ++k) {
                const auto& t = in.mesh.triangles[k];
                if (t[0] != v && t[1] != v && t[2] != v) continue;
                const auto p = corners(in, static_cast<long long>(k));
                if (!has_area(p)) continue;
                if (n_faces < 4) {
                    faces += (n_faces ? ", " : "") + std::to_string(k);
                    sum += (n_faces ? " + " : "") + num(face_cross(p), 4);
                }
                ++n_faces;
            }
            if (n_faces > 4) faces += ", …", sum += " + …";
            info.narration += (a ? "; " : "") + vname(v) + " (face" + (n_faces == 1 ? " " : "s ") +
                              faces + "): " + sum + " → n_" + std::to_string(v) + " = " +
                              num(normals[v], 4);
            info.math += (a ? ",\\quad " : "") + std::string("n_{") + std::to_string(v) +
                         "} = " + tex(normals[v], 4);
        }
        info.math =
            "n_V = \\frac{\\sum_f (P_1 - P_0) \\times (P_2 - P_0)}{|\\cdot|}:\\quad " + info.math;
    }
    if (lit > static_cast<long long>(shown.size()))
        info.narration +=
            " (and " +
            plural(lit - static_cast<long long>(shown.size()), "more vertex", "more vertices") +
            ")";
    info.narration += ".";
}

void narrate_vertex_colors(const Shading::State& s, StepInfo& info) {
    const Input& in = *s.in;
    const bool rgb = in.lighting.rgb;
    const auto& colors = *s.vertex_colors;
    info.event = "vertex-colors";
    info.line = kLineVertexColors;
    info.narration =
        "Gouraud lights the vertices only: " + plural(s.evaluations, "evaluation", "evaluations") +
        ", one per vertex, each ambient + diffuse + specular: ";
    const std::vector<int> shown = listed_vertices(s);
    for (std::size_t a = 0; a < shown.size(); ++a) {
        const int v = shown[a];
        const auto full = PhongLighting::shade(in.lighting, in.mesh.vertices[v], (*s.normals)[v]);
        info.narration += (a ? "; " : "") + std::string("c_") + std::to_string(v) + " = I(" +
                          num(in.mesh.vertices[v], 4) + ", n_" + std::to_string(v) +
                          ") = " + ctext(full.ambient, rgb) + " + " + ctext(full.diffuse, rgb) +
                          " + " + ctext(full.specular, rgb) + " = " + ctext(colors[v], rgb);
        info.math += (a ? ",\\quad " : "") + std::string("c_{") + std::to_string(v) +
                     "} = " + ctex(colors[v], rgb);
    }
    if (s.evaluations > static_cast<long long>(shown.size()))
        info.narration +=
            " (and " +
            plural(s.evaluations - static_cast<long long>(shown.size()), "more", "more") + ")";
    info.narration += ".";
}

void narrate_triangle(const Shading::State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Face& f = s.face;
    const bool rgb = in.lighting.rgb;
    std::string who = "Triangle " + std::to_string(f.k) + " (";
    for (int m = 0; m < 3; ++m) who += (m ? ", " : "") + vname(f.idx[m]) + " = " + num(f.p[m], 4);
    who += ")";
    if (f.setup.orient == 0) {
        info.event = "degenerate";
        info.line = kLineDegenerate;
        info.narration = who +
                         ": its vertices lie on one line on the screen, so it has no area "
                         "and covers no pixel centre; it is skipped" +
                         std::string(in.model == Model::Flat ? " (no evaluation)." : ".");
        info.math = "(P_1 - P_0) \\times (P_2 - P_0) \\cdot \\hat z = 0";
        return;
    }
    const double area = std::fabs(f.area2) / 2;
    const std::string rows =
        f.setup.j_begin < f.setup.j_end
            ? "its scanlines j = " + std::to_string(f.setup.j_begin) + " to " +
                  std::to_string(f.setup.j_end - 1) + " (y0 < j + ½ ≤ y2, inside the image)"
            : "no scanline centre j + ½ of the image lies within its height, so it draws nothing";
    if (in.model == Model::Flat) {
        const dvec3 c = (f.p[0] + f.p[1] + f.p[2]) / 3.0;
        const dvec3 cross = face_cross(f.p);
        const auto full = PhongLighting::shade(in.lighting, c, f.normal);
        info.event = "flat-face";
        info.line = kLineFlat;
        info.narration =
            who + ", area " + num(area, 4) + " on the screen; " + rows +
            ". Face normal (P1 − P0) × (P2 − P0), turned to the viewer: " + num(cross, 4) +
            " → n_f = " + num(f.normal, 4) + "; at the centroid " + num(c, 4) +
            " the lighting gives " + ctext(full.ambient, rgb) + " + " + ctext(full.diffuse, rgb) +
            " + " + ctext(full.specular, rgb) + " = " + ctext(f.flat, rgb) +
            ", the colour of all its pixels.";
        info.math = "n_f = " + tex(f.normal, 4) + ",\\quad c = I\\left(" + tex(c, 4) +
                    ", n_f\\right) = " + ctex(f.flat, rgb);
        return;
    }
    info.event = "triangle";
    info.line = kLineTriangle;
    info.narration = who + ", area " + num(area, 4) + " on the screen; " + rows + ". ";
    const bool gouraud = in.model == Model::Gouraud;
    info.narration += gouraud ? "Its vertex colours " : "Its vertex normals ";
    for (int m = 0; m < 3; ++m) {
        const int v = f.idx[m];
        info.narration += (m ? ", " : "") +
                          (gouraud ? ctext((*s.vertex_colors)[v], rgb) : num((*s.normals)[v], 4));
        info.math +=
            (m ? ",\\quad " : "") + std::string(gouraud ? "c_{" : "n_{") + std::to_string(v) +
            "} = " + (gouraud ? ctex((*s.vertex_colors)[v], rgb) : tex((*s.normals)[v], 4));
    }
    info.narration += gouraud ? " are interpolated across it."
                              : " are interpolated across it, "
                                "and lit at every pixel.";
}

// The interpolated quantities at (x, y) as the narration shows them.
std::string quantities(const Shading::State& s, dvec2 q) {
    const Input& in = *s.in;
    const auto l = barycentric(s.face, q);
    std::string t = "z = " + num(depth_at(s.face, l), 4);
    if (in.model == Model::Gouraud)
        t += ", c = " +
             ctext(mix(l, (*s.vertex_colors)[s.face.idx[0]], (*s.vertex_colors)[s.face.idx[1]],
                       (*s.vertex_colors)[s.face.idx[2]]),
                   in.lighting.rgb);
    if (in.model == Model::Phong)
        t += ", n = " + num(unit(normal_at(s.face, *s.normals, l)), 3) + " normalised";
    return t;
}

void narrate_span(const Shading::State& s, StepInfo& info) {
    const Input& in = *s.in;
    const double y = s.j + 0.5;
    info.line = kLineSpan;
    info.narration = "Scanline j = " + std::to_string(s.j) + " of triangle " +
                     std::to_string(s.face.k) + ", y = " + num(y) + ": ";
    if (s.i_first >= s.i_end) {
        info.event = "empty-span";
        info.narration += "the span [" + num(s.x_left, 4) + ", " + num(s.x_right, 4) +
                          "): no pixel centre i + ½ of the image lies in it.";
        info.math =
            "\\lceil x_{left} - \\tfrac12 \\rceil \\ge \\lceil x_{right} - \\tfrac12 \\rceil";
        return;
    }
    info.event = "span";
    info.narration += "from x_left = " + num(s.x_left, 4) + " (" + quantities(s, {s.x_left, y}) +
                      ") to x_right = " + num(s.x_right, 4) + " (" + quantities(s, {s.x_right, y}) +
                      "); pixels i = " + std::to_string(s.i_first) + " to " +
                      std::to_string(s.i_end - 1) + ": " + std::to_string(s.written) + " written";
    if (s.hidden) info.narration += ", " + std::to_string(s.hidden) + " hidden by nearer pixels";
    info.narration += in.model == Model::Phong
                          ? " (" + plural(s.written, "evaluation", "evaluations") + ")."
                          : ".";
    info.math = "x_{left} = " + tex(s.x_left, 4) + ",\\quad x_{right} = " + tex(s.x_right, 4) +
                ",\\quad " + tex(double(s.i_first)) + " \\le i \\le " + tex(double(s.i_end - 1));
}

void narrate_pixel(const Shading::State& s, StepInfo& info) {
    const Input& in = *s.in;
    const Face& f = s.face;
    const bool rgb = in.lighting.rgb;
    const dvec2 q{s.pixel_i + 0.5, s.pixel_j + 0.5};
    const auto l = barycentric(f, q);
    info.line = kLineWrite;
    const std::string where =
        "Pixel (" + std::to_string(s.pixel_i) + ", " + std::to_string(s.pixel_j) + "), centre " +
        num(q) + ", in triangle " + std::to_string(f.k) + ": λ = (" + num(l[0], 4) + ", " +
        num(l[1], 4) + ", " + num(l[2], 4) + ") for " + vname(f.idx[0]) + ", " + vname(f.idx[1]) +
        ", " + vname(f.idx[2]) + "; z = Σ λ_k z_k = " + num(s.pixel_z, 4);
    const std::string lam = "\\lambda = (" + tex(l[0], 4) + ", " + tex(l[1], 4) + ", " +
                            tex(l[2], 4) + "),\\quad z = " + tex(s.pixel_z, 4);
    const std::string before = std::isinf(s.pixel_z_old)
                                   ? "the depth buffer there is still ∞"
                                   : "the depth buffer holds " + num(s.pixel_z_old, 4) +
                                         " (triangle " + std::to_string(s.pixel_owner_old) + ")";
    if (!s.pixel_won) {
        info.event = "pixel-hidden";
        info.line = kLineDepth;
        info.narration = where + ", but " + before +
                         ": z is not nearer, so the pixel keeps "
                         "what it has" +
                         (in.model == Model::Phong ? " and no lighting is evaluated." : ".");
        info.math = lam + ",\\quad z \\ge " + tex(s.pixel_z_old, 4);
        return;
    }
    const Color c = s.image.at(s.pixel_i, s.pixel_j).color;
    info.narration = where + "; " + before + ", so z is nearer and the pixel is written. ";
    switch (in.model) {
        case Model::Flat:
            info.event = "pixel-flat";
            info.narration +=
                "Flat: it takes the triangle's colour " + ctext(c, rgb) + ", whatever λ is.";
            info.math = lam + ",\\quad c = " + ctex(c, rgb);
            break;
        case Model::Gouraud: {
            info.event = "pixel-gouraud";
            const auto& vc = *s.vertex_colors;
            info.narration += "Gouraud: c = λ0·c_" + std::to_string(f.idx[0]) + " + λ1·c_" +
                              std::to_string(f.idx[1]) + " + λ2·c_" + std::to_string(f.idx[2]) +
                              " = " + num(l[0], 4) + "·" + ctext(vc[f.idx[0]], rgb) + " + " +
                              num(l[1], 4) + "·" + ctext(vc[f.idx[1]], rgb) + " + " + num(l[2], 4) +
                              "·" + ctext(vc[f.idx[2]], rgb) + " = " + ctext(c, rgb) + ".";
            info.math = lam + ",\\quad c = \\sum_k \\lambda_k c_k = " + ctex(c, rgb);
            break;
        }
        case Model::Phong: {
            info.event = "pixel-phong";
            const dvec3 n = normal_at(f, *s.normals, l);
            const dvec3 P{q, s.pixel_z};
            const auto full = PhongLighting::shade(in.lighting, P, n);
            info.narration +=
                "Phong: n = Σ λ_k n_k = " + num(n, 4) + ", |n| = " + num(glm::length(n), 4) +
                " (shorter than 1 between differing "
                "normals), normalised " +
                num(full.n, 4) + "; at P = " + num(P, 4) + " with v = " + num(full.v, 3);
            for (std::size_t i = 0; i < full.lights.size(); ++i) {
                const auto& t = full.lights[i];
                info.narration += ", light " + std::to_string(i) + ": l·n = " + num(t.n_dot_l, 4) +
                                  ", " +
                                  (in.lighting.model == PhongLighting::Model::Phong
                                       ? "r·v = " + num(t.r_dot_v, 4)
                                       : "h·n = " + num(t.n_dot_h, 4));
            }
            info.narration += "; I = " + ctext(full.ambient, rgb) + " + " +
                              ctext(full.diffuse, rgb) + " + " + ctext(full.specular, rgb) + " = " +
                              ctext(c, rgb) + ".";
            info.math = lam +
                        ",\\quad n = \\frac{\\sum_k \\lambda_k n_k}{|\\cdot|} = " + tex(full.n, 4) +
                        ",\\quad I = " + ctex(c, rgb);
            break;
        }
    }
}

void fill_vars(const Shading::State& s, StepInfo& info) {
    const Input& in = *s.in;
    const bool rgb = in.lighting.rgb;
    info.vars.push_back({"model", std::string(Shading::model_id(in.model))});
    if (s.face.k >= 0) info.vars.push_back({"triangle", static_cast<long long>(s.face.k)});
    if (s.last == Phase::Span || s.last == Phase::Pixel) {
        info.vars.push_back({"j", static_cast<long long>(s.j)});
        info.vars.push_back({"x_left", s.x_left});
        info.vars.push_back({"x_right", s.x_right});
        if (s.i_first < s.i_end) {
            info.vars.push_back({"i_first", static_cast<long long>(s.i_first)});
            info.vars.push_back({"i_last", static_cast<long long>(s.i_end - 1)});
            info.vars.push_back({"written", static_cast<long long>(s.written)});
            info.vars.push_back({"hidden", static_cast<long long>(s.hidden)});
        }
    }
    if (s.last == Phase::Pixel) {
        const auto l = barycentric(s.face, {s.pixel_i + 0.5, s.pixel_j + 0.5});
        info.vars.push_back({"pixel", std::vector<double>{double(s.pixel_i), double(s.pixel_j)}});
        info.vars.push_back({"lambda", std::vector<double>{l[0], l[1], l[2]}});
        info.vars.push_back({"z", s.pixel_z});
        if (s.pixel_won)
            info.vars.push_back({"color", cvalue(s.image.at(s.pixel_i, s.pixel_j).color, rgb)});
    }
    if (s.last == Phase::Triangle && in.model == Model::Flat && s.face.setup.orient != 0) {
        info.vars.push_back({"n_f", vec(s.face.normal)});
        info.vars.push_back({"flat_color", cvalue(s.face.flat, rgb)});
    }
    info.vars.push_back({"covered", s.covered});
    info.vars.push_back({"evaluations", s.evaluations});
}

}  // namespace

void Shading::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    switch (s.last) {
        case Phase::Normals:
            narrate_normals(s, info);
            break;
        case Phase::VertexColors:
            narrate_vertex_colors(s, info);
            break;
        case Phase::Triangle:
            narrate_triangle(s, info);
            break;
        case Phase::Span:
            narrate_span(s, info);
            break;
        case Phase::Pixel:
            narrate_pixel(s, info);
            break;
        case Phase::Finish:
        case Phase::Done: {
            const Input& in = *s.in;
            info.event = "done";
            info.line = kLineDone;
            const char* per = in.model == Model::Flat      ? "one per triangle with area"
                              : in.model == Model::Gouraud ? "one per vertex"
                                                           : "one per pixel written";
            info.narration =
                "Every triangle is drawn: " + plural(s.covered, "pixel write", "pixel writes") +
                ", " + plural(s.evaluations, "lighting evaluation", "lighting evaluations") + " (" +
                model_name(in.model) + ": " + per +
                "). The colours are "
                "kept unclamped; the picture clamps them to [0, 1].";
            info.math = "\\text{evaluations} = " + std::to_string(s.evaluations);
            break;
        }
    }
    fill_vars(s, info);
}

}  // namespace cg
