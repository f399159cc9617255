// Sections: [lattice] [bernstein and blend] [spec] [validate] [state machine] [narrate]
//           [result and compute]
#include "animation/morph_ffd.hpp"

#include <algorithm>
#include <cmath>

#include "core/format.hpp"

namespace cg {

namespace {

using Input = MorphFfd::Input;
using Phase = MorphFfd::Phase;
using State = MorphFfd::State;
using Weights = MorphFfd::Weights;
using V2 = std::vector<glm::dvec2>;

enum Line { kLineLattice = 1, kLineMove, kLineEach, kLineLocal, kLineOutside, kLineBlend, kLineReport };

// C(d, i) for d ≤ kMaxDegree = 8, exact in double.
constexpr double kBinomial[9][9] = {
    {1},
    {1, 1},
    {1, 2, 1},
    {1, 3, 3, 1},
    {1, 4, 6, 4, 1},
    {1, 5, 10, 10, 5, 1},
    {1, 6, 15, 20, 15, 6, 1},
    {1, 7, 21, 35, 35, 21, 7, 1},
    {1, 8, 28, 56, 70, 56, 28, 8, 1},
};
static_assert(MorphFfd::kMaxDegree == 8);

std::size_t at(const Input& in, int i, int j) {
    return std::size_t(i) * std::size_t(in.m + 1) + std::size_t(j);
}

}  // namespace

// ---- [lattice] ------------------------------------------------------------------------------

glm::dvec2 MorphFfd::rest(const Input& in, int i, int j) {
    // Exactly the corners at i = 0, l and j = 0, m (no X_0 + 1·S rounding away from x_max).
    const glm::dvec2 lo = in.box_min, hi = in.box_max;
    const double x = i == in.l ? hi.x : lo.x + (hi.x - lo.x) * (double(i) / in.l);
    const double y = j == in.m ? hi.y : lo.y + (hi.y - lo.y) * (double(j) / in.m);
    return {x, y};
}

V2 MorphFfd::lattice(const Input& in) {
    V2 p((std::size_t(in.l) + 1) * std::size_t(in.m + 1));
    for (int i = 0; i <= in.l; ++i)
        for (int j = 0; j <= in.m; ++j) p[at(in, i, j)] = rest(in, i, j);
    for (const Move& mv : in.moves) {
        glm::dvec2& q = p[at(in, mv.i, mv.j)];
        q = mv.absolute ? mv.value : q + mv.value;
    }
    return p;
}

glm::dvec2 MorphFfd::local(const Input& in, glm::dvec2 x) {
    // The box is axis-aligned, so (X − X_0)·S/|S|² is a division per axis.
    return (x - in.box_min) / (in.box_max - in.box_min);
}

// ---- [bernstein and blend] ------------------------------------------------------------------

void MorphFfd::bernstein(int d, double u, Weights& b) {
    // B_i^d(u) = C(d, i) u^i (1 − u)^(d − i), from the two lists of powers.
    const double v = 1 - u;
    double pu[kMaxDegree + 1], pv[kMaxDegree + 1];
    pu[0] = pv[0] = 1;
    for (int i = 1; i <= d; ++i) pu[i] = pu[i - 1] * u, pv[i] = pv[i - 1] * v;
    for (int i = 0; i <= d; ++i) b[std::size_t(i)] = kBinomial[d][i] * pu[i] * pv[d - i];
}

glm::dvec2 MorphFfd::blend(const Input& in, const V2& p, glm::dvec2 st) {
    Weights bs, bt;
    bernstein(in.l, st.x, bs);
    bernstein(in.m, st.y, bt);
    glm::dvec2 x{0, 0};
    for (int i = 0; i <= in.l; ++i) {
        // Σ_j B_j^m(t) P_ij: the point of column i at t, then blended across the columns by s.
        glm::dvec2 column{0, 0};
        const glm::dvec2* pi = &p[at(in, i, 0)];
        for (int j = 0; j <= in.m; ++j) column += bt[std::size_t(j)] * pi[j];
        x += bs[std::size_t(i)] * column;
    }
    return x;
}

glm::dvec2 MorphFfd::deform(const Input& in, const V2& p, glm::dvec2 x) {
    const glm::dvec2 st = local(in, x);
    return inside(st) ? blend(in, p, st) : x;
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& MorphFfd::spec() {
    static const Spec spec{
        "morph-ffd",
        "Free-form deformation: a Bernstein lattice bends the space around a shape",
        "Animation",
        {
            "lay the lattice P_ij = X_0 + (i/l) S + (j/m) T over the box  (in 3D P_ijk, + (k/n) U)",
            "move control points:  P_ij ← P_ij + Δ  (or ← a new position)",
            "for every point X of the shape:",
            "  (s, t) ← ((X − X_0)·S/|S|², (X − X_0)·T/|T|²)  (in 3D also u ← (X − X_0)·U/|U|²)",
            "  if s or t (or u) outside [0, 1]: X stays where it is",
            "  X' ← Σ_i Σ_j B_i^l(s) B_j^m(t) P_ij  (in 3D Σ_k B_k^n(u) too),  B_i^l(s) = C(l,i) s^i (1−s)^(l−i)",
            "report the deformed shape",
        },
        {
            {"lattice", "the lattice laid over the box and its control points moved"},
            {"point", "one point inside the box: its local (s, t), the Bernstein weights, X'"},
            {"outside", "one point outside the box: left where it is"},
            {"summary", "the whole shape deformed"},
        },
        {},  // no sliders
        {
            .predict = {{"point", {"s", "t"}}},
            .mistakes =
                {
                    {"point", "s", "swap:t", "took s along y and t along x"},
                    {"point", "X'", "copy:X", "computed the weights but left the point where it was"},
                    {"outside", "X'", "keep", "deformed a point outside the box like the one before"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

void check_point(glm::dvec2 p, const std::string& field) {
    for (int c = 0; c < 2; ++c) {
        if (!std::isfinite(p[c])) throw InputError(field, "must be finite (got " + given(p[c]) + ")");
        if (std::fabs(p[c]) > MorphFfd::kMaxCoordinate)
            throw InputError(field, "is too large (" + given(p[c]) + "): at most 1e6 in size");
    }
}

std::string item(const char* list, std::size_t i, const char* field = nullptr) {
    std::string s = std::string(list) + "[" + std::to_string(i) + "]";
    return field ? s + "." + field : s;
}

}  // namespace

void MorphFfd::validate(const Input& in) {
    if (in.spatial()) return validate3(in);
    check_point(in.box_min, "box.min");
    check_point(in.box_max, "box.max");
    for (int c = 0; c < 2; ++c)
        if (!(in.box_max[c] > in.box_min[c]))
            throw InputError("box", std::string("max must be above min in ") + "xy"[c] + " (got " +
                                        given(in.box_min[c]) + " to " + given(in.box_max[c]) + ")");
    if (in.l < 1 || in.l > kMaxDegree || in.m < 1 || in.m > kMaxDegree)
        throw InputError("degree", "must be [l, m] with each 1 to " + std::to_string(kMaxDegree) +
                                       " (got [" + std::to_string(in.l) + ", " +
                                       std::to_string(in.m) + "])");
    if (in.moves.size() > std::size_t(kMaxMoves))
        throw InputError("moves", "has " + std::to_string(in.moves.size()) + " moves; at most " +
                                      std::to_string(kMaxMoves));
    for (std::size_t q = 0; q < in.moves.size(); ++q) {
        const Move& mv = in.moves[q];
        if (mv.i < 0 || mv.i > in.l || mv.j < 0 || mv.j > in.m)
            throw InputError(item("moves", q, "point"),
                             "must name a control point [i, j] with 0 ≤ i ≤ " +
                                 std::to_string(in.l) + " and 0 ≤ j ≤ " + std::to_string(in.m) +
                                 " (got [" + std::to_string(mv.i) + ", " + std::to_string(mv.j) +
                                 "])");
        check_point(mv.value, item("moves", q, mv.absolute ? "to" : "by"));
    }
    if (in.shape.empty()) throw InputError("shape", "must have at least 1 point (got none)");
    if (in.shape.size() > std::size_t(kMaxPoints))
        throw InputError("shape", "has " + std::to_string(in.shape.size()) + " points; at most " +
                                      std::to_string(kMaxPoints));
    // The field's name is built only for a point that fails (a string per point would cost
    // as much as deforming it).
    for (std::size_t q = 0; q < in.shape.size(); ++q) {
        const glm::dvec2 p = in.shape[q];
        if (!(std::fabs(p.x) <= kMaxCoordinate && std::fabs(p.y) <= kMaxCoordinate))
            check_point(p, item("shape", q));
    }
}

// ---- [state machine] ------------------------------------------------------------------------

MorphFfd::State MorphFfd::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

MorphFfd::State MorphFfd::begin(Shared<Input> shared) {
    State s;
    s.in = std::move(shared);
    if (s.in->spatial()) {
        const std::size_t n = s.in->shape3.size();
        s.local3.reserve(n);
        s.deformed3.reserve(n);
        s.inside.reserve(n);
        return s;
    }
    const std::size_t n = s.in->shape.size();
    s.local.reserve(n);
    s.deformed.reserve(n);
    s.inside.reserve(n);
    return s;
}

void MorphFfd::take_step(State& s) {
    const Input& in = *s.in;
    if (in.spatial()) return take_step3(s);
    switch (s.phase) {
        case Phase::Lattice:
            s.lattice = Shared<V2>(lattice(in));
            s.last = Phase::Lattice;
            s.phase = Phase::Point;
            return;
        case Phase::Point: {
            const glm::dvec2 x = in.shape[std::size_t(s.k)];
            const glm::dvec2 st = local(in, x);
            const bool in_box = inside(st);
            s.local.push_back(st);
            s.inside.push_back(char(in_box));
            s.deformed.push_back(in_box ? blend(in, *s.lattice, st) : x);
            s.inside_count += in_box;
            s.last = Phase::Point;
            if (++s.k == int(in.shape.size())) s.phase = Phase::Summary;
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

void MorphFfd::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    take_step(s);
    if (info) narrate(s, *info);
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string list(const Weights& b, int d) {
    std::string t = "[";
    for (int i = 0; i <= d; ++i) t += (i ? ", " : "") + num(b[std::size_t(i)], 4);
    return t + "]";
}

std::vector<double> values(const Weights& b, int d) {
    return {b.begin(), b.begin() + d + 1};
}

std::string pij(int i, int j) {
    return "P_" + std::to_string(i) + std::to_string(j);
}

void narrate_lattice(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "lattice";
    info.line = kLineMove;
    const glm::dvec2 size = in.box_max - in.box_min;
    std::string t = "A lattice of degree " + std::to_string(in.l) + " × " + std::to_string(in.m) +
                    ": " + std::to_string((in.l + 1) * (in.m + 1)) +
                    " control points P_ij = X_0 + (i/" + std::to_string(in.l) + ") S + (j/" +
                    std::to_string(in.m) + ") T over the box from X_0 = " + num(in.box_min) +
                    " with S = " + num(glm::dvec2(size.x, 0)) + ", T = " +
                    num(glm::dvec2(0, size.y)) + ". ";
    if (in.moves.empty()) {
        t += "No control point moves: the lattice is undeformed, and linear precision says "
             "every point will stay where it is.";
    } else {
        t += "Moved: ";
        const std::size_t shown = std::min<std::size_t>(in.moves.size(), 6);
        for (std::size_t q = 0; q < shown; ++q) {
            const MorphFfd::Move& mv = in.moves[q];
            t += (q ? "; " : "") + pij(mv.i, mv.j) + " " +
                 (mv.absolute ? "to " + num(mv.value) : "by " + num(mv.value));
        }
        if (in.moves.size() > shown)
            t += " and " + std::to_string(in.moves.size() - shown) + " more";
        t += ". Only the space inside the box is deformed.";
    }
    info.narration = t;
    info.math = "P_{ij} = X_0 + \\tfrac{i}{" + std::to_string(in.l) + "} S + \\tfrac{j}{" +
                std::to_string(in.m) + "} T";
    info.vars = {{"l", (long long)in.l},
                 {"m", (long long)in.m},
                 {"X_0", vec(in.box_min)},
                 {"S", vec(glm::dvec2(size.x, 0))},
                 {"T", vec(glm::dvec2(0, size.y))},
                 {"moves", (long long)in.moves.size()}};
}

void narrate_point(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t q = std::size_t(s.k - 1);
    const glm::dvec2 x = in.shape[q], st = s.local[q], X = s.deformed[q];
    const glm::dvec2 lo = in.box_min, size = in.box_max - in.box_min;
    std::string t = "Point " + std::to_string(q) + ", X = " + num(x) + ": s = (" + num(x.x) +
                    " − " + num(lo.x) + ") / " + num(size.x) + " = " + num(st.x) + ", t = (" +
                    num(x.y) + " − " + num(lo.y) + ") / " + num(size.y) + " = " + num(st.y);
    info.vars = {{"index", (long long)q}, {"X", vec(x)}, {"s", st.x}, {"t", st.y}};
    if (!s.inside[q]) {
        info.event = "outside";
        info.line = kLineOutside;
        t += std::string(": ") + (st.x < 0 || st.x > 1 ? "s" : "t") +
             " is outside [0, 1], so the point is outside the box and the lattice does not move "
             "it: X' = X.";
        info.narration = t;
        info.math = "X' = X = " + tex(X);
        info.vars.push_back({"X'", vec(X)});
        return;
    }
    info.event = "point";
    info.line = kLineBlend;
    Weights bs, bt;
    MorphFfd::bernstein(in.l, st.x, bs);
    MorphFfd::bernstein(in.m, st.y, bt);
    t += ", inside the box. Bernstein weights B^" + std::to_string(in.l) + "(s) = " +
         list(bs, in.l) + ", B^" + std::to_string(in.m) + "(t) = " + list(bt, in.m) + ". ";
    // By linear precision X' = X + Σ B_i(s) B_j(t) (P_ij − rest_ij): only the moved points
    // matter, which is how one works it by hand.
    const V2& p = *s.lattice;
    std::string terms;
    int moved = 0, shown = 0;
    for (int i = 0; i <= in.l; ++i)
        for (int j = 0; j <= in.m; ++j) {
            const glm::dvec2 d = p[at(in, i, j)] - MorphFfd::rest(in, i, j);
            if (d == glm::dvec2(0)) continue;
            ++moved;
            if (++shown > 4) continue;
            terms += std::string(shown > 1 ? " + " : "") + num(bs[std::size_t(i)] * bt[std::size_t(j)], 4) +
                     " · " + num(d) + " (" + pij(i, j) + ")";
        }
    if (moved == 0)
        t += "No control point has moved, so X' = Σ B_i(s) B_j(t) P_ij = X: ";
    else
        t += "X' = Σ_i Σ_j B_i(s) B_j(t) P_ij = X + Σ B_i(s) B_j(t) ΔP_ij = X + " + terms +
             (moved > 4 ? " + " + std::to_string(moved - 4) + " more" : std::string()) + " = ";
    info.narration = t + num(X) + (moved ? ", moved by " + num(X - x) + "." : ".");
    info.math = "X' = \\sum_i \\sum_j B_i^{" + std::to_string(in.l) + "}(" + tex(st.x, 4) +
                ")\\,B_j^{" + std::to_string(in.m) + "}(" + tex(st.y, 4) + ")\\,P_{ij} = " + tex(X);
    info.vars.push_back({"B(s)", values(bs, in.l)});
    info.vars.push_back({"B(t)", values(bt, in.m)});
    info.vars.push_back({"X'", vec(X)});
}

void narrate_summary(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "summary";
    info.line = kLineReport;
    double largest = 0;
    for (std::size_t q = 0; q < s.deformed.size(); ++q) {
        const glm::dvec2 d = s.deformed[q] - in.shape[q];
        largest = std::max(largest, std::hypot(d.x, d.y));
    }
    const int n = int(in.shape.size());
    info.narration = "Done: " + std::to_string(s.inside_count) + " of " + std::to_string(n) +
                     " points lay inside the box and were deformed, " +
                     std::to_string(n - s.inside_count) +
                     " outside stayed put; the largest displacement is " + num(largest, 4) + ".";
    info.vars = {{"inside", (long long)s.inside_count},
                 {"outside", (long long)(n - s.inside_count)},
                 {"largest", largest}};
}

}  // namespace

void MorphFfd::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    if (s.in->spatial()) return narrate3(s, info);
    switch (s.last) {
        case Phase::Lattice: narrate_lattice(s, info); break;
        case Phase::Point: narrate_point(s, info); break;
        default: narrate_summary(s, info); break;
    }
}

// ---- [result and compute] -------------------------------------------------------------------

MorphFfd::Result MorphFfd::result(const State& s) {
    Result r;
    if (s.in->spatial()) {
        r.lattice3 = *s.lattice3;
        r.local3 = s.local3;
        r.deformed3 = s.deformed3;
        r.inside = s.inside;
        r.inside_count = s.inside_count;
        return r;
    }
    r.lattice = *s.lattice;
    r.local = s.local;
    r.inside = s.inside;
    r.deformed = s.deformed;
    r.inside_count = s.inside_count;
    return r;
}

MorphFfd::Result MorphFfd::compute(const Input& in) {
    validate(in);
    if (in.spatial()) return compute3(in);
    Result r;
    r.lattice = lattice(in);
    const std::size_t n = in.shape.size();
    r.local.reserve(n);
    r.inside.reserve(n);
    r.deformed.reserve(n);
    for (const glm::dvec2& x : in.shape) {
        const glm::dvec2 st = local(in, x);
        const bool in_box = inside(st);
        r.local.push_back(st);
        r.inside.push_back(char(in_box));
        r.deformed.push_back(in_box ? blend(in, r.lattice, st) : x);
        r.inside_count += in_box;
    }
    return r;
}

}  // namespace cg
