// Sections: [helpers] [geometry] [spec] [validate] [advance] [narrate] [result and solve]
// (the picture: shadow_volume_draw.cpp)
#include "shadows/shadow_volume.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <utility>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec3;
using Phase = ShadowVolume::Phase;
using Input = ShadowVolume::Input;
using Mesh = ShadowVolume::Mesh;
using State = ShadowVolume::State;
using Crossing = ShadowVolume::Crossing;
using Ray = ShadowVolume::Ray;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineFace = 1,
    kLineEdge,
    kLineSilhouette,
    kLineRay,
    kLineStart,
    kLineCross,
    kLineVerdict
};

bool finite3(const dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
std::vector<double> vec3(const dvec3& v) {
    return {v.x, v.y, v.z};
}
std::string idx(int k) {
    return std::to_string(k);
}
std::string edge_text(int a, int b) {
    return "(" + idx(a) + ", " + idx(b) + ")";
}
std::string surface_text(int surface) {
    if (surface == ShadowVolume::kFloor) return "the floor";
    if (surface == ShadowVolume::kNone) return "nothing";
    return "face " + idx(surface);
}

void check_point(const dvec3& p, const std::string& field) {
    for (int i = 0; i < 3; ++i) {
        const std::string f = field + "[" + idx(i) + "]";
        if (!std::isfinite(p[i]))
            throw InputError(f, "must be a finite number (got " + given(p[i]) + ")");
        if (std::fabs(p[i]) > ShadowVolume::kMaxCoordinate)
            throw InputError(f, "is too large (" + given(p[i]) +
                                    "): coordinates must be at most 1e9 in size, or the "
                                    "shadow volume's products lose all precision");
    }
}

// ---- [geometry] -----------------------------------------------------------------------------

// Möller–Trumbore: where the line o + t d meets triangle (a, b, c); false when parallel or
// outside (the edges count as inside).
bool ray_triangle(const dvec3& o, const dvec3& d, const dvec3& a, const dvec3& b, const dvec3& c,
                  double& t) {
    const dvec3 e1 = b - a, e2 = c - a;
    const dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (det == 0) return false;
    const double inv = 1.0 / det;
    const dvec3 s = o - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0 || u > 1) return false;
    const dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) * inv;
    if (v < 0 || u + v > 1) return false;
    t = glm::dot(e2, q) * inv;
    return std::isfinite(t);
}

// The generalised winding number of a closed mesh around p (solid angles, Van Oosterom and
// Strackee): 1 inside, 0 outside, ½ on a face.
double winding(const Input& in, const dvec3& p) {
    double sum = 0;
    for (const auto& f : in.faces) {
        const dvec3 a = in.vertices[f[0]] - p, b = in.vertices[f[1]] - p, c = in.vertices[f[2]] - p;
        const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
        const double det = glm::dot(a, glm::cross(b, c));
        const double den =
            la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
        sum += 2 * std::atan2(det, den);
    }
    return sum / (4 * std::numbers::pi);
}

// The face p lies on (coplanar and inside or on its edges), or −1.
int face_containing(const Input& in, const Mesh& mesh, const dvec3& p) {
    for (std::size_t f = 0; f < in.faces.size(); ++f) {
        const dvec3 a = in.vertices[in.faces[f][0]], b = in.vertices[in.faces[f][1]],
                    c = in.vertices[in.faces[f][2]];
        const dvec3 n = mesh.normals[f];
        if (glm::dot(n, p - a) != 0) continue;
        if (glm::dot(glm::cross(b - a, p - a), n) >= 0 &&
            glm::dot(glm::cross(c - b, p - b), n) >= 0 &&
            glm::dot(glm::cross(a - c, p - c), n) >= 0)
            return int(f);
    }
    return -1;
}

double facing(const Input& in, const Mesh& mesh, int f) {
    return glm::dot(mesh.normals[f], in.light - in.vertices[in.faces[f][0]]);
}

std::array<int, 2> quad_of(const ShadowVolume::Edge& e, const std::vector<std::uint8_t>& lit) {
    return lit[e.f] ? std::array<int, 2>{e.a, e.b} : std::array<int, 2>{e.b, e.a};
}

dvec3 quad_normal(const Input& in, const std::array<int, 2>& q) {
    return glm::cross(in.vertices[q[0]] - in.light, in.vertices[q[1]] - in.light);
}

}  // namespace

ShadowVolume::Mesh ShadowVolume::build_mesh(const Input& in) {
    Mesh m;
    m.normals.reserve(in.faces.size());
    std::map<std::pair<int, int>, int> seen;  // undirected (min, max) → edge index
    for (std::size_t f = 0; f < in.faces.size(); ++f) {
        const auto& t = in.faces[f];
        m.normals.push_back(glm::cross(in.vertices[t[1]] - in.vertices[t[0]],
                                       in.vertices[t[2]] - in.vertices[t[0]]));
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            const auto key = std::minmax(a, b);
            const auto it = seen.find(key);
            if (it == seen.end()) {
                seen.emplace(key, int(m.edges.size()));
                m.edges.push_back({a, b, int(f), -1});
            } else {
                m.edges[it->second].g = int(f);
            }
        }
    }
    return m;
}

ShadowVolume::Ray ShadowVolume::first_hit(const Input& in, const Mesh& mesh, const dvec3& target) {
    Ray r;
    const dvec3 d = target - in.eye;
    double best = INFINITY;
    if (in.has_floor && d.y != 0) {
        const double t = (in.floor - in.eye.y) / d.y;
        if (t > 0 && std::isfinite(t)) best = t, r.surface = kFloor;
    }
    for (std::size_t f = 0; f < in.faces.size(); ++f) {
        double t;
        if (ray_triangle(in.eye, d, in.vertices[in.faces[f][0]], in.vertices[in.faces[f][1]],
                         in.vertices[in.faces[f][2]], t) &&
            t > 0 && t < best)
            best = t, r.surface = int(f);
    }
    (void)mesh;
    if (r.surface != kNone) {
        r.t_hit = best;
        r.hit = in.eye + best * d;
        if (r.surface == kFloor) r.hit.y = in.floor;
    }
    return r;
}

int ShadowVolume::cones_containing(const Input& in, const std::vector<std::uint8_t>& lit,
                                   const dvec3& p, int skip, bool any_face) {
    const dvec3 d = in.light - p;
    int n = 0;
    for (std::size_t f = 0; f < in.faces.size(); ++f) {
        if (int(f) == skip || !(any_face || lit[f])) continue;
        double t;
        if (ray_triangle(p, d, in.vertices[in.faces[f][0]], in.vertices[in.faces[f][1]],
                         in.vertices[in.faces[f][2]], t) &&
            t > 0 && t < 1) {
            ++n;
            if (any_face) return n;  // a shadow ray: blocked is enough
        }
    }
    return n;
}

std::vector<ShadowVolume::Crossing> ShadowVolume::crossings(
    const Input& in, const std::vector<std::array<int, 2>>& silhouette, const dvec3& target) {
    std::vector<Crossing> out;
    const dvec3 d = target - in.eye;
    for (std::size_t q = 0; q < silhouette.size(); ++q) {
        const dvec3 A = in.vertices[silhouette[q][0]] - in.light,
                    B = in.vertices[silhouette[q][1]] - in.light;
        const dvec3 n = glm::cross(A, B);
        const double den = glm::dot(n, d);
        if (den == 0) continue;  // the ray runs in the quad's plane
        const double t = glm::dot(n, in.light - in.eye) / den;
        if (!(t > 0) || !std::isfinite(t)) continue;
        const dvec3 X = in.eye + t * d - in.light;  // X − L = α A + β B
        const double nn = glm::dot(n, n);
        const double alpha = glm::dot(glm::cross(X, B), n) / nn;
        const double beta = glm::dot(glm::cross(A, X), n) / nn;
        if (alpha >= 0 && beta >= 0 && alpha + beta >= 1)
            out.push_back({t, int(q), den < 0 ? +1 : -1});
    }
    std::sort(out.begin(), out.end(), [](const Crossing& a, const Crossing& b) {
        return a.t != b.t ? a.t < b.t : a.quad < b.quad;
    });
    return out;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& ShadowVolume::spec() {
    static const Spec spec{
        "shadow-volume",
        "Shadow volumes: silhouette, shadow quads and the stencil count",
        "Shadows",
        {
            "for each face f = (a, b, c):  n_f ← (b − a) × (c − a);  lit(f) ← n_f · (L − a) > 0",
            "for each edge (a, b) shared by faces f and g:",
            "    if lit(f) ≠ lit(g): silhouette; (a, b) as in the lit face; quad a, b, b∞, a∞;  "
            "n_q ← (a − L) × (b − L)",
            "for each eye ray E + t d:  P ← the first surface point (floor or occluder), at t_P",
            "    count ← the number of shadow volumes containing E   ▷ 0 when the eye is lit",
            "    for each quad crossed at 0 < t < t_P, in order:  count += (n_q · d < 0 ? +1 : −1)",
            "    in shadow ⟺ count > 0      ▷ the same as: the shadow ray from P to L is blocked",
        },
        {
            {"lit", "the face faces the light: n_f · (L − a) > 0"},
            {"unlit",
             "the face faces away from the light (or is edge-on to it): n_f · (L − a) ≤ 0"},
            {"silhouette",
             "the edge's two faces disagree: a silhouette edge; its shadow quad is extruded away "
             "from the light, with outward normal n_q = (a − L) × (b − L)"},
            {"inner-edge", "both faces lit or both unlit: not a silhouette edge, no quad"},
            {"ray",
             "the eye ray's first surface point P; the eye is lit, so the count starts at 0"},
            {"eye-in-shadow",
             "the eye itself is inside the shadow volume: the count starts at the number of "
             "volumes containing it, not 0 (plain z-pass would be wrong)"},
            {"miss", "the eye ray meets no surface: nothing to shade, no count"},
            {"enter", "a front-facing shadow quad passed before P (n_q · d < 0): +1"},
            {"leave", "a back-facing shadow quad passed before P (n_q · d > 0): −1"},
            {"verdict", "count > 0: in shadow; checked against the shadow ray from P to the light"},
        },
        {},  // no sliders
        {
            .predict = {{"lit", {"lit"}},
                        {"silhouette", {"silhouette"}},
                        {"inner-edge", {"silhouette"}},
                        {"enter", {"count"}},
                        {"leave", {"count"}},
                        {"verdict", {"count", "in_shadow"}}},
            .mistakes =
                {
                    {"leave", "delta", "negate",
                     "counted a back-facing shadow face (leaving the volume) as +1"},
                    {"inner-edge", "silhouette", "not",
                     "took an edge whose two faces both face the light (or both face away) as a "
                     "silhouette edge"},
                    {"verdict", "count", "copy:count_all",
                     "also counted the shadow faces behind the surface point (where the depth "
                     "test fails)"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void ShadowVolume::validate(const Input& in) {
    const std::size_t nv = in.vertices.size(), nf = in.faces.size();
    if (nv < 4 || nv > kMaxVertices)
        throw InputError("occluder.vertices", "must have 4 to " + std::to_string(kMaxVertices) +
                                                  " vertices (got " + std::to_string(nv) + ")");
    if (nf < 4 || nf > kMaxFaces)
        throw InputError("occluder.faces", "must have 4 to " + std::to_string(kMaxFaces) +
                                               " triangles (got " + std::to_string(nf) +
                                               "): a closed mesh needs at least 4");
    for (std::size_t k = 0; k < nv; ++k)
        check_point(in.vertices[k], "occluder.vertices[" + std::to_string(k) + "]");
    check_point(in.light, "light");
    check_point(in.eye, "eye");
    if (in.targets.empty()) throw InputError("targets", "must list at least one point to look at");
    if (in.targets.size() > kMaxRays)
        throw InputError("targets", "has " + std::to_string(in.targets.size()) +
                                        " points; at most " + std::to_string(kMaxRays) +
                                        " rays are stepped");
    for (std::size_t k = 0; k < in.targets.size(); ++k)
        check_point(in.targets[k], "targets[" + std::to_string(k) + "]");
    if (in.has_floor) {
        if (!std::isfinite(in.floor))
            throw InputError("floor", "must be a finite number (got " + given(in.floor) + ")");
        if (std::fabs(in.floor) > kMaxCoordinate)
            throw InputError("floor", "is too large (" + given(in.floor) +
                                          "): coordinates must be at most 1e9 in size");
    }
    // Faces: indices in range and distinct, non-zero area.
    for (std::size_t f = 0; f < nf; ++f) {
        const auto& t = in.faces[f];
        const std::string field = "occluder.faces[" + std::to_string(f) + "]";
        for (int i = 0; i < 3; ++i)
            if (t[i] < 0 || std::size_t(t[i]) >= nv)
                throw InputError(field + "[" + idx(i) + "]", "vertex index " + idx(t[i]) +
                                                                 " is out of range (there are " +
                                                                 std::to_string(nv) + " vertices)");
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            throw InputError(field, "repeats a vertex (" + idx(t[0]) + ", " + idx(t[1]) + ", " +
                                        idx(t[2]) + "): a face needs three different vertices");
        const dvec3 n = glm::cross(in.vertices[t[1]] - in.vertices[t[0]],
                                   in.vertices[t[2]] - in.vertices[t[0]]);
        if (n == dvec3(0))
            throw InputError(field,
                             "has zero area (its three vertices are collinear or equal): "
                             "it has no normal, so it can neither face the light nor "
                             "away");
        if (!finite3(n)) throw InputError(field, "is too large: its normal overflows a double");
    }
    // Closed and consistently oriented: every directed edge once, and its reverse once.
    std::map<std::pair<int, int>, int> directed;
    for (std::size_t f = 0; f < nf; ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = in.faces[f][k], b = in.faces[f][(k + 1) % 3];
            const auto [it, fresh] = directed.emplace(std::pair{a, b}, int(f));
            if (!fresh)
                throw InputError("occluder.faces[" + std::to_string(f) + "]",
                                 "runs the edge " + edge_text(a, b) +
                                     " in the same direction as face " + idx(it->second) +
                                     ": the faces are not consistently oriented (or more than "
                                     "two faces share the edge)");
        }
    for (const auto& [e, f] : directed)
        if (!directed.count({e.second, e.first}))
            throw InputError("occluder.faces[" + std::to_string(f) + "]",
                             "its edge " + edge_text(e.first, e.second) +
                                 " has no neighbouring face (no face runs " +
                                 edge_text(e.second, e.first) +
                                 "): the mesh is not closed, so it bounds no volume");
    double volume = 0;
    for (const auto& t : in.faces)
        volume += glm::dot(in.vertices[t[0]], glm::cross(in.vertices[t[1]], in.vertices[t[2]]));
    if (!(volume > 0))
        throw InputError("occluder.faces",
                         volume < 0 ? "wind clockwise seen from outside (the signed volume is "
                                      "negative): list each face's vertices counter-clockwise "
                                      "seen from outside"
                                    : "enclose no volume (the signed volume is 0)");
    const Mesh mesh = build_mesh(in);
    if (const int f = face_containing(in, mesh, in.light); f >= 0)
        throw InputError("light", "lies on face " + idx(f) +
                                      " of the occluder: that face is neither lit nor dark; "
                                      "move the light off the surface");
    if (winding(in, in.light) > 0.5)
        throw InputError("light",
                         "is inside the occluder: every face faces away from it and "
                         "the whole world outside is dark; move the light outside");
    if (const int f = face_containing(in, mesh, in.eye); f >= 0)
        throw InputError("eye", "lies on face " + idx(f) + " of the occluder");
    if (winding(in, in.eye) > 0.5)
        throw InputError("eye", "is inside the occluder: every eye ray meets a face from behind");
    for (std::size_t k = 0; k < in.targets.size(); ++k)
        if (in.targets[k] == in.eye)
            throw InputError("targets[" + std::to_string(k) + "]",
                             "equals the eye, so there is no ray to follow");
}

ShadowVolume::State ShadowVolume::start(const Input& in) {
    validate(in);
    State s;
    s.in = Shared<Input>(in);
    s.mesh = Shared<Mesh>(build_mesh(in));
    s.lit.reserve(in.faces.size());
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

namespace {

void begin_ray(State& s) {
    const Input& in = *s.in;
    const dvec3 target = in.targets[s.ray];
    s.current = ShadowVolume::first_hit(in, *s.mesh, target);
    s.crossings.clear();
    s.behind = 0;
    s.cross = -1;
    if (s.current.surface == ShadowVolume::kNone) {
        s.count = 0;
        return;
    }
    s.current.start = ShadowVolume::cones_containing(in, s.lit, in.eye, -1, false);
    s.count = s.current.start;
    for (const Crossing& c : ShadowVolume::crossings(in, s.silhouette, target)) {
        if (c.t < s.current.t_hit)
            s.crossings.push_back(c);
        else
            ++s.behind;
    }
}

void finish_ray(State& s) {
    const Input& in = *s.in;
    Ray r = s.current;
    r.behind = s.behind;
    r.count = s.count;
    r.crossings.clear();
    for (const Crossing& c : s.crossings) r.crossings.push_back(c.sign);
    r.in_shadow = s.count > 0;
    r.shadow_ray = r.surface != ShadowVolume::kNone &&
                   ShadowVolume::cones_containing(in, s.lit, r.hit, r.surface, true) > 0;
    s.rays.push_back(std::move(r));
}

}  // namespace

void ShadowVolume::advance(State& s) {
    const Input& in = *s.in;
    const Mesh& mesh = *s.mesh;
    auto next_ray = [&] {
        ++s.ray;
        if (std::size_t(s.ray) >= in.targets.size()) {
            s.phase = Phase::Done;
        } else {
            s.phase = Phase::RayStart;
        }
    };
    switch (s.phase) {
        case Phase::Face:
            ++s.face;
            s.lit.push_back(facing(in, mesh, s.face) > 0);
            s.last = Phase::Face;
            if (std::size_t(s.face) + 1 == in.faces.size()) s.phase = Phase::Edge;
            return;
        case Phase::Edge: {
            ++s.edge;
            const Edge& e = mesh.edges[s.edge];
            if (s.lit[e.f] != s.lit[e.g]) s.silhouette.push_back(quad_of(e, s.lit));
            s.last = Phase::Edge;
            if (std::size_t(s.edge) + 1 == mesh.edges.size()) next_ray();
            return;
        }
        case Phase::RayStart:
            begin_ray(s);
            s.last = Phase::RayStart;
            if (s.current.surface == kNone) {
                finish_ray(s);
                next_ray();
            } else {
                s.phase = s.crossings.empty() ? Phase::Verdict : Phase::Crossing;
            }
            return;
        case Phase::Crossing:
            ++s.cross;
            s.count += s.crossings[s.cross].sign;
            s.last = Phase::Crossing;
            if (std::size_t(s.cross) + 1 == s.crossings.size()) s.phase = Phase::Verdict;
            return;
        case Phase::Verdict:
            finish_ray(s);
            s.last = Phase::Verdict;
            next_ray();
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

void narrate_face(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const int f = s.face;
    const auto& t = in.faces[f];
    const dvec3 n = s.mesh->normals[f];
    const double v = glm::dot(n, in.light - in.vertices[t[0]]);
    const bool lit = s.lit[f];
    info.event = lit ? "lit" : "unlit";
    info.line = kLineFace;
    info.narration = "Face " + idx(f) + " = (" + idx(t[0]) + ", " + idx(t[1]) + ", " + idx(t[2]) +
                     "): n_f = (b − a) × (c − a) = " + num(n, 4) +
                     ", n_f · (L − a) = " + num(v, 4) +
                     (lit      ? " > 0: it faces the light (lit)."
                      : v == 0 ? " = 0: the light is in its plane (edge-on); it counts as facing "
                                 "away — its cone of shadow is flat."
                               : " < 0: it faces away from the light (dark).");
    info.math = "n_f \\cdot (L - a) = " + tex(v, 4) + (lit ? " > 0" : " \\le 0");
    info.vars = {{"f", (long long)f}, {"n_f", vec3(n)}, {"n·(L−a)", v}, {"lit", lit}};
}

void narrate_edge(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const auto& e = s.mesh->edges[s.edge];
    const bool lf = s.lit[e.f], lg = s.lit[e.g];
    const bool sil = lf != lg;
    info.line = sil ? kLineSilhouette : kLineEdge;
    info.vars = {{"edge", std::vector<double>{double(e.a), double(e.b)}},
                 {"faces", std::vector<double>{double(e.f), double(e.g)}},
                 {"lit(f)", lf},
                 {"lit(g)", lg},
                 {"silhouette", sil}};
    const std::string head = "Edge " + edge_text(e.a, e.b) + " between face " + idx(e.f) + " (" +
                             (lf ? "lit" : "dark") + ") and face " + idx(e.g) + " (" +
                             (lg ? "lit" : "dark") + ")";
    if (!sil) {
        info.event = "inner-edge";
        info.narration = head + ": both " + (lf ? "lit" : "dark") +
                         ", so it is not on the silhouette and casts no shadow quad.";
        info.math = "\\mathrm{lit}(f) = \\mathrm{lit}(g)";
        return;
    }
    const auto& q = s.silhouette.back();
    const dvec3 n = quad_normal(in, q);
    info.event = "silhouette";
    info.narration = head + ": they disagree, a silhouette edge. Taken as " +
                     edge_text(q[0], q[1]) + " (as it runs in the lit face), its quad runs from " +
                     num(in.vertices[q[0]], 4) + " and " + num(in.vertices[q[1]], 4) +
                     " away from the light to infinity, with outward normal n_q = (a − L) × (b − "
                     "L) = " +
                     num(n, 4) + ". Quads so far: " + std::to_string(s.silhouette.size()) + ".";
    info.math = "n_q = (a - L) \\times (b - L) = " + tex(n, 4);
    info.vars.push_back({"quad", std::vector<double>{double(q[0]), double(q[1])}});
    info.vars.push_back({"n_q", vec3(n)});
}

void ray_vars(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const dvec3 target = in.targets[s.ray];
    info.vars = {{"k", (long long)s.ray},
                 {"E", vec3(in.eye)},
                 {"d", vec3(target - in.eye)},
                 {"surface", surface_text(s.current.surface)}};
    if (s.current.surface != ShadowVolume::kNone) {
        info.vars.push_back({"t_P", s.current.t_hit});
        info.vars.push_back({"P", vec3(s.current.hit)});
    }
}

void narrate_ray(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    ray_vars(s, info);
    const std::string head = "Eye ray " + idx(s.ray) + " from E = " + num(in.eye, 4) + " through " +
                             num(in.targets[s.ray], 4);
    if (s.current.surface == ShadowVolume::kNone) {
        info.event = "miss";
        info.line = kLineRay;
        info.narration = head +
                         " meets no surface: the pixel shows the background, nothing to "
                         "shade, so no count is taken.";
        info.math.clear();
        return;
    }
    const int n = int(s.crossings.size());
    std::string tail =
        "; " + std::to_string(n) + (n == 1 ? " shadow quad lies" : " shadow quads lie") +
        " between the eye and P" +
        (s.behind ? " (" + std::to_string(s.behind) + " more behind P, not counted)" : "") + ".";
    info.line = kLineStart;
    if (s.current.start == 0) {
        info.event = "ray";
        info.narration = head + " first meets " + surface_text(s.current.surface) +
                         " at P = " + num(s.current.hit, 4) + " (t_P = " + num(s.current.t_hit, 4) +
                         "). The eye is lit (its own shadow ray meets no lit face), so the count "
                         "starts at 0, the stencil's clear value" +
                         tail;
    } else {
        info.event = "eye-in-shadow";
        info.narration =
            head + " first meets " + surface_text(s.current.surface) +
            " at P = " + num(s.current.hit, 4) + " (t_P = " + num(s.current.t_hit, 4) +
            "). The eye itself is in shadow: the segment from E to the light crosses " +
            std::to_string(s.current.start) + " lit face(s), so the count starts at " +
            std::to_string(s.current.start) +
            " — a stencil cleared to 0 (plain z-pass) would get this pixel wrong; renderers "
            "count from P away from the eye instead (z-fail)" +
            tail;
    }
    info.math = "P = E + t_P\\,d = " + tex(s.current.hit, 4) +
                ",\\; \\mathrm{count} = " + std::to_string(s.current.start);
    info.vars.push_back({"count", (long long)s.count});
}

void narrate_cross(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    ray_vars(s, info);
    const Crossing& c = s.crossings[s.cross];
    const auto& q = s.silhouette[c.quad];
    const dvec3 d = in.targets[s.ray] - in.eye;
    const dvec3 n = quad_normal(in, q);
    const dvec3 X = in.eye + c.t * d;
    const double nd = glm::dot(n, d);
    info.event = c.sign > 0 ? "enter" : "leave";
    info.line = kLineCross;
    info.narration = "At t = " + num(c.t, 4) + " < t_P = " + num(s.current.t_hit, 4) +
                     " the ray crosses the quad of edge " + edge_text(q[0], q[1]) + " at " +
                     num(X, 4) + ": n_q · d = " + num(nd, 4) +
                     (c.sign > 0 ? " < 0, front-facing — the ray enters the shadow volume: +1"
                                 : " > 0, back-facing — the ray leaves the shadow volume: −1") +
                     ", count = " + std::to_string(s.count) + ".";
    info.math = "n_q \\cdot d = " + tex(nd, 4) +
                ",\\; \\mathrm{count} = " + std::to_string(s.count - c.sign) +
                (c.sign > 0 ? " + 1" : " - 1") + " = " + std::to_string(s.count);
    info.vars.push_back({"quad", std::vector<double>{double(q[0]), double(q[1])}});
    info.vars.push_back({"t", c.t});
    info.vars.push_back({"X", vec3(X)});
    info.vars.push_back({"n_q·d", nd});
    info.vars.push_back({"delta", (long long)c.sign});
    info.vars.push_back({"count", (long long)s.count});
}

void narrate_verdict(const State& s, StepInfo& info) {
    ray_vars(s, info);
    const Ray& r = s.rays.back();
    std::string signs;
    for (int v : r.crossings) signs += (v > 0 ? " + 1" : " − 1");
    int all = r.count;
    {  // the wrong count that also takes the quads behind P
        const Input& in = *s.in;
        for (const Crossing& c : ShadowVolume::crossings(in, s.silhouette, in.targets[s.ray]))
            if (!(c.t < r.t_hit)) all += c.sign;
    }
    info.event = "verdict";
    info.line = kLineVerdict;
    const std::string sum =
        r.crossings.empty()
            ? "count = " + std::to_string(r.count) + " (no shadow quad passed before P)"
            : "count = " + std::to_string(r.start) + signs + " = " + std::to_string(r.count);
    info.narration =
        sum +
        (r.in_shadow ? ", > 0: P = " + num(r.hit, 4) +
                           " is in shadow (the stencil is non-zero, the lit pass skips it)."
                     : std::string(r.count == 0 ? ", = 0" : ", ≤ 0") + ": P = " + num(r.hit, 4) +
                           " is lit.") +
        " The shadow ray from P to the light is " +
        (r.shadow_ray ? "blocked by the occluder" : "clear") +
        (r.shadow_ray == r.in_shadow ? ": the same verdict." : ": they DISAGREE (a grazing ray).") +
        (r.behind ? " The " + std::to_string(r.behind) +
                        " quad crossing(s) behind P are not counted (they fail the depth test)."
                  : "");
    info.math =
        "\\mathrm{count} = " + std::to_string(r.count) +
        (r.in_shadow ? " > 0 \\Rightarrow \\text{in shadow}" : " = 0 \\Rightarrow \\text{lit}");
    info.vars.push_back({"count", (long long)r.count});
    info.vars.push_back({"count_all", (long long)all});
    info.vars.push_back({"in_shadow", r.in_shadow});
    info.vars.push_back({"shadow_ray", r.shadow_ray});
}

}  // namespace

void ShadowVolume::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Face:
            narrate_face(s, info);
            break;
        case Phase::Edge:
            narrate_edge(s, info);
            break;
        case Phase::RayStart: {
            // A miss has already been recorded and the next ray begun: narrate from the record.
            if (s.rays.size() > 0 && s.rays.back().surface == kNone &&
                (s.phase != Phase::Crossing && s.phase != Phase::Verdict)) {
                State t = s;
                t.ray = int(s.rays.size()) - 1;
                t.current = s.rays.back();
                narrate_ray(t, info);
            } else {
                narrate_ray(s, info);
            }
            break;
        }
        case Phase::Crossing:
            narrate_cross(s, info);
            break;
        case Phase::Verdict:
        case Phase::Done: {
            State t = s;
            t.ray = int(s.rays.size()) - 1;
            t.current = s.rays.back();
            narrate_verdict(t, info);
            break;
        }
    }
}

void ShadowVolume::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and solve] ---------------------------------------------------------------------

ShadowVolume::Result ShadowVolume::result(const State& s) {
    Result r;
    r.lit.assign(s.lit.begin(), s.lit.end());
    r.silhouette = s.silhouette;
    r.rays = s.rays;
    return r;
}

ShadowVolume::Result ShadowVolume::result(State&& s) {
    Result r;
    r.lit.assign(s.lit.begin(), s.lit.end());
    r.silhouette = std::move(s.silhouette);
    r.rays = std::move(s.rays);
    return r;
}

ShadowVolume::Result ShadowVolume::solve(const Input& in) {
    validate(in);
    const Mesh mesh = build_mesh(in);
    Result r;
    std::vector<std::uint8_t> lit(in.faces.size());
    for (std::size_t f = 0; f < in.faces.size(); ++f) lit[f] = facing(in, mesh, int(f)) > 0;
    r.lit.assign(lit.begin(), lit.end());
    for (const Edge& e : mesh.edges)
        if (lit[e.f] != lit[e.g]) r.silhouette.push_back(quad_of(e, lit));
    const int start = cones_containing(in, lit, in.eye, -1, false);
    for (const dvec3& target : in.targets) {
        Ray ray = first_hit(in, mesh, target);
        if (ray.surface != kNone) {
            ray.start = start;
            ray.count = start;
            for (const Crossing& c : crossings(in, r.silhouette, target)) {
                if (c.t < ray.t_hit) {
                    ray.crossings.push_back(c.sign);
                    ray.count += c.sign;
                } else {
                    ++ray.behind;
                }
            }
            ray.in_shadow = ray.count > 0;
            ray.shadow_ray = cones_containing(in, lit, ray.hit, ray.surface, true) > 0;
        }
        r.rays.push_back(std::move(ray));
    }
    return r;
}

}  // namespace cg
