// Scene DAG with a matrix stack: the puppet worked by hand (a shared arm drawn twice with two
// different matrices); 600 random DAGs (shared nodes, coordinate and oblique axes, negative
// scales, whole matrices) whose every draw is checked against the product of its path's
// matrices computed independently in long double; the stack's discipline (push/pop balanced,
// depth back to 0, one step per event); the straight-line traversal; errors naming the field;
// determinism and the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <algorithm>
#include <array>
#include <functional>
#include <limits>

#include "core/rng.hpp"
#include "io/registry.hpp"
#include "support/replay.hpp"
#include "transforms/scene_dag.hpp"

using cg::SceneDag;
using glm::dmat4;
using glm::dvec3;

namespace {

using LM = std::array<std::array<long double, 4>, 4>;  // [row][col]

LM identity() {
    LM m{};
    for (int i = 0; i < 4; ++i) m[i][i] = 1;
    return m;
}

LM mul(const LM& a, const LM& b) {
    LM c{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) c[i][j] += a[i][k] * b[k][j];
    return c;
}

// M = T R S in long double, with R from Rodrigues' formula and std::cos/std::sin of the angle
// in radians — nothing shared with the implementation.
LM reference_local(const SceneDag::Node& n) {
    LM m{};
    if (n.has_matrix) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) m[i][j] = n.matrix[j][i];
        return m;
    }
    long double R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    if (n.has_rotate) {
        const long double len = std::sqrt((long double)n.axis.x * n.axis.x +
                                          (long double)n.axis.y * n.axis.y +
                                          (long double)n.axis.z * n.axis.z);
        const long double k[3] = {n.axis.x / len, n.axis.y / len, n.axis.z / len};
        const long double t = n.angle_deg * 3.14159265358979323846264338327950288L / 180;
        const long double c = std::cos(t), s = std::sin(t);
        const long double K[3][3] = {{0, -k[2], k[1]}, {k[2], 0, -k[0]}, {-k[1], k[0], 0}};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                R[i][j] = (i == j ? c : 0) + s * K[i][j] + (1 - c) * k[i] * k[j];
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[i][j] = R[i][j] * n.scale[j];
        m[i][3] = n.translate[i];
    }
    m[3][3] = 1;
    return m;
}

struct RefDraw {
    std::string path;
    LM m;
};

std::vector<RefDraw> reference(const SceneDag::Input& in) {
    std::vector<RefDraw> out;
    std::function<void(const std::string&, const LM&, const std::string&)> visit =
        [&](const std::string& name, const LM& parent, const std::string& prefix) {
            const SceneDag::Node* n = nullptr;
            for (const auto& x : in.nodes)
                if (x.name == name) n = &x;
            REQUIRE(n);
            const LM m = mul(parent, reference_local(*n));
            const std::string path = prefix.empty() ? name : prefix + "/" + name;
            if (n->box) out.push_back({path, m});
            for (const auto& c : n->children) visit(c, m, path);
        };
    visit(in.root, identity(), "");
    return out;
}

double diff(const dmat4& a, const LM& b) {
    double d = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            d = std::max(d, static_cast<double>(std::fabs(a[j][i] - b[i][j])));
    return d;
}

double size(const LM& b) {
    double d = 1;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) d = std::max(d, static_cast<double>(std::fabs(b[i][j])));
    return d;
}

// The input the JSON layer reads (JsonIo lives in the io library's .cpp).
SceneDag::Input read_input(const cg::json& j) {
    static const cg::Registry registry = cg::builtin_registry();
    const auto run = registry.find("scene-dag")->create(j);
    return dynamic_cast<const cg::RunOf<SceneDag>&>(*run).state.in;
}

SceneDag::Input puppet() {
    static const cg::Registry registry = cg::builtin_registry();
    return read_input(registry.find("scene-dag")->example());
}

struct Walk {
    std::vector<std::string> events;
    std::vector<cg::StepInfo> steps;
    SceneDag::Result result;
    bool balanced = true;  // push: depth +1, pop: depth −1, others: unchanged, never < 0
};

Walk walk(const SceneDag::Input& in, bool narrate) {
    Walk w;
    auto s = SceneDag::start(in);
    int depth = 0;
    while (!SceneDag::done(s)) {
        cg::StepInfo info;
        SceneDag::step(s, narrate ? &info : nullptr);
        const int d = SceneDag::depth(s);
        const SceneDag::Event e = s.last;
        if (e == SceneDag::Event::Push && d != depth + 1) w.balanced = false;
        if (e == SceneDag::Event::Pop && d != depth - 1) w.balanced = false;
        if ((e == SceneDag::Event::Multiply || e == SceneDag::Event::Draw) && d != depth)
            w.balanced = false;
        if (d < 0) w.balanced = false;
        depth = d;
        if (narrate) {
            w.events.push_back(info.event);
            w.steps.push_back(info);
        }
    }
    if (SceneDag::depth(s) != 0 || s.stack.size() != 1 || s.stack[0] != dmat4(1.0))
        w.balanced = false;
    w.result = SceneDag::result(s);
    return w;
}

SceneDag::Node random_node(cg::Rng& rng, const std::string& name) {
    SceneDag::Node n;
    n.name = name;
    if (rng.chance(0.15)) {  // a whole affine matrix: a random invertible 3×3 and a shift
        n.has_matrix = true;
        for (;;) {
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r) n.matrix[c][r] = rng.uniform(-2, 2);
            if (std::fabs(glm::determinant(glm::dmat3(n.matrix))) > 0.05) break;
        }
        for (int r = 0; r < 3; ++r) n.matrix[3][r] = rng.uniform(-3, 3);
        return n;
    }
    if (rng.chance(0.8)) n.translate = {rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3)};
    if (rng.chance(0.8)) {
        n.has_rotate = true;
        if (rng.chance(0.4)) {  // a coordinate axis, either way
            n.axis = dvec3(0);
            n.axis[static_cast<int>(rng.integer(0, 2))] = rng.chance(0.5) ? 2 : -1;
        } else {
            n.axis = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
            if (n.axis == dvec3(0)) n.axis = {1, 1, 1};
        }
        n.angle_deg = rng.chance(0.5) ? 15.0 * static_cast<double>(rng.integer(-24, 24))
                                      : rng.uniform(-720, 720);
    }
    if (rng.chance(0.5))
        for (int c = 0; c < 3; ++c) {
            n.scale[c] = rng.uniform(0.2, 2.0) * (rng.chance(0.15) ? -1 : 1);
        }
    n.box = rng.chance(0.6);
    return n;
}

// A random DAG: edges only from lower to higher index (acyclic by construction), a node may be
// the child of several parents (instancing), sometimes the same child twice.
SceneDag::Input random_dag(cg::Rng& rng) {
    SceneDag::Input in;
    const int N = static_cast<int>(rng.integer(1, 10));
    for (int i = 0; i < N; ++i) in.nodes.push_back(random_node(rng, "n" + std::to_string(i)));
    for (int i = 0; i < N; ++i) {
        const int k = static_cast<int>(rng.integer(0, 3));
        for (int e = 0; e < k && i + 1 < N; ++e)
            in.nodes[i].children.push_back(
                "n" + std::to_string(rng.integer(i + 1, N - 1)));
    }
    in.root = "n0";
    return in;
}

std::string error_of(const std::string& text) {
    static const cg::Registry registry = cg::builtin_registry();
    try {
        registry.find("scene-dag")->create(cg::parse_json(text));
    } catch (const cg::InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

TEST_CASE("scene-dag: the puppet's shared arm is drawn twice with two matrices",
          "[transforms][scene-dag]") {
    const SceneDag::Input in = puppet();
    const Walk w = walk(in, true);
    const std::vector<std::string> want = {
        "push", "multiply",                                              // torso
        "push", "multiply", "draw", "pop",                               // torso_box
        "push", "multiply", "push", "multiply", "draw", "pop", "pop",    // left shoulder, arm
        "push", "multiply", "push", "multiply", "draw", "pop", "pop",    // right shoulder, arm
        "pop"};
    CHECK(w.events == want);
    CHECK(w.balanced);
    REQUIRE(w.result.draws.size() == 3);
    CHECK(w.result.draws[0].path == "torso/torso_box");
    CHECK(w.result.draws[1].path == "torso/left_shoulder/arm");
    CHECK(w.result.draws[2].path == "torso/right_shoulder/arm");
    CHECK(w.result.max_depth == 3);
    CHECK(w.result.steps == 21);
    // By hand: the left arm's origin is (0, 1, 0) + (−0.75, 0.8, 0) + R_z(−30°)(0, −0.6, 0)
    // = (−0.75 − 0.3, 1.8 − 0.3√3, 0); the right arm mirrors it.
    const dvec3 left(w.result.draws[1].matrix[3]), right(w.result.draws[2].matrix[3]);
    CHECK(left.x == Approx(-1.05).margin(1e-15));
    CHECK(left.y == Approx(1.8 - 0.3 * std::sqrt(3.0)).margin(1e-15));
    CHECK(right.x == Approx(1.05).margin(1e-15));
    CHECK(right.y == Approx(left.y).margin(1e-15));
    CHECK(w.result.draws[1].matrix != w.result.draws[2].matrix);
    // The arm's x column: R_z(−30°) (0.3, 0, 0) = (0.3·√3/2, −0.15, 0).
    CHECK(w.result.draws[1].matrix[0][0] == Approx(0.15 * std::sqrt(3.0)).margin(1e-15));
    CHECK(w.result.draws[1].matrix[0][1] == Approx(-0.15).margin(1e-15));
    // The torso's box: scale (1, 2, 0.5) at (0, 1, 0), not passed on to the arms.
    CHECK(w.result.draws[0].matrix == dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 2, 0, 0),
                                            glm::dvec4(0, 0, 0.5, 0), glm::dvec4(0, 1, 0, 1)));
    // Narration names the path; the stack is shown, top first.
    CHECK(w.steps[10].narration.find("torso/left_shoulder/arm") != std::string::npos);
    REQUIRE(w.steps[10].vars.size() >= 4);
    CHECK(w.steps[10].vars[3].name == "stack[3] (top)");
    CHECK(w.steps[10].vars.back().name == "stack[0]");
    CHECK(w.steps.back().narration.find("traversal is done") != std::string::npos);
    CHECK(SceneDag::traverse(in) == w.result);
}

TEST_CASE("scene-dag: every draw equals the product of its path's matrices on random DAGs",
          "[transforms][scene-dag]") {
    cg::Rng rng(20261122);
    int checked = 0, draws = 0, instanced = 0;
    for (int t = 0; t < 600; ++t) {
        const SceneDag::Input in = random_dag(rng);
        try {
            SceneDag::validate(in);
        } catch (const cg::InputError& e) {
            // Only the instance limit may refuse a random DAG.
            CHECK_THAT(e.what(), Catch::Contains("node instances"));
            continue;
        }
        ++checked;
        const bool narrate = t % 7 == 0;
        const Walk w = walk(in, narrate);
        CHECK(w.balanced);
        const std::vector<RefDraw> ref = reference(in);
        REQUIRE(w.result.draws.size() == ref.size());
        for (std::size_t k = 0; k < ref.size(); ++k) {
            CHECK(w.result.draws[k].path == ref[k].path);
            CHECK(diff(w.result.draws[k].matrix, ref[k].m) <= 1e-12 * size(ref[k].m) * 64);
            for (std::size_t j = 0; j < k; ++j) {
                const auto last = [](const std::string& p) { return p.substr(p.rfind('/') + 1); };
                if (last(ref[j].path) == last(ref[k].path) && ref[j].path != ref[k].path)
                    ++instanced;
            }
        }
        draws += static_cast<int>(ref.size());
        // The straight-line traversal computes the very same numbers.
        CHECK(SceneDag::traverse(in) == w.result);
        // One step per push, multiply and pop of each instance and per draw.
        CHECK(w.result.steps ==
              static_cast<int>(3 * SceneDag::expand(in, false).size() + ref.size()));
    }
    CHECK(checked > 500);
    CHECK(draws > 1000);
    CHECK(instanced > 100);  // shared nodes were exercised
}

TEST_CASE("scene-dag: a shared node gets a distinct matrix per path", "[transforms][scene-dag]") {
    // A diamond: root → a, b; a → leaf, b → leaf; a and b shift differently.
    const std::string text = R"({"nodes": [
        {"name": "root", "children": ["a", "b"]},
        {"name": "a", "transform": {"translate": [1, 0, 0]}, "children": ["leaf"]},
        {"name": "b", "transform": {"rotate": {"axis": [0, 1, 0], "angle_deg": 90}},
         "children": ["leaf", "leaf"]},
        {"name": "leaf", "transform": {"translate": [0, 0, 2]}, "shape": "box"}],
        "root": "root"})";
    const SceneDag::Input in = read_input(cg::parse_json(text));
    const Walk w = walk(in, false);
    REQUIRE(w.result.draws.size() == 3);
    CHECK(w.result.draws[0].path == "root/a/leaf");
    CHECK(w.result.draws[1].path == "root/b/leaf");
    CHECK(w.result.draws[2].path == "root/b/leaf");
    CHECK(dvec3(w.result.draws[0].matrix[3]) == dvec3(1, 0, 2));
    CHECK(dvec3(w.result.draws[1].matrix[3]) == dvec3(2, 0, 0));  // R_y(90°) (0, 0, 2)
    CHECK(w.result.max_depth == 3);
    // The result's corners are the unit cube's under the draw matrix.
    const auto c = SceneDag::corners(w.result.draws[0].matrix);
    CHECK(c[0] == dvec3(0.5, -0.5, 1.5));
    CHECK(c[7] == dvec3(1.5, 0.5, 2.5));
}

TEST_CASE("scene-dag: bad input is refused naming the field", "[transforms][scene-dag]") {
    auto dag = [](const std::string& nodes, const std::string& root = "\"a\"") {
        return error_of("{\"nodes\": [" + nodes + "], \"root\": " + root + "}");
    };
    CHECK(dag(R"({"name": "a", "children": ["b"]}, {"name": "b"})") == "(accepted)");
    CHECK(dag(R"({"name": "a", "children": ["b"]}, {"name": "b"}, {"name": "c", "children": ["zz"]})") ==
          "nodes[2].children[0]: no node is named \"zz\"");
    CHECK(dag(R"({"name": "a", "children": ["b"]}, {"name": "b", "children": ["c"]},
                 {"name": "c", "children": ["a"]})") ==
          "nodes[2].children[0]: closes the cycle a → b → c → a: a scene graph must be acyclic "
          "(a DAG), or the depth-first traversal would never end");
    CHECK_THAT(dag(R"({"name": "a", "children": ["a"]})"),
               Catch::StartsWith("nodes[0].children[0]: closes the cycle a → a"));
    CHECK_THAT(error_of(R"({"nodes": [{"name": "a"}]})"), Catch::StartsWith("root: is missing"));
    CHECK(dag(R"({"name": "a"})", "\"b\"") == "root: no node is named \"b\"");
    CHECK_THAT(dag(R"({"name": "a"}, {"name": "a"})"),
               Catch::StartsWith("nodes[1].name: \"a\" is already the name of nodes[0]"));
    CHECK_THAT(dag(R"({"name": "a/b"})", "\"a/b\""), Catch::StartsWith("nodes[0].name: must not contain"));
    CHECK_THAT(dag(R"({"name": "a", "transform": {"scale": [1, 0, 1]}})"),
               Catch::StartsWith("nodes[0].transform.scale[1]: is 0: a zero scale flattens"));
    CHECK_THAT(dag(R"({"name": "a", "transform": {"rotate": {"axis": [0, 0, 0], "angle_deg": 5}}})"),
               Catch::StartsWith("nodes[0].transform.rotate.axis: must not be (0, 0, 0)"));
    CHECK_THAT(dag(R"({"name": "a", "transform": {"rotate": {"axis": [0, 0, 1]}}})"),
               Catch::StartsWith("nodes[0].transform.rotate.angle_deg: is missing"));
    CHECK_THAT(dag(R"({"name": "a", "transform": {"shear": 1}})"),
               Catch::StartsWith("nodes[0].transform.shear: is not a known field"));
    CHECK_THAT(dag(R"({"name": "a", "shape": "sphere"})"),
               Catch::StartsWith("nodes[0].shape: must be \"box\" or \"none\""));
    CHECK_THAT(dag(R"({"name": "a", "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]})"),
               Catch::StartsWith("nodes[0].matrix[3]: must be [0, 0, 0, 1]"));
    CHECK_THAT(dag(R"({"name": "a", "matrix": [[1, 2, 0, 0], [2, 4, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]})"),
               Catch::StartsWith("nodes[0].matrix: is singular"));
    CHECK_THAT(dag(R"({"name": "a", "matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]})"),
               Catch::StartsWith("nodes[0].matrix: must be a 4×4 matrix"));
    CHECK_THAT(dag(R"({"name": "a", "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
                       "transform": {}})"),
               Catch::StartsWith("nodes[0]: gives both"));
    CHECK_THAT(dag(R"({"name": "a", "children": "b"})"),
               Catch::StartsWith("nodes[0].children: must be a list"));
    CHECK_THAT(dag(R"({"name": "a", "children": [3]})"),
               Catch::StartsWith("nodes[0].children[0]: must be a node's name"));
    CHECK_THAT(error_of(R"({"nodes": [], "root": "a"})"), Catch::StartsWith("nodes: must list"));

    // Depth: a chain of 64 is fine, 65 is refused.
    auto chain = [](int n) {
        std::string s;
        for (int i = 0; i < n; ++i)
            s += (i ? ", " : "") + std::string("{\"name\": \"a") + std::to_string(i) + "\"" +
                 (i + 1 < n ? ", \"children\": [\"a" + std::to_string(i + 1) + "\"]" : "") + "}";
        return s;
    };
    CHECK(error_of("{\"nodes\": [" + chain(64) + "], \"root\": \"a0\"}") == "(accepted)");
    CHECK_THAT(error_of("{\"nodes\": [" + chain(65) + "], \"root\": \"a0\"}"),
               Catch::StartsWith("root: the deepest path from \"a0\" has 65 nodes; the limit is 64"));

    // Instances: a ladder whose every level points twice at the next doubles the paths.
    auto ladder = [](int n) {
        std::string s;
        for (int i = 0; i < n; ++i) {
            const std::string next = "\"a" + std::to_string(i + 1) + "\"";
            s += (i ? ", " : "") + std::string("{\"name\": \"a") + std::to_string(i) + "\"" +
                 (i + 1 < n ? ", \"children\": [" + next + ", " + next + "]" : "") + "}";
        }
        return s;
    };
    CHECK(error_of("{\"nodes\": [" + ladder(9) + "], \"root\": \"a0\"}") == "(accepted)");  // 511
    CHECK_THAT(error_of("{\"nodes\": [" + ladder(10) + "], \"root\": \"a0\"}"),
               Catch::StartsWith("nodes: the graph unfolds into 1023 node instances"));
    CHECK_THAT(error_of("{\"nodes\": [" + ladder(60) + "], \"root\": \"a0\"}"),
               Catch::StartsWith("nodes: the graph unfolds into more than 10^12 node instances"));

    // Overflow of a world matrix, and NaN given directly.
    CHECK_THAT(dag(R"({"name": "a", "transform": {"scale": [1e200, 1, 1]}, "children": ["b"]},
                      {"name": "b", "transform": {"scale": [1e200, 1, 1]}})"),
               Catch::StartsWith("nodes: the world matrix of the path a/b overflows"));
    SceneDag::Input in = puppet();
    in.nodes[1].translate.y = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(SceneDag::start(in),
                      "nodes[1].transform.translate[1]: must be a finite number (got NaN)");
    in = puppet();
    in.nodes[2].angle_deg = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(SceneDag::start(in), Catch::StartsWith("nodes[2].transform.rotate.angle_deg"));
}

TEST_CASE("scene-dag: traces are deterministic and stepping back reproduces them",
          "[transforms][scene-dag]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("scene-dag");
    REQUIRE(a);
    cg::test::check_replay(*a, a->example(), cg::test::kEveryStep);
    REQUIRE(a->exam_input);
    for (std::uint64_t seed = 1; seed <= 5; ++seed)
        cg::test::check_replay(*a, a->exam_input(seed), 3);
    auto run = a->create(a->example());
    while (!run->done()) run->step(nullptr);
    const cg::json r = a->result(*run);
    CHECK(r["draws"].size() == 3);
    CHECK(r["corners"].size() == 3);
    CHECK(r["corners"][0].size() == 8);
    CHECK(r["max_depth"] == 3);
}

TEST_CASE("scene-dag: exam arms are valid and their hand's matrix is the path product",
          "[transforms][scene-dag]") {
    cg::Rng rng(11);
    for (int t = 0; t < 200; ++t) {
        const SceneDag::Input in = SceneDag::exam_input(rng);
        REQUIRE_NOTHROW(SceneDag::validate(in));
        const Walk w = walk(in, false);
        REQUIRE(w.result.draws.size() == 1);
        const auto ref = reference(in);
        CHECK(diff(w.result.draws[0].matrix, ref[0].m) < 1e-12);
        CHECK(SceneDag::question(in).find("hand") != std::string::npos);
    }
}

TEST_CASE("scene-dag: the picture shows the boxes, the path and the current frame",
          "[transforms][scene-dag]") {
    auto s = SceneDag::start(puppet());
    for (int k = 0; k < 11; ++k) SceneDag::step(s, nullptr);  // the left arm just drawn
    REQUIRE(s.last == SceneDag::Event::Draw);
    cg::Scene scene;
    SceneDag::draw(s, scene);
    auto count = [](const auto& items, cg::Role role) {
        return std::count_if(items.begin(), items.end(),
                             [&](const auto& i) { return i.style.role == role; });
    };
    // Two boxes so far (the torso's green, the arm's orange), the other arm a grey ghost.
    CHECK(count(scene.faces3, cg::Role::Kept) == 6);
    CHECK(count(scene.faces3, cg::Role::Active) == 6);
    CHECK(count(scene.faces3, cg::Role::Construction) == 6);
    CHECK(count(scene.segments3, cg::Role::Active) == 3);  // origin → torso → shoulder → arm
    CHECK(scene.points3.back().label == "arm");
    REQUIRE(scene.frames3.size() == 1);  // the world's
    CHECK(scene.frames3[0].name.empty());
    std::vector<std::string> axes;  // the current node's frame, apart from the world's x, y, z
    for (const auto& seg : scene.segments3)
        if (seg.style.rgba != 0) axes.push_back(seg.label);
    CHECK(axes == std::vector<std::string>{"x′", "y′", "z′"});
    REQUIRE(scene.focus3.size() == 1);  // the whole model
    CHECK(scene.focus3[0].hi.x - scene.focus3[0].lo.x > 2);
}

TEST_CASE("scene-dag: a part translated by 1e300 keeps the picture's framing finite",
          "[transforms][scene-dag]") {
    // Found by fuzz_algorithm_input: glm::length squared the translation and overflowed.
    const cg::json in = cg::json::parse(R"({"nodes": [
        {"name": "table", "children": ["top", "far"]},
        {"name": "top", "transform": {"scale": [2, 0.1, 1]}, "shape": "box"},
        {"name": "far", "transform": {"translate": [1e300, 0, 0.4], "scale": [1e-3, 1e-3, 1e-3]},
         "shape": "box"}], "root": "table"})");
    auto run = cg::builtin_registry().find("scene-dag")->create(in);
    while (!run->done()) {
        run->step(nullptr);
        cg::Scene scene;
        run->draw(scene);
        REQUIRE(scene.focus3.size() == 1);
        CHECK(std::isfinite(scene.focus3[0].hi.x));
        CHECK(scene.focus3[0].hi.x >= 1e300);
    }
}
