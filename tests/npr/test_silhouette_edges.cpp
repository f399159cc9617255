// Silhouette edges against a brute-force reference: every pair of faces, in long double, the
// shared edges found by comparing their corner lists and the front/back test made with a
// normal from the face's own Newell sum in long double; boundary edges by counting each edge's
// faces over all faces. Cube counts (4 or 6 edges from any outside eye), closed loops on the
// sphere and torus (every vertex meets an even number of silhouette edges), open meshes, edge-on
// faces, refused meshes, the state machine against the plain function and the exam.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "npr/silhouette_edges.hpp"

using cg::SilhouetteEdges;
using Edges = std::vector<SilhouetteEdges::EdgeId>;

namespace {

cg::npr::Mesh cube() {
    cg::npr::Mesh m;
    m.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}};
    m.faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    return m;
}

SilhouetteEdges::Input with_eye(cg::npr::Mesh m, glm::dvec3 eye) {
    SilhouetteEdges::Input in;
    in.mesh = std::move(m);
    in.eye = eye;
    return in;
}

// (P_0 − E)·N in long double, N by Newell's sum.
long double side_ref(const SilhouetteEdges::Input& in, const std::vector<int>& f) {
    long double n[3] = {0, 0, 0};
    for (std::size_t i = 0; i < f.size(); ++i) {
        const glm::dvec3 a = in.mesh.vertices[f[i]], b = in.mesh.vertices[f[(i + 1) % f.size()]];
        n[0] += ((long double)a.y - b.y) * ((long double)a.z + b.z);
        n[1] += ((long double)a.z - b.z) * ((long double)a.x + b.x);
        n[2] += ((long double)a.x - b.x) * ((long double)a.y + b.y);
    }
    const glm::dvec3 p = in.mesh.vertices[f[0]];
    return ((long double)p.x - in.eye.x) * n[0] + ((long double)p.y - in.eye.y) * n[1] +
           ((long double)p.z - in.eye.z) * n[2];
}

struct Reference {
    Edges silhouette, boundary;
    bool doubtful = false;  // some face within rounding of edge-on
};

Reference reference(const SilhouetteEdges::Input& in) {
    const auto& F = in.mesh.faces;
    Reference r;
    std::vector<bool> front;
    for (const auto& f : F) {
        const long double s = side_ref(in, f);
        front.push_back(s < 0);
        r.doubtful = r.doubtful || (s != 0 && std::fabs(s) < 1e-9L);
    }
    auto has_edge = [](const std::vector<int>& f, int a, int b) {
        for (std::size_t i = 0; i < f.size(); ++i) {
            const int x = f[i], y = f[(i + 1) % f.size()];
            if ((x == a && y == b) || (x == b && y == a)) return true;
        }
        return false;
    };
    for (std::size_t i = 0; i < F.size(); ++i)
        for (std::size_t j = i + 1; j < F.size(); ++j)
            for (std::size_t c = 0; c < F[i].size(); ++c) {
                const int a = F[i][c], b = F[i][(c + 1) % F[i].size()];
                if (has_edge(F[j], a, b) && front[i] != front[j])
                    r.silhouette.push_back({std::min(a, b), std::max(a, b)});
            }
    for (std::size_t i = 0; i < F.size(); ++i)
        for (std::size_t c = 0; c < F[i].size(); ++c) {
            const int a = F[i][c], b = F[i][(c + 1) % F[i].size()];
            int count = 0;
            for (const auto& g : F) count += has_edge(g, a, b);
            if (count == 1) r.boundary.push_back({std::min(a, b), std::max(a, b)});
        }
    std::sort(r.silhouette.begin(), r.silhouette.end());
    std::sort(r.boundary.begin(), r.boundary.end());
    return r;
}

std::map<int, int> degrees(const Edges& e) {
    std::map<int, int> d;
    for (const auto& x : e) ++d[x[0]], ++d[x[1]];
    return d;
}

}  // namespace

TEST_CASE("silhouette-edges: the cube from a general point has a six-edge silhouette", "[npr][silhouette]") {
    const auto r = SilhouetteEdges::compute(with_eye(cube(), {5, 4, 6}));
    // Front: the faces z = 2 (F1), y = 2 (F3) and x = 2 (F5).
    CHECK(r.front == std::vector<bool>{false, true, false, true, false, true});
    CHECK(r.silhouette == Edges{{1, 2}, {1, 5}, {2, 3}, {3, 7}, {4, 5}, {4, 7}});
    CHECK(r.edges == 12);
    CHECK(r.boundary.empty());
    // One face seen: its four edges; two faces: six.
    CHECK(SilhouetteEdges::compute(with_eye(cube(), {1, 1, 6})).silhouette == Edges{{4, 5}, {4, 7}, {5, 6}, {6, 7}});
    CHECK(SilhouetteEdges::compute(with_eye(cube(), {6, 1, 6})).silhouette.size() == 6);
}

TEST_CASE("silhouette-edges: an edge-on face counts as back-facing", "[npr][silhouette]") {
    // The eye in the plane y = 2 of the top face F3: (P_0 − E)·N = 0. Only F1 (z = 2) is front.
    SilhouetteEdges::State s = SilhouetteEdges::start(with_eye(cube(), {1, 2, 6}));
    cg::StepInfo info;
    std::vector<std::string> events;
    while (!SilhouetteEdges::done(s)) SilhouetteEdges::step(s, &info), events.push_back(info.event);
    CHECK(events[3] == "back");
    const auto r = SilhouetteEdges::result(s);
    CHECK(r.front == std::vector<bool>{false, true, false, false, false, false});
    CHECK(r.silhouette == Edges{{4, 5}, {4, 7}, {5, 6}, {6, 7}});
    CHECK(events.back() == "done");
}

TEST_CASE("silhouette-edges: any outside eye sees a cube silhouette of 4 or 6 edges", "[npr][silhouette]") {
    int sixes = 0, fours = 0;
    for (std::uint64_t seed = 0; seed < 2000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        glm::dvec3 e{rng.uniform(-6, 8), rng.uniform(-6, 8), rng.uniform(-6, 8)};
        if (e.x > 0 && e.x < 2 && e.y > 0 && e.y < 2 && e.z > 0 && e.z < 2) continue;
        const auto in = with_eye(cube(), e);
        const auto r = SilhouetteEdges::compute(in);
        int outside = 0;  // the faces the eye is outside of = the faces seen
        for (int c = 0; c < 3; ++c) outside += e[c] < 0 || e[c] > 2;
        CHECK(r.silhouette.size() == (outside == 1 ? 4u : 6u));
        (outside == 1 ? fours : sixes) += 1;
        CHECK(r.silhouette == reference(in).silhouette);
        for (const auto& [v, d] : degrees(r.silhouette)) CHECK(d == 2);  // one closed loop
    }
    CHECK(sixes > 1000);
    CHECK(fours > 50);
}

TEST_CASE("silhouette-edges: agrees with the brute-force pairs on spheres, tori and random eyes, closed loops",
          "[npr][silhouette]") {
    const cg::npr::Mesh meshes[] = {cg::npr::generate("sphere", 8), cg::npr::generate("sphere", 16),
                                    cg::npr::generate("torus", 12), cg::npr::generate("torus", 16)};
    int runs = 0, doubtful = 0;
    for (std::size_t mi = 0; mi < std::size(meshes); ++mi)
        for (std::uint64_t seed = 0; seed < 250; ++seed) {
            CAPTURE(mi, seed);
            cg::Rng rng(seed * 7 + mi);
            glm::dvec3 e;
            do e = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
            while (glm::length(e) < 1.6);
            const auto in = with_eye(meshes[mi], e);
            const auto r = SilhouetteEdges::compute(in);
            const Reference ref = reference(in);
            ++runs;
            if (ref.doubtful) {
                ++doubtful;
                continue;
            }
            CHECK(r.silhouette == ref.silhouette);
            CHECK(r.boundary.empty());
            CHECK(r.silhouette.size() >= 3);
            for (const auto& [v, d] : degrees(r.silhouette)) CHECK(d % 2 == 0);
        }
    CHECK(runs == 1000);
    CHECK(doubtful < 10);
}

TEST_CASE("silhouette-edges: open meshes list their boundary apart", "[npr][silhouette]") {
    cg::npr::Mesh open = cube();
    open.faces.pop_back();  // no x = 2 face: its four edges are the rim
    const auto in = with_eye(open, {5, 4, 6});
    const auto r = SilhouetteEdges::compute(in);
    CHECK(r.boundary == Edges{{1, 2}, {1, 5}, {2, 6}, {5, 6}});
    CHECK(r.boundary == reference(in).boundary);
    CHECK(r.silhouette == reference(in).silhouette);
    CHECK(r.edges == 12);
    // Random open grids: a height field seen from above and the side.
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        SilhouetteEdges::Input g;
        const int n = 4;
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) g.mesh.vertices.push_back({i, rng.uniform(-1, 1), j});
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const int a = j * (n + 1) + i;
                g.mesh.faces.push_back({a, a + n + 1, a + 1});
                g.mesh.faces.push_back({a + 1, a + n + 1, a + n + 2});
            }
        g.eye = {rng.uniform(-3, 7), rng.uniform(1, 4), rng.uniform(-3, 7)};
        const auto gr = SilhouetteEdges::compute(g);
        const Reference ref = reference(g);
        if (ref.doubtful) continue;
        CHECK(gr.boundary.size() == 16u);
        CHECK(gr.boundary == ref.boundary);
        CHECK(gr.silhouette == ref.silhouette);
    }
}

TEST_CASE("silhouette-edges: the state machine equals the plain function, copies and traces repeat",
          "[npr][silhouette]") {
    const auto in = with_eye(cg::npr::generate("torus", 16), {2, 3, 4});
    SilhouetteEdges::State s = SilhouetteEdges::start(in);
    for (int i = 0; i < 150; ++i) SilhouetteEdges::step(s, nullptr);
    SilhouetteEdges::State copy = s;
    std::vector<cg::StepInfo> a, b;
    cg::StepInfo info;
    while (!SilhouetteEdges::done(s)) SilhouetteEdges::step(s, &info), a.push_back(info);
    while (!SilhouetteEdges::done(copy)) SilhouetteEdges::step(copy, &info), b.push_back(info);
    CHECK(a == b);
    CHECK(copy == s);
    CHECK(SilhouetteEdges::result(s) == SilhouetteEdges::compute(in));
    // 128 faces, 256 edges: 128 face steps + 256 edge steps + done, 150 taken before.
    CHECK(a.size() == 128 + 256 + 1 - 150);
}

TEST_CASE("silhouette-edges: bad meshes are refused, naming the field", "[npr][silhouette][errors]") {
    static const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("silhouette-edges");
    REQUIRE(a);
    auto error_of = [&](const cg::json& j) -> std::string {
        try {
            a->create(j);
        } catch (const cg::InputError& e) {
            return e.what();
        }
        return "";
    };
    const cg::json base = a->example();
    CHECK(error_of(base).empty());
    auto with = [&](const char* key, cg::json v) {
        cg::json j = base;
        j[key] = std::move(v);
        return j;
    };
    // A face listed clockwise: it runs along its neighbours' edges the same way they do.
    CHECK_THAT(error_of(with("faces", cg::json::parse("[[0, 3, 2, 1], [4, 7, 6, 5], [0, 1, 5, 4]]"))),
               Catch::Contains("faces[2]") && Catch::Contains("same way round"));
    // Three faces on one edge.
    CHECK_THAT(error_of(with("faces", cg::json::parse("[[0, 1, 2], [1, 0, 3], [0, 1, 4]]"))),
               Catch::Contains("faces[2]") && Catch::Contains("two faces"));
    CHECK_THAT(error_of(with("faces", cg::json::parse("[[0, 1, -1]]"))), Catch::Contains("faces[0][2]"));
    CHECK_THAT(error_of(with("eye", cg::json::parse("[1, 2]"))), Catch::Contains("eye"));
    CHECK_THAT(error_of(with("thresholds", cg::json::parse("[0.9, 0.2]"))), Catch::Contains("thresholds[1]"));
    CHECK_THAT(error_of(with("light", cg::json::parse("[0, 0, 0]"))), Catch::Contains("light"));
    CHECK_THAT(error_of(with("vertices", cg::json::parse("[[0, 0, 0], [1, 0, 0]]"))), Catch::Contains("vertices"));
    cg::json bogus = base;
    bogus["colour"] = 1;
    CHECK_THAT(error_of(bogus), Catch::Contains("colour"));
}

TEST_CASE("silhouette-edges: exam answers match the brute-force reference", "[npr][silhouette][exam]") {
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        CAPTURE(seed);
        cg::Rng rng(seed);
        const SilhouetteEdges::Input in = SilhouetteEdges::exam_input(rng);
        const auto r = SilhouetteEdges::compute(in);
        const Reference ref = reference(in);
        REQUIRE(!ref.doubtful);  // integers: exact
        CHECK(r.silhouette == ref.silhouette);
        CHECK(r.silhouette.size() >= 3);
        for (const auto& [v, d] : degrees(r.silhouette)) CHECK(d % 2 == 0);
        CHECK_THAT(SilhouetteEdges::question(in), Catch::Contains("E = "));
    }
    static const cg::Registry registry = cg::builtin_registry();
    const cg::ExamProblem p = cg::make_exam(*registry.find("silhouette-edges"), 3);
    CHECK(p.answers == std::vector<std::string>{"silhouette"});
}

TEST_CASE("silhouette-edges: the picture — seen from beside the eye, framed on the step's face or edge",
          "[npr][silhouette]") {
    auto s = SilhouetteEdges::start(with_eye(cube(), {5, 4, 6}));
    SilhouetteEdges::step(s, nullptr);  // the first face
    cg::Scene face;
    SilhouetteEdges::draw(s, face);
    // Not along the line of sight: from there the eye would sit on the cube.
    const glm::dvec3 sight = glm::normalize(glm::dvec3(5, 4, 6) - glm::dvec3(1));
    CHECK(glm::dot(-face.view3.look, sight) < 0.9);
    REQUIRE(face.focus3.size() == 1);
    CHECK(face.focus3[0].hi.z >= 6);  // the eye is in the frame with the face
    bool normal = false, to_face = false;
    for (const auto& seg : face.segments3) {
        normal = normal || (seg.label == "N̂" && seg.min_pixels >= 30);
        to_face = to_face || seg.label == "P₀ − E";
    }
    CHECK(normal);
    CHECK(to_face);
    while (s.phase == SilhouetteEdges::Phase::Face) SilhouetteEdges::step(s, nullptr);
    SilhouetteEdges::step(s, nullptr);  // the first edge
    cg::Scene edge;
    SilhouetteEdges::draw(s, edge);
    REQUIRE(edge.focus3.size() == 1);
    int active = 0;
    for (const auto& seg : edge.segments3) active += seg.style.role == cg::Role::Active;
    CHECK(active == 1);
}
