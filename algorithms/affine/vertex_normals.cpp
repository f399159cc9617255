// Sections: [spec] [validate] [the arithmetic] [step] [narrate]; the picture is in
// vertex_normals_draw.cpp
#include "affine/vertex_normals.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "rays/quadric.hpp"  // unit(): v/|v| without overflow, 0 for 0

namespace cg {

namespace {

using glm::dvec3;
using FaceNormal = VertexNormals::FaceNormal;
using VertexSums = VertexNormals::VertexSums;
using Weighting = VertexNormals::Weighting;

constexpr double kPi = 3.14159265358979323846;

enum Line { kLineFace = 1, kLineNormal, kLineAngles, kLineVertex, kLineSums, kLineNormalise };

std::string fname(long long k) {
    return "F" + std::to_string(k);
}
std::string vname(long long v) {
    return "V" + std::to_string(v);
}
// |v| without overflow: the cross products of coordinates near ±1e100 reach 10²⁰⁰, whose
// square does not fit a double.
double norm(dvec3 v) {
    const double m = std::max(std::max(std::fabs(v.x), std::fabs(v.y)), std::fabs(v.z));
    if (m == 0) return 0;
    v /= m;
    return m * std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

double deg(double rad) {
    return rad * (180.0 / kPi);
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const char* VertexNormals::weighting_id(Weighting w) {
    switch (w) {
        case Weighting::Unweighted:
            return "unweighted";
        case Weighting::Area:
            return "area";
        case Weighting::Angle:
            return "angle";
    }
    return "area";
}

const Spec& VertexNormals::spec() {
    static const Spec spec{
        "vertex-normals",
        "Vertex normals: averaging the face normals around a vertex",
        "Affine Geometry",
        {
            "for each face f:",
            "    N_f ← (P1 − P0) × (P2 − P0) (triangle) or Newell's Σ (P_i − P0) × (P_i+1 − P0)",
            "    A_f ← |N_f| / 2, n_f ← N_f / |N_f| (none when N_f = 0); θ at each corner",
            "for each vertex V:",
            "    sums over V's faces with a normal: Σ n_f, Σ A_f n_f, Σ θ_f n_f",
            "    n_V ← each sum / its length (none when there is no face or the sum cancels)",
        },
        {
            {"face", "a triangle's normal from the cross product of two edges"},
            {"face-newell", "a polygon's normal by Newell's method (every edge counts)"},
            {"face-degenerate", "a face of zero area: no normal, it contributes nothing"},
            {"vertex", "a vertex's three averages, each normalised"},
            {"vertex-cancelled",
             "a vertex whose faces' normals cancel (opposite windings) under some weighting"},
            {"vertex-isolated", "a vertex of no face with area: its normal is undefined"},
        },
        {},  // no sliders
        {
            .predict = {{"face", {"area"}},
                        {"face-newell", {"area"}},
                        {"vertex", {"n_area", "n_angle"}}},
            .mistakes =
                {
                    {"vertex", "n_unweighted", "copy:sum_unweighted",
                     "forgot to normalise the sum of the face normals"},
                    {"vertex", "n_unweighted", "copy:n_area",
                     "summed the unnormalised cross products for the unweighted average (that "
                     "weighs each face by its area)"},
                    {"vertex", "n_angle", "copy:n_unweighted",
                     "left out the angles: every face counted once"},
                    {"face", "n_f", "negate",
                     "crossed the edges in the wrong order, (P2 − P0) × (P1 − P0): the normal "
                     "points into the mesh"},
                    {"face-newell", "n_f", "negate",
                     "walked the polygon clockwise: Newell's normal points the other way"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void VertexNormals::validate(const Input& in) {
    prepare(in);
}

VertexNormals::Prepared VertexNormals::prepare(const Input& in) {
    const long long nv = static_cast<long long>(in.vertices.size());
    if (nv == 0) throw InputError("vertices", "must list at least one vertex");
    if (nv > kMaxVertices)
        throw InputError("vertices", "at most " + std::to_string(kMaxVertices) + " vertices (got " +
                                         std::to_string(nv) + ")");
    for (long long v = 0; v < nv; ++v)
        for (int d = 0; d < 3; ++d) {
            const double x = in.vertices[v][d];
            const std::string f = "vertices[" + std::to_string(v) + "][" + std::to_string(d) + "]";
            if (!std::isfinite(x))
                throw InputError(f, "must be a finite number (got " + given(x) + ")");
            if (std::fabs(x) > kMaxCoordinate)
                throw InputError(f, "must be within ±1e100 (got " + given(x) +
                                        "), so that the cross products stay finite");
        }
    if (static_cast<long long>(in.faces.size()) > kMaxFaces)
        throw InputError("faces", "at most " + std::to_string(kMaxFaces) + " faces");
    Prepared p;
    static_cast<Input&>(p) = in;
    p.faces_of.assign(static_cast<std::size_t>(nv), {});
    long long corners = 0;
    for (std::size_t k = 0; k < in.faces.size(); ++k) {
        const auto& face = in.faces[k];
        const std::string f = "faces[" + std::to_string(k) + "]";
        if (face.size() < 3)
            throw InputError(
                f, "a face needs at least 3 vertices (got " + std::to_string(face.size()) + ")");
        corners += static_cast<long long>(face.size());
        if (corners > kMaxCorners)
            throw InputError(
                f, "the faces list more than " + std::to_string(kMaxCorners) + " corners in all");
        for (std::size_t j = 0; j < face.size(); ++j)
            if (face[j] < 0 || face[j] >= nv)
                throw InputError(f + "[" + std::to_string(j) + "]",
                                 "vertex index " + std::to_string(face[j]) +
                                     " is out of range (the mesh has " + std::to_string(nv) +
                                     " vertices, 0 to " + std::to_string(nv - 1) + ")");
        // Repeats in a row (cyclically) are zero-length edges: dropped.
        std::vector<long long> c;
        for (std::size_t j = 0; j < face.size(); ++j)
            if (c.empty() || c.back() != face[j]) c.push_back(face[j]);
        while (c.size() > 1 && c.back() == c.front()) c.pop_back();
        for (std::size_t a = 0; a < c.size(); ++a)
            for (std::size_t b = a + 1; b < c.size(); ++b)
                if (c[a] == c[b]) {
                    // Name the second listing in the face as written.
                    std::size_t first = 0, second = 0;
                    while (face[first] != c[a]) ++first;
                    second = first + 1;
                    while (face[second] == c[a]) ++second;
                    while (face[second] != c[a]) ++second;
                    throw InputError(f + "[" + std::to_string(second) + "]",
                                     "repeats vertex " + std::to_string(c[a]) + " of " + f + "[" +
                                         std::to_string(first) +
                                         "] apart from it: a polygon passes through each vertex "
                                         "once");
                }
        for (long long v : c) p.faces_of[static_cast<std::size_t>(v)].push_back(int(k));
        p.corners.push_back(std::move(c));
    }
    if (in.has_focus && (in.focus_vertex < 0 || in.focus_vertex >= nv))
        throw InputError("focus.vertex", "must be a vertex index, 0 to " + std::to_string(nv - 1) +
                                             " (got " + std::to_string(in.focus_vertex) + ")");
    return p;
}

// ---- [the arithmetic] -----------------------------------------------------------------------

FaceNormal VertexNormals::face_normal(const std::vector<dvec3>& vertices,
                                      std::vector<long long> corners) {
    FaceNormal f;
    f.corners = std::move(corners);
    const std::size_t n = f.corners.size();
    auto P = [&](std::size_t i) { return vertices[static_cast<std::size_t>(f.corners[i % n])]; };
    f.angles.assign(n, 0.0);
    if (n < 3) return f;  // collapsed by repeats: no area, no angles worth the name
    f.newell = n > 3;
    if (!f.newell) {
        f.N = glm::cross(P(1) - P(0), P(2) - P(0));
    } else {
        // Newell: the fan from P0, Σ (P_i − P0) × (P_(i+1) − P0).
        const dvec3 p0 = P(0);
        for (std::size_t i = 1; i + 1 < n; ++i) f.N += glm::cross(P(i) - p0, P(i + 1) - p0);
    }
    f.defined = f.N != dvec3(0.0);
    f.area = norm(f.N) / 2;
    f.normal = unit(f.N);
    for (std::size_t i = 0; i < n; ++i) {
        const dvec3 a = P(i + 1) - P(i), b = P(i + n - 1) - P(i);
        // A zero-length edge (two indices at one point) gives the corner no angle.
        if (a == dvec3(0.0) || b == dvec3(0.0)) continue;
        // The angle between the edges; reflex where the corner turns against n_f.
        const dvec3 c = glm::cross(a, b);
        double t = std::atan2(norm(c), glm::dot(a, b));
        if (f.newell && f.defined && glm::dot(f.normal, c) < 0) t = 2 * kPi - t;
        f.angles[i] = t;
    }
    return f;
}

VertexSums VertexNormals::vertex_sums(const std::vector<FaceNormal>& faces,
                                      const std::vector<int>& around, int vertex) {
    VertexSums s;
    for (int k : around) {
        const FaceNormal& f = faces[static_cast<std::size_t>(k)];
        if (!f.defined) {
            s.zero_area_faces.push_back(k);
            continue;
        }
        s.faces.push_back(k);
        std::size_t c = 0;
        while (f.corners[c] != vertex) ++c;
        const double theta = f.angles[c];
        s.sum[0] += f.normal;
        s.sum[1] += f.N;  // = 2 A_f n_f: the same direction as Σ A_f n_f
        s.sum[2] += theta * f.normal;
        s.scale[0] += 1;
        s.scale[1] += norm(f.N);
        s.scale[2] += theta;
    }
    for (int w = 0; w < 3; ++w) {
        if (s.faces.empty()) continue;
        if (norm(s.sum[w]) <= kCancel * s.scale[w]) continue;  // cancelled (or all θ = 0)
        s.normal[w] = unit(s.sum[w]);
    }
    return s;
}

std::vector<dvec3> VertexNormals::area_weighted(
    std::size_t vertex_count, const std::vector<std::array<long long, 3>>& triangles,
    const std::vector<dvec3>& N) {
    std::vector<dvec3> sum(vertex_count, dvec3(0.0));
    for (std::size_t k = 0; k < triangles.size(); ++k) {
        if (N[k] == dvec3(0.0)) continue;  // no area: contributes nothing
        for (long long v : triangles[k]) sum[static_cast<std::size_t>(v)] += N[k];
    }
    for (dvec3& s : sum) s = unit(s);
    return sum;
}

VertexNormals::Result VertexNormals::compute(const Input& in) {
    const Prepared p = prepare(in);
    Result r;
    r.faces.reserve(p.corners.size());
    for (const auto& c : p.corners) r.faces.push_back(face_normal(in.vertices, c));
    r.vertices.reserve(in.vertices.size());
    for (std::size_t v = 0; v < in.vertices.size(); ++v)
        r.vertices.push_back(vertex_sums(r.faces, p.faces_of[v], static_cast<int>(v)));
    return r;
}

// ---- [step] ---------------------------------------------------------------------------------

VertexNormals::State VertexNormals::start(const Input& in) {
    State s;
    s.in = Shared<Prepared>(prepare(in));
    s.faces.reserve(s.in->corners.size());
    s.vertices.reserve(in.vertices.size());
    return s;
}

void VertexNormals::step(State& s, StepInfo* info) {
    if (done(s)) return;
    const Prepared& p = *s.in;
    if (s.face + 1 < static_cast<int>(p.corners.size())) {
        ++s.face;
        s.faces.push_back(face_normal(p.vertices, p.corners[static_cast<std::size_t>(s.face)]));
    } else {
        ++s.vertex;
        s.vertices.push_back(
            vertex_sums(s.faces, p.faces_of[static_cast<std::size_t>(s.vertex)], s.vertex));
    }
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

void VertexNormals::narrate(const State& s, StepInfo& info) {
    const Prepared& p = *s.in;
    info = StepInfo{};
    if (s.vertex < 0) {
        const FaceNormal& f = s.faces.back();
        const int k = s.face;
        const auto& raw = p.faces[static_cast<std::size_t>(k)];
        std::string list;
        for (std::size_t i = 0; i < f.corners.size(); ++i)
            list += (i ? ", " : "") + vname(f.corners[i]);
        std::string angles, angles_tex;
        std::vector<double> angles_deg;
        for (std::size_t i = 0; i < f.angles.size(); ++i) {
            angles += (i ? ", " : "") + num(deg(f.angles[i]), 4) + "° at " + vname(f.corners[i]);
            angles_deg.push_back(deg(f.angles[i]));
        }
        const std::size_t n_dropped = raw.size() - f.corners.size();
        const std::string dropped = n_dropped
                                        ? " (" + std::to_string(n_dropped) + " repeated index" +
                                              (n_dropped == 1 ? "" : "es") +
                                              " dropped: a zero-length edge has no direction)"
                                        : "";
        if (!f.defined) {
            info.event = "face-degenerate";
            info.line = kLineNormal;
            info.narration = "Face " + fname(k) + " (" + list + ")" + dropped +
                             ": N = " + num(f.N, 4) +
                             ", so its area is 0 and its normal is undefined; it adds nothing to "
                             "any vertex, under any weighting (no division by |N| = 0).";
            info.math = "N_{" + std::to_string(k) + "} = " + tex(f.N, 4) + ",\\quad A = 0";
            info.vars = {{"face", static_cast<long long>(k)},
                         {"N", vec(f.N)},
                         {"area", 0.0},
                         {"n_f", std::string("undefined")}};
            return;
        }
        info.event = f.newell ? "face-newell" : "face";
        info.line = kLineNormal;
        const std::string how =
            f.newell ? "Newell's method, Σ (P_i − P0) × (P_(i+1) − P0) over its " +
                           std::to_string(f.corners.size()) + " corners,"
                     : "(P1 − P0) × (P2 − P0) = " +
                           num(p.vertices[f.corners[1]] - p.vertices[f.corners[0]], 4) + " × " +
                           num(p.vertices[f.corners[2]] - p.vertices[f.corners[0]], 4);
        info.narration = "Face " + fname(k) + " (" + list + ")" + dropped + ": N = " + how +
                         (f.newell ? " gives " : " = ") + num(f.N, 4) +
                         ", area |N|/2 = " + num(f.area, 4) + ", n_f = " + num(f.normal, 4) +
                         "; angles " + angles + ".";
        info.math = "N = " + tex(f.N, 4) + ",\\quad A = " + tex(f.area, 4) +
                    ",\\quad n_f = " + tex(f.normal, 4);
        info.vars = {{"face", static_cast<long long>(k)},
                     {"N", vec(f.N)},
                     {"area", f.area},
                     {"n_f", vec(f.normal)},
                     {"angles_deg", angles_deg}};
        return;
    }
    const int v = s.vertex;
    const VertexSums& vs = s.vertices.back();
    std::string faces;
    for (std::size_t i = 0; i < vs.faces.size(); ++i) faces += (i ? ", " : "") + fname(vs.faces[i]);
    std::string zero;
    for (std::size_t i = 0; i < vs.zero_area_faces.size(); ++i)
        zero += (i ? ", " : "") + fname(vs.zero_area_faces[i]);
    const std::string zero_note = zero.empty() ? "" : " (" + zero + " without area, left out)";
    info.vars = {{"vertex", static_cast<long long>(v)},
                 {"faces", static_cast<long long>(vs.faces.size())}};
    if (vs.faces.empty()) {
        info.event = "vertex-isolated";
        info.line = kLineNormalise;
        info.narration = vname(v) + " belongs to no face with area" + zero_note +
                         ": there is nothing to average, so its normal is undefined (null) under "
                         "every weighting.";
        info.math = "n_{" + std::to_string(v) + "} = \\text{undefined}";
        return;
    }
    static const char* const kName[3] = {"unweighted", "area", "angle"};
    static const char* const kSum[3] = {"Σ n_f", "Σ N_f (= 2 Σ A_f n_f)", "Σ θ_f n_f"};
    bool cancelled = false;
    std::string parts, math;
    for (int w = 0; w < 3; ++w) {
        parts += std::string(w ? "; " : "") + kName[w] + " " + kSum[w] + " = " + num(vs.sum[w], 4) +
                 " → " +
                 (vs.normal[w] ? num(*vs.normal[w], 4) : std::string("undefined (it cancels)"));
        math += std::string(w ? ",\\quad " : "") + "n^{\\text{" + kName[w] +
                "}} = " + (vs.normal[w] ? tex(*vs.normal[w], 4) : std::string("\\text{undefined}"));
        cancelled = cancelled || !vs.normal[w];
    }
    info.event = cancelled ? "vertex-cancelled" : "vertex";
    info.line = kLineNormalise;
    std::string angle_list;
    for (std::size_t i = 0; i < vs.faces.size(); ++i) {
        const FaceNormal& f = s.faces[static_cast<std::size_t>(vs.faces[i])];
        std::size_t c = 0;
        while (f.corners[c] != v) ++c;
        angle_list += (i ? ", " : "") + num(deg(f.angles[c]), 4) + "°";
    }
    info.narration = vname(v) + ", faces " + faces + zero_note + " (angles there " + angle_list +
                     "): " + parts + "." +
                     (cancelled ? " Faces wound oppositely point their normals apart, so the "
                                  "sum cancels and there is no direction to normalise."
                                : "");
    info.math = math;
    const char* const kVar[3] = {"n_unweighted", "n_area", "n_angle"};
    const char* const kSumVar[3] = {"sum_unweighted", "sum_area", "sum_angle"};
    for (int w = 0; w < 3; ++w) {
        info.vars.push_back({kSumVar[w], vec(vs.sum[w])});
        info.vars.push_back(
            {kVar[w], vs.normal[w] ? Value{vec(*vs.normal[w])} : Value{std::string("undefined")}});
    }
}

}  // namespace cg
