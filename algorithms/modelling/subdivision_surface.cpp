// Sections: [topology] [rules] [connect] [spec] [validate] [advance] [narrate] [result and compute]
// (the picture is in subdivision_surface_draw.cpp)
#include "modelling/subdivision_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/format.hpp"

namespace cg {

namespace {

using S = SubdivisionSurface;
using glm::dvec3;
using Input = S::Input;
using Mesh = S::Mesh;
using Phase = S::Phase;
using Scheme = S::Scheme;
using State = S::State;
using Topology = S::Topology;

constexpr double kPi = 3.14159265358979323846;

}  // namespace

const char* SubdivisionSurface::scheme_id(Scheme s) {
    return s == Scheme::Loop ? "loop" : "catmull-clark";
}

// ---- [topology] -----------------------------------------------------------------------------

// Every edge once: for each vertex the edges to higher-numbered vertices, (other end, edge id),
// searched linearly (a vertex has a handful of edges).
SubdivisionSurface::Topology SubdivisionSurface::topology(const Mesh& m) {
    Topology t;
    std::vector<std::vector<std::array<int, 2>>> up(m.vertices.size());
    t.face_edges.resize(m.faces.size());
    std::size_t corners = 0;
    for (const auto& f : m.faces) corners += f.size();
    t.edges.reserve(corners / 2 + 8);
    t.edge_faces.reserve(corners / 2 + 8);
    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        const auto& f = m.faces[k];
        auto& fe = t.face_edges[k];
        fe.resize(f.size());
        for (std::size_t i = 0; i < f.size(); ++i) {
            const int a = f[i], b = f[(i + 1) % f.size()];
            const int lo = std::min(a, b), hi = std::max(a, b);
            int id = -1;
            for (const auto& [other, e] : up[std::size_t(lo)])
                if (other == hi) id = e;
            if (id < 0) {
                id = int(t.edges.size());
                up[std::size_t(lo)].push_back({hi, id});
                t.edges.push_back({a, b});
                t.edge_faces.push_back({int(k), -1});
            } else {
                // A third face on one edge is refused by validate(); compute() never sees one.
                t.edge_faces[std::size_t(id)][1] = int(k);
            }
            fe[i] = id;
        }
    }
    return t;
}

SubdivisionSurface::Counts SubdivisionSurface::counts_of(const Mesh& m, const Topology& t) {
    return {(long long)m.vertices.size(), (long long)t.edges.size(), (long long)m.faces.size()};
}

SubdivisionSurface::Counts SubdivisionSurface::counts_after(Scheme scheme, const Mesh& m,
                                                            const Counts& c) {
    if (scheme == Scheme::Loop) return {c.V + c.E, 2 * c.E + 3 * c.F, 4 * c.F};
    long long corners = 0;
    for (const auto& f : m.faces) corners += (long long)f.size();
    return {c.V + c.F + c.E, 2 * c.E + corners, corners};
}

int SubdivisionSurface::find_edge(const Topology& t, int a, int b) {
    for (std::size_t e = 0; e < t.edges.size(); ++e)
        if ((t.edges[e][0] == a && t.edges[e][1] == b) || (t.edges[e][0] == b && t.edges[e][1] == a))
            return int(e);
    return -1;
}

// ---- [rules] --------------------------------------------------------------------------------

double SubdivisionSurface::loop_beta(int n) {
    if (n == 3) return 3.0 / 16.0;  // exact, as the course's tables give it
    if (n == 6) return 1.0 / 16.0;
    const double c = 3.0 / 8.0 + 0.25 * std::cos(2 * kPi / n);
    return (5.0 / 8.0 - c * c) / n;
}

std::vector<dvec3> SubdivisionSurface::face_points(const Mesh& m) {
    std::vector<dvec3> out(m.faces.size());
    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        dvec3 c(0.0);
        for (int v : m.faces[k]) c += m.vertices[std::size_t(v)];
        out[k] = c / double(m.faces[k].size());
    }
    return out;
}

namespace {

// The corner of triangle f opposite its edge i (corners i and i + 1).
int opposite(const Mesh& m, int f, int a, int b) {
    for (int v : m.faces[std::size_t(f)])
        if (v != a && v != b) return v;
    return a;
}

}  // namespace

std::vector<dvec3> SubdivisionSurface::edge_points(Scheme scheme, const Mesh& m, const Topology& t,
                                                   const std::vector<dvec3>& fp) {
    std::vector<dvec3> out(t.edges.size());
    const auto& P = m.vertices;
    for (std::size_t e = 0; e < t.edges.size(); ++e) {
        const auto [a, b] = t.edges[e];
        const auto [f0, f1] = t.edge_faces[e];
        const dvec3 sum = P[std::size_t(a)] + P[std::size_t(b)];
        if (f1 < 0)
            out[e] = 0.5 * sum;  // boundary: the midpoint
        else if (scheme == Scheme::Loop)
            out[e] = 0.375 * sum + 0.125 * (P[std::size_t(opposite(m, f0, a, b))] +
                                            P[std::size_t(opposite(m, f1, a, b))]);
        else
            out[e] = 0.25 * (sum + fp[std::size_t(f0)] + fp[std::size_t(f1)]);
    }
    return out;
}

// Sums gathered per vertex in one pass over the edges and one over the faces, then each
// vertex's rule.
std::vector<dvec3> SubdivisionSurface::vertex_points(Scheme scheme, const Mesh& m,
                                                     const Topology& t,
                                                     const std::vector<dvec3>& fp) {
    const auto& P = m.vertices;
    const std::size_t nv = P.size();
    std::vector<int> valence(nv, 0), border(nv, 0), faces_at(nv, 0);
    std::vector<dvec3> around(nv, dvec3(0.0)), border_sum(nv, dvec3(0.0)), q(nv, dvec3(0.0));
    for (std::size_t e = 0; e < t.edges.size(); ++e) {
        const auto a = std::size_t(t.edges[e][0]), b = std::size_t(t.edges[e][1]);
        ++valence[a], ++valence[b];
        around[a] += P[b], around[b] += P[a];
        if (t.edge_faces[e][1] < 0) {
            ++border[a], ++border[b];
            border_sum[a] += P[b], border_sum[b] += P[a];
        }
    }
    if (scheme == Scheme::CatmullClark)
        for (std::size_t k = 0; k < m.faces.size(); ++k)
            for (int v : m.faces[k]) q[std::size_t(v)] += fp[k], ++faces_at[std::size_t(v)];
    std::vector<dvec3> out(nv);
    for (std::size_t v = 0; v < nv; ++v) {
        const int n = valence[v];
        if (n == 0 || border[v] > 2) {
            out[v] = P[v];  // in no face, or a pinch: kept
        } else if (border[v] == 2) {
            out[v] = 0.75 * P[v] + 0.125 * border_sum[v];
        } else if (scheme == Scheme::Loop) {
            const double beta = loop_beta(n);
            out[v] = (1 - n * beta) * P[v] + beta * around[v];
        } else {
            const dvec3 Q = q[v] / double(faces_at[v]);
            const dvec3 R = 0.5 * (P[v] + around[v] / double(n));
            out[v] = (Q + 2.0 * R + double(n - 3) * P[v]) / double(n);
        }
    }
    return out;
}

namespace {

std::string vname(long long v) {
    return "V" + std::to_string(v);
}

}  // namespace

SubdivisionSurface::Stencil SubdivisionSurface::vertex_stencil(Scheme scheme, const Mesh& m,
                                                               const Topology& t,
                                                               const std::vector<dvec3>& fp,
                                                               int v) {
    const auto& P = m.vertices;
    Stencil st;
    std::vector<int> nb, border_nb, faces;
    for (std::size_t e = 0; e < t.edges.size(); ++e) {
        const auto [a, b] = t.edges[e];
        if (a != v && b != v) continue;
        const int w = a == v ? b : a;
        nb.push_back(w);
        if (t.edge_faces[e][1] < 0) border_nb.push_back(w);
    }
    for (std::size_t k = 0; k < m.faces.size(); ++k)
        if (std::find(m.faces[k].begin(), m.faces[k].end(), v) != m.faces[k].end())
            faces.push_back(int(k));
    auto add = [&](dvec3 p, double w, std::string name) {
        st.points.push_back(p);
        st.weights.push_back(w);
        st.names.push_back(std::move(name));
    };
    const int n = int(nb.size());
    if (n == 0 || border_nb.size() > 2) {
        st.rule = n == 0 ? "in no face: kept" : "a pinch (more than two boundary edges): kept";
        add(P[std::size_t(v)], 1.0, vname(v));
        return st;
    }
    if (border_nb.size() == 2) {
        st.rule = "boundary";
        add(P[std::size_t(v)], 0.75, vname(v));
        for (int w : border_nb) add(P[std::size_t(w)], 0.125, vname(w));
        return st;
    }
    st.rule = "interior, n = " + std::to_string(n);
    if (scheme == Scheme::Loop) {
        const double beta = loop_beta(n);
        add(P[std::size_t(v)], 1 - n * beta, vname(v));
        for (int w : nb) add(P[std::size_t(w)], beta, vname(w));
        return st;
    }
    // (Q + 2R + (n − 3)v)/n with R = v/2 + Σw/(2n): v gets (n − 2)/n, each neighbour 1/n²,
    // each face point 1/(n·faces).
    add(P[std::size_t(v)], double(n - 2) / n, vname(v));
    for (int w : nb) add(P[std::size_t(w)], 1.0 / (double(n) * n), vname(w));
    for (int f : faces)
        add(fp[std::size_t(f)], 1.0 / (double(n) * double(faces.size())),
            "F" + std::to_string(f));
    return st;
}

SubdivisionSurface::Stencil SubdivisionSurface::edge_stencil(Scheme scheme, const Mesh& m,
                                                             const Topology& t,
                                                             const std::vector<dvec3>& fp,
                                                             int e) {
    const auto& P = m.vertices;
    Stencil st;
    const auto [a, b] = t.edges[std::size_t(e)];
    const auto [f0, f1] = t.edge_faces[std::size_t(e)];
    auto add = [&](dvec3 p, double w, std::string name) {
        st.points.push_back(p);
        st.weights.push_back(w);
        st.names.push_back(std::move(name));
    };
    if (f1 < 0) {
        st.rule = "boundary: the midpoint";
        add(P[std::size_t(a)], 0.5, vname(a));
        add(P[std::size_t(b)], 0.5, vname(b));
    } else if (scheme == Scheme::Loop) {
        st.rule = "interior";
        const int c = opposite(m, f0, a, b), d = opposite(m, f1, a, b);
        add(P[std::size_t(a)], 0.375, vname(a));
        add(P[std::size_t(b)], 0.375, vname(b));
        add(P[std::size_t(c)], 0.125, vname(c));
        add(P[std::size_t(d)], 0.125, vname(d));
    } else {
        st.rule = "interior";
        add(P[std::size_t(a)], 0.25, vname(a));
        add(P[std::size_t(b)], 0.25, vname(b));
        add(fp[std::size_t(f0)], 0.25, "F" + std::to_string(f0));
        add(fp[std::size_t(f1)], 0.25, "F" + std::to_string(f1));
    }
    return st;
}

// ---- [connect] ------------------------------------------------------------------------------

SubdivisionSurface::Mesh SubdivisionSurface::connect(Scheme scheme, const Mesh& m,
                                                     const Topology& t, Points&& p) {
    Mesh out;
    const int nv = int(m.vertices.size()), nf = int(m.faces.size());
    out.vertices = std::move(p.vertex);
    out.vertices.insert(out.vertices.end(), p.face.begin(), p.face.end());
    out.vertices.insert(out.vertices.end(), p.edge.begin(), p.edge.end());
    const int edge0 = scheme == Scheme::Loop ? nv : nv + nf;  // the first edge point's index
    std::size_t corners = 0;
    for (const auto& f : m.faces) corners += f.size();
    out.faces.reserve(scheme == Scheme::Loop ? 4 * m.faces.size() : corners);
    for (int k = 0; k < nf; ++k) {
        const auto& f = m.faces[std::size_t(k)];
        const auto& fe = t.face_edges[std::size_t(k)];
        const int n = int(f.size());
        if (scheme == Scheme::Loop) {
            const int ab = edge0 + fe[0], bc = edge0 + fe[1], ca = edge0 + fe[2];
            out.faces.push_back({f[0], ab, ca});
            out.faces.push_back({f[1], bc, ab});
            out.faces.push_back({f[2], ca, bc});
            out.faces.push_back({ab, bc, ca});
        } else {
            for (int i = 0; i < n; ++i)
                out.faces.push_back({f[std::size_t(i)], edge0 + fe[std::size_t(i)], nv + k,
                                     edge0 + fe[std::size_t((i + n - 1) % n)]});
        }
    }
    return out;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& SubdivisionSurface::spec() {
    static const Spec spec{
        "subdivision-surface",
        "Subdivision surfaces: Loop and Catmull–Clark",
        "Modelling",
        {
            "for each level ℓ = 1 … L:",
            "split: a new point on every edge (Catmull–Clark: and in every face)",
            "face point f = the centroid of the face's corners   ▷ Catmull–Clark",
            "edge point: Loop 3/8(a + b) + 1/8(c + d); Catmull–Clark (a + b + f₁ + f₂)/4; "
            "boundary (a + b)/2",
            "vertex point: Loop (1 − nβ)v + βΣw; Catmull–Clark (Q + 2R + (n − 3)v)/n; "
            "boundary 1/8 u + 3/4 v + 1/8 w",
            "connect: Loop 1 triangle → 4; Catmull–Clark n-gon → n quads",
            "report V, E, F per level: V − E + F unchanged",
        },
        {
            {"split", "the edges numbered and counted; how many points and faces will be made"},
            {"face-points", "Catmull–Clark: every face's centroid, its face point"},
            {"edge-points", "every edge's new point from its ends (and its neighbours)"},
            {"vertex-points", "every old vertex moved to a weighted average of its neighbours"},
            {"connect", "the new points joined into the finer mesh"},
            {"summary", "the counts per level and the final mesh"},
        },
        {},
        {
            .predict = {{"face-points", {"face_point"}},
                        {"edge-points", {"edge_point"}},
                        {"vertex-points", {"vertex_point"}},
                        {"connect", {"V", "F"}}},
            .mistakes =
                {
                    {"vertex-points", "vertex_point", "copy:v",
                     "left the old vertex where it was (only the new points averaged): the "
                     "surface interpolates the coarse mesh and keeps its corners"},
                    {"edge-points", "edge_point", "copy:midpoint",
                     "took the midpoint for an interior edge (the boundary rule), ignoring the "
                     "neighbouring faces"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void SubdivisionSurface::validate(const Input& in) {
    const Mesh& m = in.mesh;
    if (m.vertices.empty()) throw InputError("vertices", "needs at least one vertex");
    if ((long long)m.vertices.size() > kMaxVertices)
        throw InputError("vertices", "has " + std::to_string(m.vertices.size()) +
                                         " vertices; at most " + std::to_string(kMaxVertices));
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
        const dvec3 p = m.vertices[i];
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(p[c]) || std::fabs(p[c]) > kMaxCoordinate)
                throw InputError("vertices[" + std::to_string(i) + "]",
                                 "coordinates must be finite numbers within ±1e100");
    }
    if (m.faces.empty()) throw InputError("faces", "needs at least one face");
    if ((long long)m.faces.size() > kMaxFaces)
        throw InputError("faces", "has " + std::to_string(m.faces.size()) + " faces; at most " +
                                      std::to_string(kMaxFaces));
    const bool loop = in.scheme == Scheme::Loop;
    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        const auto& f = m.faces[k];
        const std::string field = "faces[" + std::to_string(k) + "]";
        if (loop && f.size() != 3)
            throw InputError(field, "Loop subdivision needs triangles; this face has " +
                                        std::to_string(f.size()) + " vertices");
        if (f.size() != 3 && f.size() != 4)
            throw InputError(field, "must be a triangle or a quad (3 or 4 vertex indices), got " +
                                        std::to_string(f.size()));
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (f[i] < 0 || f[i] >= int(m.vertices.size()))
                throw InputError(field + "[" + std::to_string(i) + "]",
                                 "vertex index " + std::to_string(f[i]) + " is out of range (0 to " +
                                     std::to_string(m.vertices.size() - 1) + ")");
            for (std::size_t j = 0; j < i; ++j)
                if (f[j] == f[i])
                    throw InputError(field, "lists vertex " + std::to_string(f[i]) +
                                                " twice: a face's corners must differ");
        }
    }
    // An edge in a third face: not a surface, no rule applies.
    {
        std::vector<std::vector<std::array<int, 2>>> up(m.vertices.size());  // (other, count)
        for (std::size_t k = 0; k < m.faces.size(); ++k) {
            const auto& f = m.faces[k];
            for (std::size_t i = 0; i < f.size(); ++i) {
                const int a = f[i], b = f[(i + 1) % f.size()];
                const int lo = std::min(a, b), hi = std::max(a, b);
                bool found = false;
                for (auto& [other, count] : up[std::size_t(lo)]) {
                    if (other != hi) continue;
                    found = true;
                    if (++count > 2)
                        throw InputError("faces[" + std::to_string(k) + "]",
                                         "the edge " + std::to_string(lo) + "–" +
                                             std::to_string(hi) +
                                             " is in a third face: a non-manifold edge (at most "
                                             "two faces share an edge)");
                }
                if (!found) up[std::size_t(lo)].push_back({hi, 1});
            }
        }
    }
    if (in.levels < 0 || in.levels > kMaxLevels)
        throw InputError("levels", "must be 0 to " + std::to_string(kMaxLevels) + " (got " +
                                       std::to_string(in.levels) + ")");
    // The face count after each level by the formulas: Loop 4F, Catmull–Clark Σ n_f then 4F.
    long long faces = (long long)m.faces.size();
    for (int l = 1; l <= in.levels; ++l) {
        if (l == 1 && !loop) {
            faces = 0;
            for (const auto& f : m.faces) faces += (long long)f.size();
        } else {
            faces *= 4;
        }
        if (faces > kMaxFaces)
            throw InputError("levels", "level " + std::to_string(l) + " would have " +
                                           std::to_string(faces) + " faces; at most " +
                                           std::to_string(kMaxFaces) + " are built and drawn");
    }
    switch (in.focus) {
        case FocusKind::None:
            break;
        case FocusKind::Vertex:
            if (in.focus_a < 0 || in.focus_a >= (long long)m.vertices.size())
                throw InputError("focus.vertex", "must be a vertex index, 0 to " +
                                                     std::to_string(m.vertices.size() - 1));
            break;
        case FocusKind::Face:
            if (loop)
                throw InputError("focus.face", "Loop subdivision has no face points");
            if (in.focus_a < 0 || in.focus_a >= (long long)m.faces.size())
                throw InputError("focus.face",
                                 "must be a face index, 0 to " + std::to_string(m.faces.size() - 1));
            break;
        case FocusKind::Edge:
            if (find_edge(topology(m), int(std::clamp<long long>(in.focus_a, -1, 1 << 30)),
                          int(std::clamp<long long>(in.focus_b, -1, 1 << 30))) < 0)
                throw InputError("focus.edge", "[" + std::to_string(in.focus_a) + ", " +
                                                   std::to_string(in.focus_b) +
                                                   "] is not an edge of the mesh");
            break;
    }
}

SubdivisionSurface::State SubdivisionSurface::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

SubdivisionSurface::State SubdivisionSurface::begin(Shared<Input> shared) {
    State s;
    s.in = std::move(shared);
    s.mesh = s.in->mesh;
    s.topo = topology(s.mesh);
    s.counts.push_back(counts_of(s.mesh, s.topo));
    s.phase = s.in->levels > 0 ? Phase::Split : Phase::Summary;
    return s;
}

std::size_t SubdivisionSurface::bytes(const State& s) {
    const auto pts = [](const Points& p) {
        return heap_bytes(p.face) + heap_bytes(p.edge) + heap_bytes(p.vertex);
    };
    const auto topo = [](const Topology& t) {
        return heap_bytes(t.edges) + heap_bytes(t.edge_faces) + heap_bytes(t.face_edges);
    };
    return heap_bytes(s.mesh.vertices) + heap_bytes(s.mesh.faces) + topo(s.topo) +
           topo(s.first_topology) + pts(s.points) + pts(s.first) + heap_bytes(s.counts);
}

// ---- [advance] ------------------------------------------------------------------------------

void SubdivisionSurface::advance(State& s) {
    const Input& in = *s.in;
    const bool cc = in.scheme == Scheme::CatmullClark;
    switch (s.phase) {
        case Phase::Split:
            if (s.level > 0) s.topo = topology(s.mesh);  // level 1's was built by begin()
            s.points = {};
            if (s.level == 0) s.first_topology = s.topo;
            s.last = Phase::Split;
            s.phase = cc ? Phase::FacePoints : Phase::EdgePoints;
            return;
        case Phase::FacePoints:
            s.points.face = face_points(s.mesh);
            s.last = Phase::FacePoints;
            s.phase = Phase::EdgePoints;
            return;
        case Phase::EdgePoints:
            s.points.edge = edge_points(in.scheme, s.mesh, s.topo, s.points.face);
            s.last = Phase::EdgePoints;
            s.phase = Phase::VertexPoints;
            return;
        case Phase::VertexPoints:
            s.points.vertex = vertex_points(in.scheme, s.mesh, s.topo, s.points.face);
            if (s.level == 0) s.first = s.points;
            s.last = Phase::VertexPoints;
            s.phase = Phase::Connect;
            return;
        case Phase::Connect: {
            const Counts next = counts_after(in.scheme, s.mesh, s.counts.back());
            s.mesh = connect(in.scheme, s.mesh, s.topo, std::move(s.points));
            s.points = {};
            s.counts.push_back(next);
            ++s.level;
            s.last = Phase::Connect;
            s.phase = s.level < in.levels ? Phase::Split : Phase::Summary;
            return;
        }
        case Phase::Summary:
            s.last = Phase::Summary;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void SubdivisionSurface::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and compute] -------------------------------------------------------------------

namespace {

void set_focus(const Input& in, SubdivisionSurface::Result& r) {
    r.has_focus = in.focus != SubdivisionSurface::FocusKind::None && in.levels > 0;
    if (!r.has_focus) return;
    switch (in.focus) {
        case SubdivisionSurface::FocusKind::Vertex:
            r.focus_point = r.first.vertex[std::size_t(in.focus_a)];
            break;
        case SubdivisionSurface::FocusKind::Face:
            r.focus_point = r.first.face[std::size_t(in.focus_a)];
            break;
        case SubdivisionSurface::FocusKind::Edge:
            r.focus_point = r.first.edge[std::size_t(
                SubdivisionSurface::find_edge(r.first_topology, int(in.focus_a), int(in.focus_b)))];
            break;
        case SubdivisionSurface::FocusKind::None:
            break;
    }
}

}  // namespace

SubdivisionSurface::Result SubdivisionSurface::result(const State& s) {
    Result r;
    r.mesh = s.mesh;
    r.counts = s.counts;
    r.first_topology = s.first_topology;
    r.first = s.first;
    set_focus(*s.in, r);
    return r;
}

SubdivisionSurface::Result SubdivisionSurface::result(State&& s) {
    Result r;
    r.mesh = std::move(s.mesh);
    r.counts = std::move(s.counts);
    r.first_topology = std::move(s.first_topology);
    r.first = std::move(s.first);
    set_focus(*s.in, r);
    return r;
}

SubdivisionSurface::Result SubdivisionSurface::compute(const Input& in) {
    Result r;
    Mesh m = in.mesh;
    Topology t = topology(m);
    r.counts.push_back(counts_of(m, t));
    for (int l = 0; l < in.levels; ++l) {
        if (l > 0) t = topology(m);
        Points p;
        if (in.scheme == Scheme::CatmullClark) p.face = face_points(m);
        p.edge = edge_points(in.scheme, m, t, p.face);
        p.vertex = vertex_points(in.scheme, m, t, p.face);
        if (l == 0) {
            r.first_topology = t;
            r.first = p;
        }
        const Counts next = counts_after(in.scheme, m, r.counts.back());
        m = connect(in.scheme, m, t, std::move(p));
        r.counts.push_back(next);
    }
    r.mesh = std::move(m);
    set_focus(in, r);
    return r;
}

}  // namespace cg

// ---- [narrate] ------------------------------------------------------------------------------

namespace cg {

// A weight as the course writes it: a fraction with a small denominator when it is one.
std::string subdivision_weight(double w) {
    for (long long d : {1, 2, 3, 4, 6, 8, 9, 12, 16, 18, 24, 32, 36, 64, 128, 256, 512}) {
        const double n = std::round(w * double(d));
        if (std::fabs(n - w * double(d)) <= 1e-9 * double(d)) {
            if (d == 1) return std::to_string((long long)n);
            return std::to_string((long long)n) + "/" + std::to_string(d);
        }
    }
    return num(w, 4);
}

// The vertex, face and edge the narration works out in full (and the picture labels): the focus
// when there is one, else vertex 0; a face and an edge at that vertex on later levels.
int subdivision_shown_vertex(const SubdivisionSurface::Input& in) {
    using F = SubdivisionSurface::FocusKind;
    if (in.focus == F::Vertex) return int(in.focus_a);
    if (in.focus == F::Face) return in.mesh.faces[std::size_t(in.focus_a)][0];
    if (in.focus == F::Edge) return int(in.focus_a);
    return 0;
}

int subdivision_shown_face(const SubdivisionSurface::State& s) {
    if (s.level == 0 && s.in->focus == SubdivisionSurface::FocusKind::Face) return int(s.in->focus_a);
    const int v = subdivision_shown_vertex(*s.in);
    for (std::size_t k = 0; k < s.mesh.faces.size(); ++k)
        for (int c : s.mesh.faces[k])
            if (c == v) return int(k);
    return 0;
}

int subdivision_shown_edge(const SubdivisionSurface::State& s) {
    if (s.level == 0 && s.in->focus == SubdivisionSurface::FocusKind::Edge)
        return SubdivisionSurface::find_edge(s.topo, int(s.in->focus_a), int(s.in->focus_b));
    const int v = subdivision_shown_vertex(*s.in);
    for (std::size_t e = 0; e < s.topo.edges.size(); ++e)
        if (s.topo.edges[e][0] == v || s.topo.edges[e][1] == v) return int(e);
    return 0;
}

namespace {

using S = SubdivisionSurface;
using glm::dvec3;
using Phase = S::Phase;
using Scheme = S::Scheme;
using State = S::State;

enum Line { kLineLevel = 1, kLineSplit, kLineFace, kLineEdge, kLineVertex, kLineConnect, kLineReport };

// "3/8·V0 + 3/8·V1 + 1/8·V2 + 1/8·V3"
std::string weighted_sum(const S::Stencil& st) {
    std::string out;
    for (std::size_t i = 0; i < st.weights.size(); ++i)
        out += (i ? " + " : "") + subdivision_weight(st.weights[i]) + "·" + st.names[i];
    return out;
}

std::string weighted_tex(const S::Stencil& st) {
    std::string out;
    for (std::size_t i = 0; i < st.weights.size(); ++i)
        out += (i ? " + " : "") + subdivision_weight(st.weights[i]) + "\\," + st.names[i];
    return out;
}

std::string counts_text(const S::Counts& c) {
    return std::to_string(c.V) + " vertices, " + std::to_string(c.E) + " edges, " +
           std::to_string(c.F) + " faces";
}

std::string level_text(const State& s) {
    return "Level " + std::to_string(s.level + 1) + " of " + std::to_string(s.in->levels);
}

void narrate_split(const State& s, StepInfo& info) {
    const bool cc = s.in->scheme == Scheme::CatmullClark;
    const S::Counts c = s.counts.back();
    const S::Counts next = S::counts_after(s.in->scheme, s.mesh, c);
    long long border = 0;
    for (const auto& ef : s.topo.edge_faces) border += ef[1] < 0;
    info.event = "split";
    info.line = kLineSplit;
    info.narration =
        level_text(s) + ": the mesh has " + counts_text(c) + " (" + std::to_string(border) +
        " on the boundary). The split puts a point on each of the " + std::to_string(c.E) +
        " edges" + (cc ? " and in each of the " + std::to_string(c.F) + " faces" : "") +
        "; joined, they will make " + counts_text(next) + " (" +
        (cc ? "V + F + E, 2E + Σn_f, Σn_f" : "V + E, 2E + 3F, 4F") + "). V − E + F = " +
        std::to_string(c.euler()) + " before and after.";
    info.math = cc ? "V' = V + F + E = " + std::to_string(next.V)
                   : "V' = V + E = " + std::to_string(next.V);
    info.vars = {{"level", (long long)s.level + 1},     {"V", c.V}, {"E", c.E}, {"F", c.F},
                 {"boundary_edges", border}};
}

void narrate_face(const State& s, StepInfo& info) {
    const int f = subdivision_shown_face(s);
    const auto& face = s.mesh.faces[std::size_t(f)];
    const dvec3 p = s.points.face[std::size_t(f)];
    std::string corners;
    for (std::size_t i = 0; i < face.size(); ++i) corners += (i ? " + " : "") + ("V" + std::to_string(face[i]));
    info.event = "face-points";
    info.line = kLineFace;
    info.narration = level_text(s) + ": " + std::to_string(s.mesh.faces.size()) +
                     " face points, each the centroid of its face. F" + std::to_string(f) + " = (" +
                     corners + ")/" + std::to_string(face.size()) + " = " + num(p) + ".";
    info.math = "F_{" + std::to_string(f) + "} = \\tfrac{1}{" + std::to_string(face.size()) +
                "}(" + corners + ") = " + tex(p);
    info.vars = {{"face", (long long)f}, {"face_point", vec(p)}};
}

void narrate_edge(const State& s, StepInfo& info) {
    const int e = subdivision_shown_edge(s);
    const auto st = S::edge_stencil(s.in->scheme, s.mesh, s.topo, s.points.face, e);
    const auto [a, b] = s.topo.edges[std::size_t(e)];
    const dvec3 p = s.points.edge[std::size_t(e)];
    const dvec3 mid = 0.5 * (s.mesh.vertices[std::size_t(a)] + s.mesh.vertices[std::size_t(b)]);
    info.event = "edge-points";
    info.line = kLineEdge;
    info.narration = level_text(s) + ": " + std::to_string(s.topo.edges.size()) +
                     " edge points. E" + std::to_string(e) + " joins V" + std::to_string(a) +
                     " and V" + std::to_string(b) + " (" + st.rule + "): " + weighted_sum(st) +
                     " = " + num(p) + ".";
    info.math = "E_{" + std::to_string(e) + "} = " + weighted_tex(st) + " = " + tex(p);
    info.vars = {{"edge", std::vector<double>{double(a), double(b)}},
                 {"midpoint", vec(mid)},
                 {"edge_point", vec(p)}};
}

void narrate_vertex(const State& s, StepInfo& info) {
    const int v = subdivision_shown_vertex(*s.in);
    const auto st = S::vertex_stencil(s.in->scheme, s.mesh, s.topo, s.points.face, v);
    const dvec3 old = s.mesh.vertices[std::size_t(v)];
    const dvec3 p = s.points.vertex[std::size_t(v)];
    const bool loop = s.in->scheme == Scheme::Loop;
    std::string why;
    if (st.rule.rfind("interior", 0) == 0) {
        const int valence = int(std::count_if(st.names.begin() + 1, st.names.end(),
                                              [](const std::string& x) { return x[0] == 'V'; }));
        why = loop ? " β = " + subdivision_weight(S::loop_beta(valence)) + " = " +
                         num(S::loop_beta(valence), 5) + "; 1 − nβ = " + subdivision_weight(st.weights[0])
                   : " (Q + 2R + (n − 3)v)/n puts " + subdivision_weight(st.weights[0]) +
                         " on the vertex, 1/n² on each neighbour and on each face point";
    }
    info.event = "vertex-points";
    info.line = kLineVertex;
    info.narration = level_text(s) + ": every old vertex moves. V" + std::to_string(v) + " (" +
                     st.rule + ")" + (why.empty() ? "" : ":" + why) + ". New V" + std::to_string(v) + " = " +
                     weighted_sum(st) + " = " + num(p) + " (was " + num(old) + ").";
    info.math = "V_{" + std::to_string(v) + "}' = " + weighted_tex(st) + " = " + tex(p);
    info.vars = {{"vertex", (long long)v}, {"v", vec(old)}, {"weights", st.weights},
                 {"vertex_point", vec(p)}};
}

void narrate_connect(const State& s, StepInfo& info) {
    const bool cc = s.in->scheme == Scheme::CatmullClark;
    const S::Counts c = s.counts.back(), before = s.counts[s.counts.size() - 2];
    info.event = "connect";
    info.line = kLineConnect;
    info.narration = "Level " + std::to_string(s.level) + " joined: " +
                     (cc ? "each face became one quad per corner (corner, edge point, face point, "
                           "edge point)"
                         : "each triangle became four (three at its corners, one in the middle)") +
                     ". Now " + counts_text(c) + " (was " + counts_text(before) +
                     "); V − E + F = " + std::to_string(c.euler()) + ", unchanged.";
    info.math = "V - E + F = " + std::to_string(c.V) + " - " + std::to_string(c.E) + " + " +
                std::to_string(c.F) + " = " + std::to_string(c.euler());
    info.vars = {{"V", c.V}, {"E", c.E}, {"F", c.F}, {"euler", c.euler()}};
}

void narrate_summary(const State& s, StepInfo& info) {
    std::string per;
    for (std::size_t l = 0; l < s.counts.size(); ++l)
        per += (l ? "; " : "") + std::string("level ") + std::to_string(l) + ": " +
               std::to_string(s.counts[l].V) + "/" + std::to_string(s.counts[l].E) + "/" +
               std::to_string(s.counts[l].F);
    info.event = "summary";
    info.line = kLineReport;
    info.narration = std::string(s.in->scheme == Scheme::Loop ? "Loop" : "Catmull–Clark") +
                     " subdivision, " + std::to_string(s.in->levels) + " level" +
                     (s.in->levels == 1 ? "" : "s") + ". V/E/F per level: " + per +
                     ". V − E + F = " + std::to_string(s.counts.back().euler()) + " throughout.";
    info.vars = {{"V", s.counts.back().V}, {"E", s.counts.back().E}, {"F", s.counts.back().F},
                 {"euler", s.counts.back().euler()}};
}

}  // namespace

void SubdivisionSurface::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    switch (s.last) {
        case Phase::Split: narrate_split(s, info); break;
        case Phase::FacePoints: narrate_face(s, info); break;
        case Phase::EdgePoints: narrate_edge(s, info); break;
        case Phase::VertexPoints: narrate_vertex(s, info); break;
        case Phase::Connect: narrate_connect(s, info); break;
        case Phase::Summary:
        case Phase::Done: narrate_summary(s, info); break;
    }
}

}  // namespace cg
