// Sections: [helpers] [spec] [validate] [build] [trace] [step] [narrate]
// (the picture: bvh_draw.cpp)
#include "accel/bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "accel/ray_aabb.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using glm::dvec3;
using Node = Bvh::Node;
using NodeKind = Bvh::NodeKind;
using Phase = Bvh::Phase;
using Visit = Bvh::Visit;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineBuild = 1,
    kLineBounds,
    kLineLeaf,
    kLineSort,
    kLineCut,
    kLineNoGain,
    kLineRecurse,
    kLineTrace,
    kLinePop,
    kLineSlab,
    kLinePrune,
    kLineLeafTest,
    kLinePush,
    kLineReturn,
};

const char* const kAxis[3] = {"x", "y", "z"};
constexpr double kCoordLimit = 1e150;

std::string at(const std::string& name, int i) {
    return name + "[" + std::to_string(i) + "]";
}

// The longest axis of a box (ties: x before y before z).
int longest_axis(const Bounds& b) {
    const dvec3 e = b.extent();
    int axis = 0;
    if (e.y > e[axis]) axis = 1;
    if (e.z > e[axis]) axis = 2;
    return axis;
}

// Every primitive's bounds, once per run.
std::vector<Bounds> primitive_bounds(const Bvh::Input& in) {
    std::vector<Bounds> out;
    out.reserve(in.primitives.size());
    for (const Primitive& p : in.primitives) out.push_back(bounds(p));
    return out;
}

// The surface area of b with its sides divided by `scale` (about the parent's longest side): the
// ratios S_L/S do not change, and neither huge nor tiny scenes overflow or underflow.
double scaled_area(const Bounds& b, double scale) {
    if (b.empty()) return 0;
    const dvec3 e = b.extent() / scale;
    return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

}  // namespace

double Bvh::sah_cost(const Bounds& node, const Bounds& l, int n_l, const Bounds& r, int n_r) {
    // The scale is the power of two at or above the longest side: dividing by it is exact, so
    // integer boxes keep exact areas (and a mirror-image tie stays a tie).
    const dvec3 e = node.extent();
    int exponent = 0;
    std::frexp(std::max({e.x, e.y, e.z}), &exponent);
    const double scale = std::ldexp(1.0, exponent);
    const double S = scaled_area(node, scale);
    // One sum over the two sides, so a mirror-image cut costs exactly the same (its tie is
    // then broken by k, not by rounding).
    return kTraversalCost +
           kIntersectCost * (scaled_area(l, scale) * n_l + scaled_area(r, scale) * n_r) / S;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Bvh::spec() {
    static const Spec spec{
        "bvh",
        "Bounding volume hierarchy: build (median or SAH) and trace a ray",
        "Bounding Boxes and Spatial Subdivision",
        {
            "build(node with n primitives):",
            "  bounds ← the union of the primitives' boxes",
            "  if n ≤ max_leaf: make a leaf; return",
            "  axis ← longest axis of the centroids' box; sort by (centroid[axis], index)",
            "  median: k ← ⌊n/2⌋;  sah: k ← argmin C(k) = C_trav + S_L/S·N_L·C_isect + "
            "S_R/S·N_R·C_isect",
            "  if sah and C(k) ≥ n·C_isect: make a leaf (no split helps); return",
            "  build(left: the first k);  build(right: the other n − k)",
            "trace(E, d):  stack ← [root];  t_best ← ∞",
            "  while the stack is not empty: node ← pop",
            "    slab test of node's box → [t_enter, t_exit];  if it misses: continue",
            "    if t_enter > t_best: continue                ▷ prune: only farther hits there",
            "    if leaf: for each primitive: t ← intersect; if t < t_best: t_best ← t, hit ← it",
            "    else: push the far child, then the near one (near: the side d points from)",
            "return hit, t_best, box_tests, primitive_tests",
        },
        {
            {"leaf", "a node with ≤ max_leaf primitives: a leaf holding them"},
            {"leaf-no-gain", "SAH: no cut is cheaper than testing all n primitives: a leaf"},
            {"split-median", "sorted along the longest centroid axis, cut in the middle"},
            {"split-sah", "sorted along the longest centroid axis, cut where C(k) is least"},
            {"box-miss", "the slab test misses the popped node's box: all it holds is skipped"},
            {"box-pruned", "the box is hit, but only beyond the closest hit so far: skipped"},
            {"push-children", "an inner node's box is hit: its children go on the stack"},
            {"leaf-tested", "a leaf's box is hit: its primitives tested, no closer hit"},
            {"leaf-hit", "a leaf's box is hit: one of its primitives is the closest hit so far"},
            {"result", "the stack is empty: the closest hit and the counts against brute force"},
        },
        {},  // no sliders
        {
            .predict = {
                {"split-median", {"k"}},
                {"split-sah", {"k"}},
                {"push-children", {"t_enter"}},
                {"leaf-hit", {"t_best"}},
                {"box-miss", {}},
                {"box-pruned", {}},
            },
            .mistakes = {
                {"box-pruned", "", "event:push-children",
                 "opened a box that starts beyond the best hit"},
                {"push-children", "stack", "reverse",
                 "pushed the near child first, so far pops first"},
                {"leaf-no-gain", "", "event:split-sah",
                 "split though the SAH cost is not below a leaf"},
            },
            .costs = {"counts", "brute_force"},  // tests per ray beside brute force's
            .variants = {{"median", "/split", "\"median\""}, {"sah", "/split", "\"sah\""}},
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void Bvh::validate(const Input& in) {
    if (in.primitives.empty()) throw InputError("primitives", "must list at least one primitive");
    if (in.primitives.size() > kMaxPrimitives)
        throw InputError("primitives", "lists " + std::to_string(in.primitives.size()) +
                                           " primitives; at most " +
                                           std::to_string(kMaxPrimitives) +
                                           " (every node of the build is a step)");
    if (in.max_leaf < 1 || in.max_leaf > kMaxLeafLimit)
        throw InputError("max_leaf", "must be a whole number from 1 to " +
                                         std::to_string(kMaxLeafLimit) + ", got " +
                                         std::to_string(in.max_leaf));
    // Beyond ±1e150 the squares in the intersection formulas (|E − C|², cross products) would
    // overflow a double.
    auto check = [](double v, const std::string& field) {
        if (!std::isfinite(v) || std::fabs(v) > kCoordLimit)
            throw InputError(field, "must be a number within ±1e150 (got " + given(v) +
                                        "): beyond, the intersection formulas' squares overflow");
    };
    Bounds scene;
    for (std::size_t i = 0; i < in.primitives.size(); ++i) {
        const Bounds b = bounds(in.primitives[i]);
        const std::string f = at("primitives", static_cast<int>(i));
        for (int k = 0; k < 3; ++k) check(b.min[k], f), check(b.max[k], f);
        scene.grow(b);
    }
    if (!in.has_ray) return;
    for (int k = 0; k < 3; ++k) {
        check(in.origin[k], at("ray.origin", k));
        check(in.direction[k], at("ray.direction", k));
    }
    if (in.direction == dvec3(0.0))
        throw InputError("ray.direction",
                         "must not be the zero vector (0, 0, 0): a ray needs a direction");
    // Every box's t must be a double, as in ray-aabb: (plane − E)/d for the scene's planes.
    for (int k = 0; k < 3; ++k) {
        const double d = in.direction[k];
        if (d == 0) continue;
        for (double c : {scene.min[k], scene.max[k]})
            if (!std::isfinite((c - in.origin[k]) / d))
                throw InputError(at("ray.direction", k),
                                 "is too small against the distance to the scene: t = (plane − "
                                 "E)/d overflows a double (beyond 1.8e308); scale it up");
    }
}

// ---- [build] --------------------------------------------------------------------------------

namespace {

struct Scratch {
    std::array<Bounds, Bvh::kMaxPrimitives> suffix;  // suffix[k]: the bounds of items k … n−1
};

// Makes the node of job `job`: its bounds, and a leaf or the split (the sort, the cut, the
// two jobs pushed, the left one on top). The one piece of arithmetic the state machine and
// build_and_trace share.
void make_node(const Bvh::Input& in, const std::vector<Bounds>& boxes, const Bvh::Job& job,
               Bvh::Result& r, std::vector<Bvh::Job>& jobs) {
    Node nd;
    nd.first = job.first, nd.count = job.count, nd.depth = job.depth, nd.parent = job.parent;
    int* items = r.order.data() + job.first;
    const int n = job.count;
    Bounds centres;
    for (int i = 0; i < n; ++i) {
        nd.bounds.grow(boxes[items[i]]);
        centres.grow(boxes[items[i]].centre());
    }
    const int id = static_cast<int>(r.nodes.size());
    if (job.parent >= 0) (job.is_left ? r.nodes[job.parent].left : r.nodes[job.parent].right) = id;
    const double leaf_cost = n * Bvh::kIntersectCost;
    auto leaf = [&](NodeKind kind) {
        nd.kind = kind;
        nd.cost = leaf_cost;
        r.nodes.push_back(nd);
    };
    if (n <= in.max_leaf) return leaf(NodeKind::Leaf);

    const int axis = longest_axis(centres);
    nd.axis = axis;
    std::sort(items, items + n, [&](int a, int b) {
        const double ca = boxes[a].centre()[axis], cb = boxes[b].centre()[axis];
        return ca < cb || (ca == cb && a < b);
    });
    if (in.split == Bvh::Split::Median) {
        nd.cut = n / 2;
    } else {
        const dvec3 e = nd.bounds.extent();
        if (!(std::max({e.x, e.y, e.z}) > 0)) return leaf(NodeKind::NoGain);  // S = 0
        static thread_local Scratch scratch;
        Bounds acc;
        for (int i = n - 1; i >= 1; --i) acc.grow(boxes[items[i]]), scratch.suffix[i] = acc;
        Bounds left;
        double best = Bvh::kInf;
        for (int k = 1; k < n; ++k) {
            left.grow(boxes[items[k - 1]]);
            const double c = Bvh::sah_cost(nd.bounds, left, k, scratch.suffix[k], n - k);
            if (c < best) best = c, nd.cut = k;
        }
        if (!(best < leaf_cost)) {
            nd.cost = best;
            nd.kind = NodeKind::NoGain;
            r.nodes.push_back(nd);
            return;
        }
        nd.cost = best;
    }
    nd.kind = NodeKind::Inner;
    r.nodes.push_back(nd);
    jobs.push_back({job.first + nd.cut, n - nd.cut, job.depth + 1, id, false});
    jobs.push_back({job.first, nd.cut, job.depth + 1, id, true});
}

// ---- [trace] --------------------------------------------------------------------------------

// Pops one node and works it: the slab test, the prune, a leaf's primitives or the push of the
// children.
struct PopOutcome {
    Visit visit = Visit::None;
    double t_enter = 0, t_exit = 0;
};

PopOutcome pop_node(const Bvh::Input& in, Bvh::Result& r, std::vector<int>& stack) {
    PopOutcome out;
    const int id = stack.back();
    stack.pop_back();
    r.visited.push_back(id);
    ++r.box_tests;
    const Node& nd = r.nodes[id];
    // The box grown by a hair (kPad of the largest coordinate in play), so that a primitive hit
    // on the box's surface — a triangle's corner on a box corner — is never lost to rounding.
    const dvec3 big =
        glm::max(glm::max(glm::abs(nd.bounds.min), glm::abs(nd.bounds.max)), glm::abs(in.origin));
    const double pad = Bvh::kPad * std::max({big.x, big.y, big.z});
    const RayAabb::Result box = RayAabb::intersect(
        {nd.bounds.min - dvec3(pad), nd.bounds.max + dvec3(pad), in.origin, in.direction});
    if (!box.hit) {
        out.visit = Visit::Missed;
        out.t_enter = box.t_min, out.t_exit = box.t_max;
        return out;
    }
    out.t_enter = std::max(box.t_min, 0.0), out.t_exit = box.t_max;
    if (out.t_enter > r.hit.t) {
        out.visit = Visit::Pruned;
        return out;
    }
    if (!nd.leaf()) {
        out.visit = Visit::Pushed;
        const bool left_near = in.direction[nd.axis] >= 0;
        stack.push_back(left_near ? nd.right : nd.left);
        stack.push_back(left_near ? nd.left : nd.right);
        return out;
    }
    out.visit = Visit::Leaf;
    for (int k = 0; k < nd.count; ++k) {
        const int i = r.order[nd.first + k];
        const PrimitiveHit h = intersect(in.primitives[i], in.origin, in.direction);
        ++r.primitive_tests;
        if (h.hit() && (h.t < r.hit.t || (h.t == r.hit.t && i < r.hit.primitive))) {
            r.hit.primitive = i;
            r.hit.t = h.t;
        }
    }
    return out;
}

void begin_result(const Bvh::Input& in, Bvh::Result& r) {
    const int n = static_cast<int>(in.primitives.size());
    r.order.resize(n);
    for (int i = 0; i < n; ++i) r.order[i] = i;
    r.nodes.reserve(2 * n);
    r.traced = in.has_ray;
    r.split = in.split;
    r.brute_force_tests = n;
}

void finish_hit(const Bvh::Input& in, Bvh::Result& r) {
    if (r.hit.primitive >= 0) r.hit.point = in.origin + r.hit.t * in.direction;
}

}  // namespace

Bvh::Result Bvh::build_and_trace(const Input& in) {
    Result r;
    begin_result(in, r);
    const std::vector<Bounds> boxes = primitive_bounds(in);
    std::vector<Job> jobs;
    jobs.push_back({0, static_cast<int>(in.primitives.size()), 0, -1, false});
    while (!jobs.empty()) {
        const Job job = jobs.back();
        jobs.pop_back();
        make_node(in, boxes, job, r, jobs);
    }
    if (!in.has_ray) return r;
    std::vector<int> stack{0};
    while (!stack.empty()) pop_node(in, r, stack);
    finish_hit(in, r);
    return r;
}

Bvh::State Bvh::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

Bvh::State Bvh::begin(Shared<Input> in) {
    State s;
    s.in = std::move(in);
    s.boxes = Shared<std::vector<Bounds>>(primitive_bounds(*s.in));
    begin_result(*s.in, s.r);
    s.jobs.push_back({0, static_cast<int>(s.in->primitives.size()), 0, -1, false});
    return s;
}

std::size_t Bvh::bytes(const State& s) {
    return heap_bytes(s.r.nodes) + heap_bytes(s.r.order) + heap_bytes(s.r.visited) +
           heap_bytes(s.jobs) + heap_bytes(s.stack) + heap_bytes(s.visits);
}

// ---- [step] ---------------------------------------------------------------------------------

void Bvh::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;  // a finished machine stays finished
    const Input& in = *s.in;
    s.last = s.phase;
    switch (s.phase) {
        case Phase::Build: {  // Make one node: its bounds, then a leaf or a split
            const Job job = s.jobs.back();
            s.jobs.pop_back();
            s.node = static_cast<int>(s.r.nodes.size());
            make_node(in, *s.boxes, job, s.r, s.jobs);
            if (s.jobs.empty()) {
                s.phase = in.has_ray ? Phase::Trace : Phase::Done;
                if (in.has_ray) s.stack.push_back(0);
            }
            break;
        }
        case Phase::Trace: {  // Pop one node: its slab test, prune, test or push
            s.node = s.stack.back();
            s.best_before = s.r.hit.primitive;
            const PopOutcome o = pop_node(in, s.r, s.stack);
            s.visit = o.visit, s.t_enter = o.t_enter, s.t_exit = o.t_exit;
            s.visits.push_back(o.visit);
            if (s.stack.empty()) s.phase = Phase::Report;
            break;
        }
        case Phase::Report:  // The closest hit, and the counts against brute force
            finish_hit(in, s.r);
            s.node = -1;
            s.phase = Phase::Done;
            break;
        case Phase::Done:
            return;
    }
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

using State = Bvh::State;

std::string tn(double t) {
    if (std::isinf(t)) return t > 0 ? "+∞" : "−∞";
    return num(t);
}
std::string tt(double t) {
    if (std::isinf(t)) return t > 0 ? "+\\infty" : "-\\infty";
    return tex(t);
}

std::string list(const int* items, int n) {
    std::string out = "[";
    for (int i = 0; i < n; ++i) out += (i ? ", " : "") + std::to_string(items[i]);
    return out + "]";
}

std::string box_text(const Bounds& b) {
    return num(b.min) + "–" + num(b.max);
}

std::vector<double> ids(const int* items, int n) {
    return std::vector<double>(items, items + n);
}

void narrate_build(const State& s, StepInfo& info) {
    const Bvh::Input& in = *s.in;
    const Node& nd = s.r.nodes[s.node];
    const int* items = s.r.order.data() + nd.first;
    const std::string name = "Node " + std::to_string(s.node);
    std::vector<int> ascending(items, items + nd.count);
    std::sort(ascending.begin(), ascending.end());
    std::string text = name + " (depth " + std::to_string(nd.depth) + ") holds " +
                       std::to_string(nd.count) + " primitive" + (nd.count == 1 ? "" : "s") + " " +
                       list(ascending.data(), nd.count) +
                       (nd.count == 1 ? "; its box is that primitive's bounds, "
                                      : "; its box is the union of theirs, ") +
                       box_text(nd.bounds) + ".";
    info.vars = {{"node", static_cast<long long>(s.node)},
                 {"depth", static_cast<long long>(nd.depth)},
                 {"n", static_cast<long long>(nd.count)},
                 {"min", vec(nd.bounds.min)},
                 {"max", vec(nd.bounds.max)}};
    if (nd.kind == NodeKind::Leaf) {
        info.event = "leaf";
        info.line = kLineLeaf;
        text += " n = " + std::to_string(nd.count) +
                " ≤ max_leaf = " + std::to_string(in.max_leaf) + ": a leaf.";
        info.math = "n = " + std::to_string(nd.count) +
                    " \\le max\\_leaf = " + std::to_string(in.max_leaf) + ":\\ \\text{leaf}";
        info.vars.push_back({"primitives", ids(items, nd.count)});
        info.narration = std::move(text);
        return;
    }
    const std::string a = kAxis[nd.axis];
    text += " The centroids spread most along " + a +
            ", so the primitives are sorted by centroid " + a + ": " + list(items, nd.count) + ".";
    info.vars.push_back({"axis", a});
    if (in.split == Bvh::Split::Median && nd.kind == NodeKind::Inner) {
        info.event = "split-median";
        info.line = kLineCut;
        text += " Median split: the first ⌊" + std::to_string(nd.count) +
                "/2⌋ = " + std::to_string(nd.cut) + " go left " + list(items, nd.cut) +
                ", the other " + std::to_string(nd.count - nd.cut) + " right " +
                list(items + nd.cut, nd.count - nd.cut) + ".";
        info.math =
            "k = \\lfloor " + std::to_string(nd.count) + "/2 \\rfloor = " + std::to_string(nd.cut);
        info.vars.push_back({"k", static_cast<long long>(nd.cut)});
        info.narration = std::move(text);
        return;
    }
    // SAH: recompute every candidate's cost for the narration (the node's items are sorted).
    std::vector<Bounds> suffix(nd.count);
    Bounds acc, left;
    for (int i = nd.count - 1; i >= 1; --i)
        acc.grow(bounds(in.primitives[items[i]])), suffix[i] = acc;
    const dvec3 e = nd.bounds.extent();
    const double S = nd.bounds.surface_area();
    std::vector<double> costs;
    std::string cand;
    std::string math;
    if (std::max({e.x, e.y, e.z}) > 0) {
        for (int k = 1; k < nd.count; ++k) {
            left.grow(bounds(in.primitives[items[k - 1]]));
            const double c = Bvh::sah_cost(nd.bounds, left, k, suffix[k], nd.count - k);
            costs.push_back(c);
            cand += (k > 1 ? "; " : "") + std::string("k = ") + std::to_string(k) + ": 1 + " +
                    num(left.surface_area(), 4) + "/" + num(S, 4) + "·" + std::to_string(k) +
                    " + " + num(suffix[k].surface_area(), 4) + "/" + num(S, 4) + "·" +
                    std::to_string(nd.count - k) + " = " + num(c, 4);
            if (k == nd.cut)
                math = "C(" + std::to_string(k) + ") = 1 + \\frac{" + tex(left.surface_area(), 4) +
                       "}{" + tex(S, 4) + "}\\cdot " + std::to_string(k) + " + \\frac{" +
                       tex(suffix[k].surface_area(), 4) + "}{" + tex(S, 4) + "}\\cdot " +
                       std::to_string(nd.count - k) + " = " + tex(c, 4);
        }
    }
    info.vars.push_back({"S", S});
    if (!costs.empty()) info.vars.push_back({"C", costs});
    const std::string leaf_cost = num(nd.count * Bvh::kIntersectCost);
    if (nd.kind == NodeKind::NoGain) {
        info.event = "leaf-no-gain";
        info.line = kLineNoGain;
        if (costs.empty()) {
            text +=
                " Its box has no area (S = 0): no cut can separate rays, so it stays a leaf "
                "with all " +
                std::to_string(nd.count) + ".";
            info.math = "S = 0:\\ \\text{leaf}";
        } else {
            text +=
                " SAH, C(k) = C_trav + S_L/S·N_L·C_isect + S_R/S·N_R·C_isect with C_trav = "
                "C_isect = 1: " +
                cand + ". The best, C(" + std::to_string(nd.cut) + ") = " + num(nd.cost, 4) +
                ", is not below the leaf's n·C_isect = " + leaf_cost +
                ": no split helps, so the node stays a leaf with all " + std::to_string(nd.count) +
                ".";
            info.math = "\\min_k C(k) = " + tex(nd.cost, 4) + " \\ge n\\,C_{isect} = " + leaf_cost +
                        ":\\ \\text{leaf}";
        }
        info.vars.push_back({"primitives", ids(items, nd.count)});
        info.narration = std::move(text);
        return;
    }
    info.event = "split-sah";
    info.line = kLineCut;
    text +=
        " SAH, C(k) = C_trav + S_L/S·N_L·C_isect + S_R/S·N_R·C_isect with C_trav = C_isect "
        "= 1, for each cut k (left: the first k): " +
        cand + ". The cheapest is k = " + std::to_string(nd.cut) + ", C = " + num(nd.cost, 4) +
        " < the leaf's " + leaf_cost + ": left " + list(items, nd.cut) + ", right " +
        list(items + nd.cut, nd.count - nd.cut) + ".";
    info.math = math + " < n\\,C_{isect} = " + leaf_cost;
    info.vars.push_back({"k", static_cast<long long>(nd.cut)});
    info.narration = std::move(text);
}

void narrate_trace(const State& s, StepInfo& info) {
    const Bvh::Input& in = *s.in;
    const Node& nd = s.r.nodes[s.node];
    const std::string name = "node " + std::to_string(s.node);
    std::string text = "Pop " + name + " (" + (nd.leaf() ? "a leaf" : "inner") + ", box " +
                       box_text(nd.bounds) + "). Slab test: ";
    info.vars = {{"node", static_cast<long long>(s.node)}};
    switch (s.visit) {
        case Visit::Missed:
            info.event = "box-miss";
            info.line = kLineSlab;
            text += "a miss (t_min = " + tn(s.t_enter) + ", t_max = " + tn(s.t_exit) +
                    (s.t_enter > s.t_exit ? ": t_min > t_max" : ": t_max < 0, behind E") +
                    "), so nothing under it can be hit: skipped.";
            info.math = "\\text{miss}";
            break;
        case Visit::Pruned:
            info.event = "box-pruned";
            info.line = kLinePrune;
            text += "the ray is in the box for t ∈ [" + tn(s.t_enter) + ", " + tn(s.t_exit) +
                    "], but t_enter = " + tn(s.t_enter) + " > t_best = " + tn(s.r.hit.t) +
                    " (primitive " + std::to_string(s.r.hit.primitive) +
                    "): anything in it is farther than the hit we have. Pruned.";
            info.math = "t_{enter} = " + tt(s.t_enter) + " > t_{best} = " + tt(s.r.hit.t) +
                        ":\\ \\text{prune}";
            break;
        case Visit::Pushed: {
            info.event = "push-children";
            info.line = kLinePush;
            const bool left_near = in.direction[nd.axis] >= 0;
            const int near = left_near ? nd.left : nd.right, far = left_near ? nd.right : nd.left;
            text += "hit, t ∈ [" + tn(s.t_enter) + ", " + tn(s.t_exit) + "]" +
                    (std::isinf(s.r.hit.t) ? "" : ", t_enter ≤ t_best = " + tn(s.r.hit.t)) +
                    ". Its split axis is " + kAxis[nd.axis] + " and d_" + kAxis[nd.axis] + " = " +
                    num(in.direction[nd.axis]) + (left_near ? " ≥ 0" : " < 0") +
                    ", so the near child is node " + std::to_string(near) + ": push node " +
                    std::to_string(far) + ", then node " + std::to_string(near) + " (popped next).";
            info.math = "[t_{enter}, t_{exit}] = [" + tt(s.t_enter) + ", " + tt(s.t_exit) + "]";
            break;
        }
        case Visit::Leaf: {
            const bool found = s.r.hit.primitive != s.best_before;
            info.event = found ? "leaf-hit" : "leaf-tested";
            info.line = kLineLeafTest;
            text += "hit, t ∈ [" + tn(s.t_enter) + ", " + tn(s.t_exit) + "]. A leaf: test";
            std::vector<double> tested;
            for (int k = 0; k < nd.count; ++k) {
                const int i = s.r.order[nd.first + k];
                const double t = intersect(in.primitives[i], in.origin, in.direction).t;
                text += (k ? "; " : " ") + std::string(kind_name(in.primitives[i].kind)) + " " +
                        std::to_string(i) + ": " + (std::isinf(t) ? "missed" : "t = " + num(t));
                tested.push_back(i);
            }
            text += found ? ". Primitive " + std::to_string(s.r.hit.primitive) +
                                " is the closest hit so far: t_best = " + tn(s.r.hit.t) + "."
                          : ". No closer hit: t_best stays " + tn(s.r.hit.t) + ".";
            info.math = "t_{best} = " + tt(s.r.hit.t);
            info.vars.push_back({"tested", std::move(tested)});
            break;
        }
        case Visit::None:
            break;
    }
    const double t_e = s.visit == Visit::Missed ? 0 : s.t_enter;
    if (s.visit != Visit::Missed && std::isfinite(t_e)) {
        info.vars.push_back({"t_enter", s.t_enter});
        if (std::isfinite(s.t_exit)) info.vars.push_back({"t_exit", s.t_exit});
    }
    if (s.r.hit.primitive >= 0) info.vars.push_back({"t_best", s.r.hit.t});
    std::vector<double> stack(s.stack.begin(), s.stack.end());
    info.vars.push_back({"stack", stack});
    info.vars.push_back({"box_tests", static_cast<long long>(s.r.box_tests)});
    info.vars.push_back({"primitive_tests", static_cast<long long>(s.r.primitive_tests)});
    text += " Stack: " + list(s.stack.data(), static_cast<int>(s.stack.size())) + ".";
    info.narration = std::move(text);
}

void narrate_report(const State& s, StepInfo& info) {
    const Bvh::Result& r = s.r;
    info.event = "result";
    info.line = kLineReturn;
    const std::string counts = std::to_string(r.box_tests) + " box tests and " +
                               std::to_string(r.primitive_tests) + " primitive tests, against " +
                               std::to_string(r.brute_force_tests) +
                               " primitive tests by brute force";
    if (r.hit.primitive >= 0)
        info.narration = "The stack is empty: the closest hit is primitive " +
                         std::to_string(r.hit.primitive) + " at t = " + num(r.hit.t) +
                         ", the point " + num(r.hit.point) + ". It took " + counts + ".";
    else
        info.narration =
            "The stack is empty and nothing was hit: the ray misses every primitive. "
            "It took " +
            counts + ".";
    info.math = "\\text{box tests} = " + std::to_string(r.box_tests) +
                ",\\ \\text{primitive tests} = " + std::to_string(r.primitive_tests) +
                "\\ \\text{vs}\\ " + std::to_string(r.brute_force_tests);
    info.vars = {{"hit", r.hit.primitive >= 0},
                 {"box_tests", static_cast<long long>(r.box_tests)},
                 {"primitive_tests", static_cast<long long>(r.primitive_tests)},
                 {"brute_force_tests", static_cast<long long>(r.brute_force_tests)}};
    if (r.hit.primitive >= 0) {
        info.vars.push_back({"primitive", static_cast<long long>(r.hit.primitive)});
        info.vars.push_back({"t", r.hit.t});
        info.vars.push_back({"point", vec(r.hit.point)});
    }
}

}  // namespace

void Bvh::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Build:
            narrate_build(s, info);
            break;
        case Phase::Trace:
            narrate_trace(s, info);
            break;
        default:
            narrate_report(s, info);
            break;
    }
}

}  // namespace cg
