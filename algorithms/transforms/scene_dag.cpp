// Sections: [helpers] [spec] [validate] [advance] [narrate] [result and traverse]; the picture
// is in scene_dag_draw.cpp
#include "transforms/scene_dag.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/format.hpp"
#include "transforms/rotation_common.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dmat4;
using glm::dvec3;
using Next = SceneDag::Next;
using Event = SceneDag::Event;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line { kLinePush = 1, kLineMultiply, kLineDraw, kLineChildren, kLinePop };

std::string node_field(std::size_t i) {
    return "nodes[" + std::to_string(i) + "]";
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}

// The rotation by `deg` about `axis` (≠ 0): a coordinate axis uses the exact coordinate
// rotation; any other axis Rodrigues' formula R = c I + s K + (1 − c) k kᵀ with k = a / |a|.
dmat3 axis_rotation(dvec3 axis, double deg) {
    const rot::CosSin cs = rot::cos_sin_deg(deg);
    int zeros = 0, along = 0;
    for (int c = 0; c < 3; ++c) {
        if (axis[c] == 0)
            ++zeros;
        else
            along = c;
    }
    if (zeros == 2) return rot::rotation(along, axis[along] > 0 ? cs : rot::inverse(cs));
    const double big = std::max({std::fabs(axis.x), std::fabs(axis.y), std::fabs(axis.z)});
    const dvec3 a = axis / big, k = a / glm::length(a);
    dmat3 m(cs.c);
    // K (cross product with k), column-major: K e_x = (0, k_z, −k_y), ...
    const dmat3 K(dvec3(0, k.z, -k.y), dvec3(-k.z, 0, k.x), dvec3(k.y, -k.x, 0));
    m += cs.s * K;
    m += (1 - cs.c) * glm::outerProduct(k, k);
    return m;
}

struct Resolved {
    std::vector<std::vector<int>> kids;
    int root = -1;
};

// Names to indices; assumes validate() has passed (or reports what it needs to).
Resolved resolve(const SceneDag::Input& in) {
    Resolved r;
    r.kids.resize(in.nodes.size());
    auto find = [&](const std::string& name) {
        for (std::size_t i = 0; i < in.nodes.size(); ++i)
            if (in.nodes[i].name == name) return static_cast<int>(i);
        return -1;
    };
    for (std::size_t i = 0; i < in.nodes.size(); ++i)
        for (const std::string& c : in.nodes[i].children) r.kids[i].push_back(find(c));
    r.root = find(in.root);
    return r;
}

void expand_rec(const SceneDag::Input& in, const std::vector<dmat4>& local, const Resolved& r,
                int n, const dmat4& parent, const std::string& prefix, bool boxes_only,
                std::vector<SceneDag::Draw>& out) {
    const dmat4 m = parent * local[n];
    const std::string path = prefix.empty() ? in.nodes[n].name : prefix + "/" + in.nodes[n].name;
    if (!boxes_only || in.nodes[n].box) out.push_back({path, m});
    for (int c : r.kids[n]) expand_rec(in, local, r, c, m, path, boxes_only, out);
}

std::string path_of(const SceneDag::State& s, std::size_t levels) {
    std::string p;
    for (std::size_t k = 0; k < levels && k < s.path.size(); ++k)
        p += (k ? "/" : "") + s.in.nodes[s.path[k].node].name;
    return p;
}

double clean(double x) {
    return std::fabs(x) < 1e-12 ? 0.0 : x;
}

std::vector<std::vector<double>> rows(const dmat4& m) {
    std::vector<std::vector<double>> r(4, std::vector<double>(4));
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = m[j][i];
    return r;
}

std::string mat_text(const dmat4& m) {
    std::string t = "[";
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) t += (j ? " " : "") + num(clean(m[j][i]), 4);
        t += i < 3 ? "; " : "]";
    }
    return t;
}

// A node's name inside LaTeX: \text{…} with its underscores escaped.
std::string tex_name(const std::string& name) {
    std::string t = "\\text{";
    for (char c : name) {
        if (c == '_' || c == '{' || c == '}' || c == '&' || c == '%' || c == '$' || c == '#')
            t += '\\';
        t += c;
    }
    return t + "}";
}

std::string mat_tex(const dmat4& m) {
    std::string t = "\\begin{bmatrix}";
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) t += (j ? " & " : "") + tex(clean(m[j][i]), 4);
        t += i < 3 ? " \\\\ " : "";
    }
    return t + "\\end{bmatrix}";
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& SceneDag::spec() {
    static const Spec spec{
        "scene-dag",
        "Hierarchical models: DAG traversal with a matrix stack",
        "Hierarchical Models & Transformations",
        {
            "visit(n):  push — copy the top of the stack",
            "  top ← top · M_n          ▷ M_n = T R S, the node's modelling transform",
            "  if n has a shape: draw it with top (its world matrix on this path)",
            "  for each child c of n: visit(c)",
            "  pop — the parent's matrix is the top again",
        },
        {
            {"push", "the top of the matrix stack is copied: the node's changes stay below it"},
            {"multiply", "the top is multiplied on the right by the node's modelling matrix"},
            {"draw", "the node's shape is drawn with the top matrix (its world matrix)"},
            {"pop", "the node is finished: its matrix is popped and the parent's is current"},
        },
        {},  // no sliders
        {
            .predict = {{"push", {}}, {"multiply", {}}, {"draw", {}}, {"pop", {}}},
            .mistakes = {
                {"push", "depth", "keep",
                 "forgot to push: the child's matrix replaces the parent's"},
                {"pop", "depth", "keep", "forgot to pop when leaving a node"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

dmat4 SceneDag::local_matrix(const Node& n) {
    if (n.has_matrix) return n.matrix;
    const dmat3 R = n.has_rotate ? axis_rotation(n.axis, n.angle_deg) : dmat3(1.0);
    dmat4 m(1.0);
    for (int c = 0; c < 3; ++c) m[c] = glm::dvec4(R[c] * n.scale[c], 0.0);
    m[3] = glm::dvec4(n.translate, 1.0);
    return m;
}

void SceneDag::validate(const Input& in) {
    if (in.nodes.empty()) throw InputError("nodes", "must list at least one node");
    if (in.nodes.size() > static_cast<std::size_t>(kMaxNodes))
        throw InputError("nodes", "has " + std::to_string(in.nodes.size()) +
                                      " nodes; the limit is " + std::to_string(kMaxNodes));
    for (std::size_t i = 0; i < in.nodes.size(); ++i) {
        const Node& n = in.nodes[i];
        const std::string f = node_field(i);
        if (n.name.empty()) throw InputError(f + ".name", "must not be empty");
        if (n.name.find('/') != std::string::npos)
            throw InputError(f + ".name", "must not contain \"/\" (it separates the names of a "
                                          "path such as torso/arm), got \"" + n.name + "\"");
        for (std::size_t k = 0; k < i; ++k)
            if (in.nodes[k].name == n.name)
                throw InputError(f + ".name", "\"" + n.name + "\" is already the name of " +
                                                  node_field(k) + "; names must be unique");
        if (n.has_matrix) {
            if (n.translate != dvec3(0) || n.has_rotate || n.scale != dvec3(1))
                throw InputError(f, "gives both a matrix and translate/rotate/scale; give one");
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c)
                    check_finite(n.matrix[c][r], f + ".matrix[" + std::to_string(r) + "][" +
                                                     std::to_string(c) + "]");
            for (int c = 0; c < 4; ++c)
                if (n.matrix[c][3] != (c == 3 ? 1.0 : 0.0))
                    throw InputError(f + ".matrix[3]",
                                     "must be [0, 0, 0, 1]: a modelling transform is affine "
                                     "(a projection does not belong in the scene graph)");
            const dmat3 L(n.matrix);
            double big = 0;
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r) big = std::max(big, std::fabs(L[c][r]));
            const double det = big > 0 ? glm::determinant(L / big) : 0.0;
            if (!(std::fabs(det) > 1e-12))
                throw InputError(f + ".matrix",
                                 "is singular (its upper 3×3 has determinant " +
                                     given(big * big * big * det) +
                                     "): it flattens the node and everything under it, and "
                                     "without an inverse the node's frame and normals are lost");
        } else {
            for (int c = 0; c < 3; ++c) {
                const std::string ci = "[" + std::to_string(c) + "]";
                check_finite(n.translate[c], f + ".transform.translate" + ci);
                check_finite(n.scale[c], f + ".transform.scale" + ci);
                if (n.scale[c] == 0)
                    throw InputError(f + ".transform.scale" + ci,
                                     "is 0: a zero scale flattens the node and everything under "
                                     "it to a plane, and the matrix has no inverse (its frame "
                                     "and normals are lost); use a small positive factor");
            }
            if (n.has_rotate) {
                for (int c = 0; c < 3; ++c)
                    check_finite(n.axis[c],
                                 f + ".transform.rotate.axis[" + std::to_string(c) + "]");
                check_finite(n.angle_deg, f + ".transform.rotate.angle_deg");
                if (n.axis == dvec3(0))
                    throw InputError(f + ".transform.rotate.axis",
                                     "must not be (0, 0, 0): a rotation needs an axis direction");
            }
        }
    }

    const Resolved r = resolve(in);
    for (std::size_t i = 0; i < in.nodes.size(); ++i)
        for (std::size_t j = 0; j < r.kids[i].size(); ++j)
            if (r.kids[i][j] < 0)
                throw InputError(node_field(i) + ".children[" + std::to_string(j) + "]",
                                 "no node is named \"" + in.nodes[i].children[j] + "\"");
    if (in.root.empty()) throw InputError("root", "is missing: name the node to start from");
    if (r.root < 0) throw InputError("root", "no node is named \"" + in.root + "\"");

    // Cycles: depth-first colouring from every node, iteratively (0 white, 1 on the path, 2 done).
    const std::size_t N = in.nodes.size();
    std::vector<int> colour(N, 0);
    for (std::size_t s0 = 0; s0 < N; ++s0) {
        if (colour[s0]) continue;
        std::vector<std::pair<int, std::size_t>> st{{static_cast<int>(s0), 0}};
        colour[s0] = 1;
        while (!st.empty()) {
            auto& [u, j] = st.back();
            if (j == r.kids[u].size()) {
                colour[u] = 2;
                st.pop_back();
                continue;
            }
            const std::size_t jj = j++;
            const int v = r.kids[u][jj];
            if (colour[v] == 1) {
                std::string cyc;
                std::size_t from = 0;
                while (st[from].first != v) ++from;
                for (std::size_t k = from; k < st.size(); ++k)
                    cyc += in.nodes[st[k].first].name + " → ";
                cyc += in.nodes[v].name;
                throw InputError(node_field(u) + ".children[" + std::to_string(jj) + "]",
                                 "closes the cycle " + cyc +
                                     ": a scene graph must be acyclic (a DAG), or the "
                                     "depth-first traversal would never end");
            }
            if (colour[v] == 0) {
                colour[v] = 1;
                st.push_back({v, 0});
            }
        }
    }

    // Depth (nodes on the longest path from the root) and instances (paths), reachable only.
    std::vector<long long> depth(N, -1), paths(N, -1);
    const long long cap = 1LL << 40;
    auto dp = [&](auto&& self, int u) -> void {
        if (depth[u] >= 0) return;
        long long d = 1, p = 1;
        for (int v : r.kids[u]) {
            self(self, v);
            d = std::max(d, 1 + depth[v]);
            p = std::min(cap, p + paths[v]);
        }
        depth[u] = d, paths[u] = p;
    };
    dp(dp, r.root);
    if (depth[r.root] > kMaxDepth)
        throw InputError("root", "the deepest path from \"" + in.root + "\" has " +
                                     std::to_string(depth[r.root]) + " nodes; the limit is " +
                                     std::to_string(kMaxDepth) + " (the matrix stack's depth)");
    if (paths[r.root] > kMaxInstances)
        throw InputError(
            "nodes", "the graph unfolds into " +
                         (paths[r.root] >= cap ? std::string("more than 10^12")
                                               : std::to_string(paths[r.root])) +
                         " node instances (paths from the root), more than the limit of " +
                         std::to_string(kMaxInstances) +
                         ": a node shared by k parents is visited (and drawn) k times");

    for (const Draw& d : expand(in, false))
        for (int c = 0; c < 4; ++c)
            for (int k = 0; k < 3; ++k)
                if (!std::isfinite(d.matrix[c][k]))
                    throw InputError("nodes", "the world matrix of the path " + d.path +
                                                  " overflows a double; scale the model down");
}

SceneDag::State SceneDag::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    Resolved r = resolve(in);
    s.kids = std::move(r.kids);
    s.root = r.root;
    s.local.reserve(in.nodes.size());
    for (const Node& n : in.nodes) s.local.push_back(local_matrix(n));
    s.path.push_back({s.root, 0, Next::Push});
    s.stack.reserve(kMaxDepth + 1);
    s.path.reserve(kMaxDepth);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void SceneDag::advance(State& s) {
    ++s.steps;
    for (;;) {
        Visit& v = s.path.back();
        switch (v.next) {
            case Next::Push:  // copy the top
                s.stack.push_back(s.stack.back());
                s.max_depth = std::max(s.max_depth, depth(s));
                v.next = Next::Multiply;
                s.last = Event::Push;
                return;
            case Next::Multiply:  // top ← top · M
                s.stack.back() = s.stack.back() * s.local[v.node];
                v.next = s.in.nodes[v.node].box ? Next::Draw : Next::Children;
                s.last = Event::Multiply;
                return;
            case Next::Draw: {  // the shape with the top matrix
                std::string p;
                for (const Visit& w : s.path) p += (p.empty() ? "" : "/") + s.in.nodes[w.node].name;
                s.draws.push_back({std::move(p), s.stack.back()});
                v.next = Next::Children;
                s.last = Event::Draw;
                return;
            }
            case Next::Children:  // not a step: descend into the next child, or finish
                if (v.child < static_cast<int>(s.kids[v.node].size())) {
                    const int c = s.kids[v.node][v.child++];
                    s.path.push_back({c, 0, Next::Push});
                } else {
                    v.next = Next::Pop;
                }
                continue;
            case Next::Pop:
                s.stack.pop_back();
                s.path.pop_back();
                s.last = Event::Pop;
                return;
        }
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

void SceneDag::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    const int d = depth(s);
    // After a pop the finished node is gone from the path; the narration names it from the
    // parent's next child (or the root).
    std::string here = path_of(s, s.path.size());
    std::string node;
    if (s.last == Event::Pop) {
        if (s.path.empty()) {
            node = s.in.nodes[s.root].name;
        } else {
            const Visit& p = s.path.back();
            node = s.in.nodes[s.kids[p.node][p.child - 1]].name;
        }
    } else {
        node = s.in.nodes[s.path.back().node].name;
    }
    const std::string D = std::to_string(d);
    switch (s.last) {
        case Event::Push:
            info.event = "push";
            info.line = kLinePush;
            info.narration = "Enter " + here + ": push a copy of the top of the stack (depth " +
                             std::to_string(d - 1) + " → " + D + "), so what " + node +
                             " changes is undone by its pop. The top is still " +
                             mat_text(s.stack.back()) + ".";
            info.math = "\\text{push: } S_{" + D + "} = S_{" + std::to_string(d - 1) +
                        "} = " + mat_tex(s.stack.back());
            break;
        case Event::Multiply: {
            const Node& n = s.in.nodes[s.path.back().node];
            std::string how;
            if (n.has_matrix) {
                how = "given as a matrix";
            } else {
                how = "M = T R S with T = translate " + num(n.translate, 4) + ", R = " +
                      (n.has_rotate ? num(n.angle_deg, 6) + "° about " + num(n.axis, 4)
                                    : std::string("I")) +
                      ", S = scale " + num(n.scale, 4);
            }
            info.event = "multiply";
            info.line = kLineMultiply;
            info.narration = "top ← top · M_" + node + " (" + how + "): M_" + node + " = " +
                             mat_text(s.local[s.path.back().node]) +
                             "; multiplying on the right applies the node's transform first, "
                             "in its parent's frame. The top, the world matrix of " + here +
                             ", is now " + mat_text(s.stack.back()) + ".";
            info.math = "S_{" + D + "} \\leftarrow S_{" + D + "} M_{" + tex_name(node) + "} = " +
                        mat_tex(s.stack.back());
            break;
        }
        case Event::Draw: {
            const dvec3 o(s.stack.back()[3]);
            const dvec3 c = dvec3(s.stack.back() * glm::dvec4(0.5, 0.5, 0.5, 1));
            info.event = "draw";
            info.line = kLineDraw;
            info.narration = "Draw " + node + "'s box with the top matrix (draw " +
                             std::to_string(s.draws.size()) + ", path " + here +
                             "): its centre lands at " + num(o, 4) + " and its corner (½, ½, ½) at " +
                             num(c, 4) + ".";
            info.math = "p_{world} = S_{" + D + "}\\, p_{" + tex_name(node) + "},\\; S_{" + D +
                        "} \\begin{bmatrix} 1/2 \\\\ 1/2 \\\\ 1/2 \\\\ 1 \\end{bmatrix} = " + tex(c, 4);
            break;
        }
        case Event::Pop:
            info.event = "pop";
            info.line = kLinePop;
            info.narration = "Leave " + (here.empty() ? node : here + "/" + node) +
                             ": pop (depth " + std::to_string(d + 1) + " → " + D + ")" +
                             (s.path.empty()
                                  ? ", and the stack is back to I alone: the traversal is done, " +
                                        std::to_string(s.draws.size()) + " shape(s) drawn."
                                  : "; the top is " + here + "'s matrix again, ready for its next "
                                    "child.");
            info.math = "\\text{pop: depth } " + std::to_string(d + 1) + " \\to " + D;
            break;
        case Event::None:
            break;
    }
    info.vars = {{"path", here}, {"depth", static_cast<long long>(d)},
                 {"draws", static_cast<long long>(s.draws.size())}};
    if (s.last == Event::Multiply)
        info.vars.push_back({"M_" + node, rows(s.local[s.path.back().node])});
    for (int k = d; k >= 0; --k)
        info.vars.push_back({"stack[" + std::to_string(k) + "]" + (k == d ? " (top)" : ""),
                             rows(s.stack[k])});
}

void SceneDag::step(State& s, StepInfo* info) {
    if (done(s)) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and traverse] ------------------------------------------------------------------

SceneDag::Result SceneDag::result(const State& s) {
    return {s.draws, s.max_depth, s.steps};
}

SceneDag::Result SceneDag::result(State&& s) {
    return {std::move(s.draws), s.max_depth, s.steps};
}

std::vector<SceneDag::Draw> SceneDag::expand(const Input& in, bool boxes_only) {
    const Resolved r = resolve(in);
    std::vector<dmat4> local;
    local.reserve(in.nodes.size());
    for (const Node& n : in.nodes) local.push_back(local_matrix(n));
    std::vector<Draw> out;
    expand_rec(in, local, r, r.root, dmat4(1.0), "", boxes_only, out);
    return out;
}

[[gnu::flatten]] SceneDag::Result SceneDag::traverse(const Input& in) {
    const Resolved r = resolve(in);
    std::vector<dmat4> local;
    local.reserve(in.nodes.size());
    for (const Node& n : in.nodes) local.push_back(local_matrix(n));
    Result res;
    std::vector<int> path;
    auto visit = [&](auto&& self, int n, const dmat4& parent) -> void {
        path.push_back(n);  // push
        res.max_depth = std::max(res.max_depth, static_cast<int>(path.size()));
        const dmat4 m = parent * local[n];  // multiply
        res.steps += 3;                     // push, multiply, pop
        if (in.nodes[n].box) {              // draw
            std::string p;
            for (int w : path) p += (p.empty() ? "" : "/") + in.nodes[w].name;
            res.draws.push_back({std::move(p), m});
            ++res.steps;
        }
        for (int c : r.kids[n]) self(self, c, m);
        path.pop_back();  // pop
    };
    visit(visit, r.root, dmat4(1.0));
    return res;
}

std::vector<dvec3> SceneDag::corners(const dmat4& m) {
    std::vector<dvec3> c;
    c.reserve(8);
    for (int i = 0; i < 8; ++i)
        c.push_back(dvec3(m * glm::dvec4(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5,
                                          i & 4 ? 0.5 : -0.5, 1.0)));
    return c;
}

}  // namespace cg
