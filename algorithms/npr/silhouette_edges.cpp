// Sections: [spec] [validate] [advance] [narrate] [plain]; the picture is in
// silhouette_edges_draw.cpp
#include "npr/silhouette_edges.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <unordered_map>

#include "core/format.hpp"
#include "core/vec.hpp"
#include "npr/toon_shading.hpp"

namespace cg {

namespace {

enum Line { kLineFaces = 1, kLineSide, kLineEdges, kLineTest, kLineBoundary, kLineDone };

SilhouetteEdges::EdgeId id(int a, int b) {
    return a < b ? SilhouetteEdges::EdgeId{a, b} : SilhouetteEdges::EdgeId{b, a};
}

std::string edge_name(int a, int b) {
    const auto e = id(a, b);
    return "P" + std::to_string(e[0]) + "P" + std::to_string(e[1]);
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& SilhouetteEdges::spec() {
    static const Spec spec{
        "silhouette-edges",
        "Silhouette edges",
        "Non-Photorealistic Rendering",
        {
            "for each face F (counter-clockwise seen from outside):",
            "    front(F) ← (P_0 − E)·N < 0          ▷ N Newell's outward normal; = 0 is back",
            "for each edge e of the mesh:",
            "    if e has faces F, G: silhouette ⇔ front(F) ≠ front(G)",
            "    else (one face): a boundary edge, listed apart",
            "done: draw the silhouette edges thick over the shaded mesh",
        },
        {
            {"front", "(P_0 − E)·N < 0: the face is turned towards the eye"},
            {"back", "(P_0 − E)·N ≥ 0: the face is turned away (or seen edge-on)"},
            {"silhouette", "the edge's two faces disagree, one front and one back"},
            {"interior", "the edge's two faces are both front or both back: not drawn as an outline"},
            {"boundary", "the edge has only one face: a rim of an open mesh, listed apart"},
            {"done", "every edge decided: the silhouette edges, sorted"},
        },
        {},
        {
            .predict = {{"front", {"(P_0 − E)·N"}}, {"back", {"(P_0 − E)·N"}}, {"silhouette", {"F", "G"}}},
            .mistakes = {
                {"front", "(P_0 − E)·N", "negate", "took the view vector from the face to the eye"},
                {"silhouette", "", "event:interior", "marked only edges between two back faces"},
                {"interior", "", "event:silhouette", "took every edge of a front face as an outline"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

std::vector<SilhouetteEdges::Edge> SilhouetteEdges::edge_list(const npr::Mesh& m) {
    std::vector<Edge> edges;
    std::unordered_map<std::uint64_t, int> index;  // {min, max} → position in edges
    index.reserve(m.faces.size() * 4);
    const std::uint64_t nv = m.vertices.size();
    for (std::size_t k = 0; k < m.faces.size(); ++k) {
        const auto& f = m.faces[k];
        for (std::size_t i = 0; i < f.size(); ++i) {
            const int a = f[i], b = f[(i + 1) % f.size()];
            const auto e = id(a, b);
            const std::uint64_t key = static_cast<std::uint64_t>(e[0]) * nv + static_cast<std::uint64_t>(e[1]);
            const auto [it, fresh] = index.try_emplace(key, static_cast<int>(edges.size()));
            if (fresh) {
                edges.push_back({a, b, static_cast<int>(k), -1});
                continue;
            }
            Edge& x = edges[static_cast<std::size_t>(it->second)];
            const std::string field = "faces[" + std::to_string(k) + "]";
            if (x.g >= 0)
                throw InputError(field, "edge " + edge_name(a, b) + " already has two faces (" +
                                            std::to_string(x.f) + " and " + std::to_string(x.g) +
                                            "): a mesh edge joins at most two faces");
            if (x.a == a)
                throw InputError(field, "runs along edge " + edge_name(a, b) + " from P" + std::to_string(a) +
                                            " to P" + std::to_string(b) + " as face " + std::to_string(x.f) +
                                            " does: neighbouring faces must be listed the same way round "
                                            "(both counter-clockwise from outside)");
            x.g = static_cast<int>(k);
        }
    }
    return edges;
}

double SilhouetteEdges::side_of(const Input& in, const std::vector<int>& f) {
    return glm::dot(in.mesh.vertices[static_cast<std::size_t>(f[0])] - in.eye, npr::newell(in.mesh.vertices, f));
}

void SilhouetteEdges::validate(const Input& in) {
    npr::validate(in.mesh);
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(in.eye[c]) || std::fabs(in.eye[c]) > 1e50)
            throw InputError("eye[" + std::to_string(c) + "]", "must be a finite number within ±1e50");
    // The picture's toon shading: the same rules as toon-shading's.
    ToonShading::Input t;
    t.mesh = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, "", 0};
    t.light = in.light;
    t.thresholds = in.thresholds;
    ToonShading::validate(t);
    (void)edge_list(in.mesh);
}

SilhouetteEdges::State SilhouetteEdges::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

SilhouetteEdges::State SilhouetteEdges::begin(Shared<Input> in) {
    State s;
    s.edges = Shared<std::vector<Edge>>(edge_list(in->mesh));
    s.r.front.reserve(in->mesh.faces.size());
    s.r.edges = static_cast<int>(s.edges->size());
    s.in = std::move(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void SilhouetteEdges::advance(State& s) {
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Face: {  // Front or back: the sign of (P_0 − E)·N
            s.side = side_of(*s.in, s.in->mesh.faces[static_cast<std::size_t>(s.k)]);
            s.r.front.push_back(s.side < 0);
            if (++s.k == static_cast<int>(s.in->mesh.faces.size())) s.k = 0, s.phase = Phase::Edge;
            return;
        }
        case Phase::Edge: {  // Compare the edge's two faces
            const Edge& e = (*s.edges)[static_cast<std::size_t>(s.k)];
            if (e.g < 0)
                s.r.boundary.push_back(id(e.a, e.b));
            else if (s.r.front[static_cast<std::size_t>(e.f)] != s.r.front[static_cast<std::size_t>(e.g)])
                s.r.silhouette.push_back(id(e.a, e.b));
            if (++s.k == static_cast<int>(s.edges->size())) s.phase = Phase::Finish;
            return;
        }
        case Phase::Finish:
            std::sort(s.r.silhouette.begin(), s.r.silhouette.end());
            std::sort(s.r.boundary.begin(), s.r.boundary.end());
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

void SilhouetteEdges::narrate(const State& s, StepInfo& info) {
    info = {};
    const auto& in = *s.in;
    if (s.last == Phase::Face) {
        const int k = s.phase == Phase::Face ? s.k - 1 : static_cast<int>(in.mesh.faces.size()) - 1;
        const auto& f = in.mesh.faces[static_cast<std::size_t>(k)];
        const glm::dvec3 p0 = in.mesh.vertices[static_cast<std::size_t>(f[0])];
        const glm::dvec3 n = npr::newell(in.mesh.vertices, f);
        const bool front = s.side < 0;
        info.event = front ? "front" : "back";
        info.line = kLineSide;
        info.narration = "F" + std::to_string(k) + ": N = " + num(n, 4) + ", P_0 − E = " + num(p0 - in.eye, 4) +
                         ", (P_0 − E)·N = " + num(s.side, 4) +
                         (front ? " < 0: front-facing." : s.side == 0 ? " = 0: edge-on, counted as back-facing."
                                                                      : " > 0: back-facing.");
        info.math = "(P_0 - E) \\cdot N = " + tex(p0 - in.eye, 4) + " \\cdot " + tex(n, 4) + " = " + tex(s.side, 4);
        info.vars.push_back({"k", static_cast<long long>(k)});
        info.vars.push_back({"N", vec(n)});
        info.vars.push_back({"(P_0 − E)·N", s.side});
        info.vars.push_back({"front", front});
    } else if (s.last == Phase::Edge) {
        const int k = s.phase == Phase::Edge ? s.k - 1 : static_cast<int>(s.edges->size()) - 1;
        const Edge& e = (*s.edges)[static_cast<std::size_t>(k)];
        const std::string E = edge_name(e.a, e.b);
        auto fb = [&](int f) {
            return "F" + std::to_string(f) + (s.r.front[static_cast<std::size_t>(f)] ? " front" : " back");
        };
        if (e.g < 0) {
            info.event = "boundary";
            info.line = kLineBoundary;
            info.narration = "Edge " + E + " belongs to " + fb(e.f) + " only: a boundary edge, listed apart.";
        } else {
            const bool sil = s.r.front[static_cast<std::size_t>(e.f)] != s.r.front[static_cast<std::size_t>(e.g)];
            info.event = sil ? "silhouette" : "interior";
            info.line = kLineTest;
            info.narration = "Edge " + E + " joins " + fb(e.f) + " and " + fb(e.g) +
                             (sil ? ": they differ, a silhouette edge." : ": the same side, not a silhouette edge.");
        }
        auto side = [&](int f) {
            return std::string(s.r.front[static_cast<std::size_t>(f)] ? "\\text{front}" : "\\text{back}");
        };
        info.math = e.g < 0 ? "F_{" + std::to_string(e.f) + "}: " + side(e.f) + ",\\quad \\text{one face: boundary}"
                            : "F_{" + std::to_string(e.f) + "}: " + side(e.f) + ",\\quad F_{" + std::to_string(e.g) +
                                  "}: " + side(e.g) + (info.event == "silhouette" ? ",\\quad \\text{differ}" : ",\\quad \\text{same}");
        info.vars.push_back({"edge", std::vector<double>{static_cast<double>(id(e.a, e.b)[0]),
                                                         static_cast<double>(id(e.a, e.b)[1])}});
        info.vars.push_back({"F", static_cast<long long>(e.f)});
        info.vars.push_back({"G", static_cast<long long>(e.g)});
        info.vars.push_back({"silhouette", info.event == "silhouette"});
    } else {
        info.event = "done";
        info.line = kLineDone;
        std::string list;
        for (std::size_t i = 0; i < s.r.silhouette.size() && i < 12; ++i)
            list += (i ? ", " : "") + edge_name(s.r.silhouette[i][0], s.r.silhouette[i][1]);
        if (s.r.silhouette.size() > 12) list += ", …";
        info.narration = std::to_string(s.r.edges) + " edges: " + std::to_string(s.r.silhouette.size()) +
                         " on the silhouette" + (list.empty() ? "" : " (" + list + ")") + ", " +
                         std::to_string(s.r.boundary.size()) + " on the boundary.";
        info.math = "\\text{silhouette edges} = " + std::to_string(s.r.silhouette.size());
    }
    info.vars.push_back({"silhouette_count", static_cast<long long>(s.r.silhouette.size())});
}

void SilhouetteEdges::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [plain] --------------------------------------------------------------------------------

[[gnu::flatten]] SilhouetteEdges::Result SilhouetteEdges::compute(const Input& in) {
    const std::vector<Edge> edges = edge_list(in.mesh);
    Result r;
    r.edges = static_cast<int>(edges.size());
    r.front.reserve(in.mesh.faces.size());
    for (const auto& f : in.mesh.faces) r.front.push_back(side_of(in, f) < 0);
    for (const Edge& e : edges) {
        if (e.g < 0)
            r.boundary.push_back(id(e.a, e.b));
        else if (r.front[static_cast<std::size_t>(e.f)] != r.front[static_cast<std::size_t>(e.g)])
            r.silhouette.push_back(id(e.a, e.b));
    }
    std::sort(r.silhouette.begin(), r.silhouette.end());
    std::sort(r.boundary.begin(), r.boundary.end());
    return r;
}

}  // namespace cg
