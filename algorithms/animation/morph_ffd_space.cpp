// Free-form deformation in space: the trivariate Sederberg–Parry lattice (n ≥ 1).
//
//   P_ijk = X_0 + (i/l) S + (j/m) T + (k/n) U,        (s, t, u) = ((X − X_0)·S/|S|², ·T/|T|², ·U/|U|²)
//   X'(s, t, u) = Σ_i Σ_j Σ_k B_i^l(s) B_j^m(t) B_k^n(u) P_ijk
//
// The same steps as the planar case (morph_ffd.cpp): the lattice, one point a step, the summary.
// Sections: [lattice] [blend] [validate] [state machine] [narrate] [compute]
#include <algorithm>
#include <cmath>

#include "animation/morph_ffd.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using Input = MorphFfd::Input;
using Phase = MorphFfd::Phase;
using State = MorphFfd::State;
using Weights = MorphFfd::Weights;
using V3 = std::vector<glm::dvec3>;

// The spec's pseudocode lines (as in morph_ffd.cpp).
enum Line { kLineLattice = 1, kLineMove, kLineEach, kLineLocal, kLineOutside, kLineBlend, kLineReport };

std::size_t at(const Input& in, int i, int j, int k) {
    return (std::size_t(i) * std::size_t(in.m + 1) + std::size_t(j)) * std::size_t(in.n + 1) +
           std::size_t(k);
}

}  // namespace

// ---- [lattice] ------------------------------------------------------------------------------

glm::dvec3 MorphFfd::rest3(const Input& in, int i, int j, int k) {
    // Exactly the corners at i = l, j = m, k = n (no X_0 + 1·S rounding away from the max).
    const glm::dvec3 lo = in.box3_min, hi = in.box3_max;
    const double x = i == in.l ? hi.x : lo.x + (hi.x - lo.x) * (double(i) / in.l);
    const double y = j == in.m ? hi.y : lo.y + (hi.y - lo.y) * (double(j) / in.m);
    const double z = k == in.n ? hi.z : lo.z + (hi.z - lo.z) * (double(k) / in.n);
    return {x, y, z};
}

V3 MorphFfd::lattice3(const Input& in) {
    V3 p((std::size_t(in.l) + 1) * std::size_t(in.m + 1) * std::size_t(in.n + 1));
    for (int i = 0; i <= in.l; ++i)
        for (int j = 0; j <= in.m; ++j)
            for (int k = 0; k <= in.n; ++k) p[at(in, i, j, k)] = rest3(in, i, j, k);
    for (const Move3& mv : in.moves3) {
        glm::dvec3& q = p[at(in, mv.i, mv.j, mv.k)];
        q = mv.absolute ? mv.value : q + mv.value;
    }
    return p;
}

glm::dvec3 MorphFfd::local3(const Input& in, glm::dvec3 x) {
    return (x - in.box3_min) / (in.box3_max - in.box3_min);  // axis-aligned: one division an axis
}

// ---- [blend] --------------------------------------------------------------------------------

glm::dvec3 MorphFfd::blend3(const Input& in, const V3& p, glm::dvec3 stu) {
    Weights bs, bt, bu;
    bernstein(in.l, stu.x, bs);
    bernstein(in.m, stu.y, bt);
    bernstein(in.n, stu.z, bu);
    glm::dvec3 x{0, 0, 0};
    for (int i = 0; i <= in.l; ++i) {
        // Σ_j B_j(t) Σ_k B_k(u) P_ijk: the lattice's slab i as a surface at (t, u), then across s.
        glm::dvec3 slab{0, 0, 0};
        for (int j = 0; j <= in.m; ++j) {
            const glm::dvec3* pij = &p[at(in, i, j, 0)];
            glm::dvec3 column{0, 0, 0};
            for (int k = 0; k <= in.n; ++k) column += bu[std::size_t(k)] * pij[k];
            slab += bt[std::size_t(j)] * column;
        }
        x += bs[std::size_t(i)] * slab;
    }
    return x;
}

glm::dvec3 MorphFfd::deform3(const Input& in, const V3& p, glm::dvec3 x) {
    const glm::dvec3 stu = local3(in, x);
    return inside3(stu) ? blend3(in, p, stu) : x;
}

// ---- [validate] -----------------------------------------------------------------------------

namespace {

void check_point3(glm::dvec3 p, const std::string& field) {
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(p[c])) throw InputError(field, "must be finite (got " + given(p[c]) + ")");
        if (std::fabs(p[c]) > MorphFfd::kMaxCoordinate)
            throw InputError(field, "is too large (" + given(p[c]) + "): at most 1e6 in size");
    }
}

std::string item(const char* list, std::size_t i, const char* field = nullptr) {
    std::string s = std::string(list) + "[" + std::to_string(i) + "]";
    return field ? s + "." + field : s;
}

std::string str(int v) {
    return std::to_string(v);
}

}  // namespace

void MorphFfd::validate3(const Input& in) {
    check_point3(in.box3_min, "box.min");
    check_point3(in.box3_max, "box.max");
    for (int c = 0; c < 3; ++c)
        if (!(in.box3_max[c] > in.box3_min[c]))
            throw InputError("box", std::string("max must be above min in ") + "xyz"[c] + " (got " +
                                        given(in.box3_min[c]) + " to " + given(in.box3_max[c]) + ")");
    const int d[3] = {in.l, in.m, in.n};
    for (int c = 0; c < 3; ++c)
        if (d[c] < 1 || d[c] > kMaxDegree)
            throw InputError("degree", "must be [l, m, n] with each 1 to " + str(kMaxDegree) +
                                           " (got [" + str(in.l) + ", " + str(in.m) + ", " +
                                           str(in.n) + "])");
    if (in.moves3.size() > std::size_t(kMaxMoves))
        throw InputError("moves", "has " + std::to_string(in.moves3.size()) + " moves; at most " +
                                      str(kMaxMoves));
    for (std::size_t q = 0; q < in.moves3.size(); ++q) {
        const Move3& mv = in.moves3[q];
        if (mv.i < 0 || mv.i > in.l || mv.j < 0 || mv.j > in.m || mv.k < 0 || mv.k > in.n)
            throw InputError(item("moves", q, "point"),
                             "must name a control point [i, j, k] with 0 ≤ i ≤ " + str(in.l) +
                                 ", 0 ≤ j ≤ " + str(in.m) + " and 0 ≤ k ≤ " + str(in.n) +
                                 " (got [" + str(mv.i) + ", " + str(mv.j) + ", " + str(mv.k) +
                                 "])");
        check_point3(mv.value, item("moves", q, mv.absolute ? "to" : "by"));
    }
    if (in.shape3.empty()) throw InputError("shape", "must have at least 1 point (got none)");
    if (in.shape3.size() > std::size_t(kMaxPoints))
        throw InputError("shape", "has " + std::to_string(in.shape3.size()) + " points; at most " +
                                      str(kMaxPoints));
    for (std::size_t q = 0; q < in.shape3.size(); ++q) {
        const glm::dvec3 p = in.shape3[q];
        if (!(std::fabs(p.x) <= kMaxCoordinate && std::fabs(p.y) <= kMaxCoordinate &&
              std::fabs(p.z) <= kMaxCoordinate))
            check_point3(p, item("shape", q));
    }
    if (in.edges.size() > std::size_t(kMaxEdges))
        throw InputError("edges", "has " + std::to_string(in.edges.size()) + " edges; at most " +
                                      str(kMaxEdges));
    const int n = int(in.shape3.size());
    for (std::size_t e = 0; e < in.edges.size(); ++e)
        for (int c = 0; c < 2; ++c)
            if (in.edges[e][std::size_t(c)] < 0 || in.edges[e][std::size_t(c)] >= n)
                throw InputError(item("edges", e),
                                 "must join two shape points, indices 0 to " + str(n - 1) +
                                     " (got [" + str(in.edges[e][0]) + ", " + str(in.edges[e][1]) +
                                     "])");
}

// ---- [state machine] ------------------------------------------------------------------------

void MorphFfd::take_step3(State& s) {
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Lattice:
            s.lattice3 = Shared<V3>(lattice3(in));
            s.last = Phase::Lattice;
            s.phase = Phase::Point;
            return;
        case Phase::Point: {
            const glm::dvec3 x = in.shape3[std::size_t(s.k)];
            const glm::dvec3 stu = local3(in, x);
            const bool in_box = inside3(stu);
            s.local3.push_back(stu);
            s.inside.push_back(char(in_box));
            s.deformed3.push_back(in_box ? blend3(in, *s.lattice3, stu) : x);
            s.inside_count += in_box;
            s.last = Phase::Point;
            if (++s.k == int(in.shape3.size())) s.phase = Phase::Summary;
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

std::string pijk(int i, int j, int k) {
    return "P_" + str(i) + str(j) + str(k);
}

void narrate_lattice(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "lattice";
    info.line = kLineMove;
    const glm::dvec3 size = in.box3_max - in.box3_min;
    const glm::dvec3 S{size.x, 0, 0}, T{0, size.y, 0}, U{0, 0, size.z};
    std::string t = "A spatial lattice of degree " + str(in.l) + " × " + str(in.m) + " × " +
                    str(in.n) + ": " + str((in.l + 1) * (in.m + 1) * (in.n + 1)) +
                    " control points P_ijk = X_0 + (i/" + str(in.l) + ") S + (j/" + str(in.m) +
                    ") T + (k/" + str(in.n) + ") U over the box from X_0 = " + num(in.box3_min) +
                    " with S = " + num(S) + ", T = " + num(T) + ", U = " + num(U) + ". ";
    if (in.moves3.empty()) {
        t += "No control point moves: the lattice is undeformed, and linear precision says "
             "every point will stay where it is.";
    } else {
        t += "Moved: ";
        const std::size_t shown = std::min<std::size_t>(in.moves3.size(), 6);
        for (std::size_t q = 0; q < shown; ++q) {
            const MorphFfd::Move3& mv = in.moves3[q];
            t += (q ? "; " : "") + pijk(mv.i, mv.j, mv.k) + " " +
                 (mv.absolute ? "to " + num(mv.value) : "by " + num(mv.value));
        }
        if (in.moves3.size() > shown)
            t += " and " + std::to_string(in.moves3.size() - shown) + " more";
        t += ". Only the space inside the box is deformed.";
    }
    info.narration = t;
    info.math = "P_{ijk} = X_0 + \\tfrac{i}{" + str(in.l) + "} S + \\tfrac{j}{" + str(in.m) +
                "} T + \\tfrac{k}{" + str(in.n) + "} U";
    info.vars = {{"l", (long long)in.l},   {"m", (long long)in.m}, {"n", (long long)in.n},
                 {"X_0", vec(in.box3_min)}, {"S", vec(S)},         {"T", vec(T)},
                 {"U", vec(U)},             {"moves", (long long)in.moves3.size()}};
}

void narrate_point(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::size_t q = std::size_t(s.k - 1);
    const glm::dvec3 x = in.shape3[q], stu = s.local3[q], X = s.deformed3[q];
    const glm::dvec3 lo = in.box3_min, size = in.box3_max - in.box3_min;
    std::string t = "Point " + std::to_string(q) + ", X = " + num(x) + ": s = (" + num(x.x) +
                    " − " + num(lo.x) + ") / " + num(size.x) + " = " + num(stu.x) + ", t = (" +
                    num(x.y) + " − " + num(lo.y) + ") / " + num(size.y) + " = " + num(stu.y) +
                    ", u = (" + num(x.z) + " − " + num(lo.z) + ") / " + num(size.z) + " = " +
                    num(stu.z);
    info.vars = {{"index", (long long)q}, {"X", vec(x)}, {"s", stu.x}, {"t", stu.y}, {"u", stu.z}};
    if (!s.inside[q]) {
        info.event = "outside";
        info.line = kLineOutside;
        const char* which = stu.x < 0 || stu.x > 1 ? "s" : stu.y < 0 || stu.y > 1 ? "t" : "u";
        t += std::string(": ") + which +
             " is outside [0, 1], so the point is outside the box and the lattice does not move "
             "it: X' = X.";
        info.narration = t;
        info.math = "X' = X = " + tex(X);
        info.vars.push_back({"X'", vec(X)});
        return;
    }
    info.event = "point";
    info.line = kLineBlend;
    Weights bs, bt, bu;
    MorphFfd::bernstein(in.l, stu.x, bs);
    MorphFfd::bernstein(in.m, stu.y, bt);
    MorphFfd::bernstein(in.n, stu.z, bu);
    t += ", inside the box. Bernstein weights B^" + str(in.l) + "(s) = " + list(bs, in.l) +
         ", B^" + str(in.m) + "(t) = " + list(bt, in.m) + ", B^" + str(in.n) +
         "(u) = " + list(bu, in.n) + ". ";
    // By linear precision X' = X + Σ B_i(s) B_j(t) B_k(u) (P_ijk − rest_ijk): the moved points.
    const V3& p = *s.lattice3;
    std::string terms;
    int moved = 0, shown = 0;
    for (int i = 0; i <= in.l; ++i)
        for (int j = 0; j <= in.m; ++j)
            for (int k = 0; k <= in.n; ++k) {
                const glm::dvec3 d = p[at(in, i, j, k)] - MorphFfd::rest3(in, i, j, k);
                if (d == glm::dvec3(0)) continue;
                ++moved;
                if (++shown > 4) continue;
                const double w = bs[std::size_t(i)] * bt[std::size_t(j)] * bu[std::size_t(k)];
                terms += std::string(shown > 1 ? " + " : "") + num(w, 4) + " · " + num(d) + " (" +
                         pijk(i, j, k) + ")";
            }
    if (moved == 0)
        t += "No control point has moved, so X' = Σ B_i(s) B_j(t) B_k(u) P_ijk = X: ";
    else
        t += "X' = Σ_i Σ_j Σ_k B_i(s) B_j(t) B_k(u) P_ijk = X + Σ B_i(s) B_j(t) B_k(u) ΔP_ijk = X + " +
             terms + (moved > 4 ? " + " + std::to_string(moved - 4) + " more" : std::string()) +
             " = ";
    info.narration = t + num(X) + (moved ? ", moved by " + num(X - x) + "." : ".");
    info.math = "X' = \\sum_i \\sum_j \\sum_k B_i^{" + str(in.l) + "}(" + tex(stu.x, 4) +
                ")\\,B_j^{" + str(in.m) + "}(" + tex(stu.y, 4) + ")\\,B_k^{" + str(in.n) + "}(" +
                tex(stu.z, 4) + ")\\,P_{ijk} = " + tex(X);
    info.vars.push_back({"B(s)", values(bs, in.l)});
    info.vars.push_back({"B(t)", values(bt, in.m)});
    info.vars.push_back({"B(u)", values(bu, in.n)});
    info.vars.push_back({"X'", vec(X)});
}

void narrate_summary(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    info.event = "summary";
    info.line = kLineReport;
    double largest = 0;
    for (std::size_t q = 0; q < s.deformed3.size(); ++q) {
        const glm::dvec3 d = s.deformed3[q] - in.shape3[q];
        largest = std::max(largest, std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
    }
    const int n = int(in.shape3.size());
    info.narration = "Done: " + str(s.inside_count) + " of " + str(n) +
                     " points lay inside the box and were deformed, " + str(n - s.inside_count) +
                     " outside stayed put; the largest displacement is " + num(largest, 4) + ".";
    info.vars = {{"inside", (long long)s.inside_count},
                 {"outside", (long long)(n - s.inside_count)},
                 {"largest", largest}};
}

}  // namespace

void MorphFfd::narrate3(const State& s, StepInfo& info) {
    switch (s.last) {
        case Phase::Lattice: narrate_lattice(s, info); break;
        case Phase::Point: narrate_point(s, info); break;
        default: narrate_summary(s, info); break;
    }
}

// ---- [compute] ------------------------------------------------------------------------------

MorphFfd::Result MorphFfd::compute3(const Input& in) {
    Result r;
    r.lattice3 = lattice3(in);
    const std::size_t n = in.shape3.size();
    r.local3.reserve(n);
    r.inside.reserve(n);
    r.deformed3.reserve(n);
    for (const glm::dvec3& x : in.shape3) {
        const glm::dvec3 stu = local3(in, x);
        const bool in_box = inside3(stu);
        r.local3.push_back(stu);
        r.inside.push_back(char(in_box));
        r.deformed3.push_back(in_box ? blend3(in, r.lattice3, stu) : x);
        r.inside_count += in_box;
    }
    return r;
}

}  // namespace cg
