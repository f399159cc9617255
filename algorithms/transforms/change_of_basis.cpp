// Sections: [helpers] [spec] [validate] [advance] [narrate]; the picture is in
// change_of_basis_draw.cpp
#include "transforms/change_of_basis.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dmat4;
using glm::dvec3;
using glm::dvec4;
using Frame = ChangeOfBasis::Frame;
using Phase = ChangeOfBasis::Phase;
using State = ChangeOfBasis::State;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line { kLineF1 = 1, kLineF2, kLineInverse, kLineCompose, kLinePoint, kLineVector };

double max_abs(dvec3 v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// The axes scaled by powers of two so that each has its largest component in [0.5, 1): exact,
// and it keeps the determinant (a product of three lengths up to 1e100 or down to 1e-100) from
// overflowing or going subnormal. Because the scales are powers of two, the cross products over
// the determinant come out bit for bit as the unscaled formula would give them.
struct Scaled {
    std::array<dvec3, 3> a;  // a_i / s_i
    dvec3 s;                 // s_i = 2^e_i
    double det;              // det[â₁ â₂ â₃]
    double ratio;            // |det| / (|â₁| |â₂| |â₃|): 1 orthogonal, 0 coplanar
};

Scaled scaled(const Frame& f) {
    Scaled sc{};
    for (int i = 0; i < 3; ++i) {
        int e = 0;
        std::frexp(max_abs(f.axes[i]), &e);
        sc.s[i] = std::ldexp(1.0, e);
        sc.a[i] = f.axes[i] / sc.s[i];
    }
    sc.det = glm::dot(sc.a[0], glm::cross(sc.a[1], sc.a[2]));
    sc.ratio =
        std::fabs(sc.det) / (glm::length(sc.a[0]) * glm::length(sc.a[1]) * glm::length(sc.a[2]));
    return sc;
}

// det[a₁ a₂ a₃] itself (for the narration; may be tiny but is never 0 after validation).
double determinant(const Frame& f) {
    const Scaled sc = scaled(f);
    return sc.det * sc.s[0] * sc.s[1] * sc.s[2];
}

dvec3 point(const dmat4& m, dvec3 p) {
    return dvec3(m * dvec4(p, 1.0));
}
dvec3 vector(const dmat4& m, dvec3 u) {
    return dvec3(m * dvec4(u, 0.0));
}

bool finite(dvec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite(const dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

std::vector<std::vector<double>> rows(const dmat4& m) {
    std::vector<std::vector<double>> out(4);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out[r].push_back(m[c][r] + 0.0);  // + 0.0: no −0
    return out;
}

std::string matrix_text(const dmat4& m, int digits = 4) {
    std::string t = "[";
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) t += (c ? " " : "") + num(m[c][r], digits);
        t += r < 3 ? "; " : "]";
    }
    return t;
}

std::string matrix_tex(const dmat4& m, int digits = 4) {
    std::string t = "\\begin{bmatrix} ";
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) t += (c ? " & " : "") + tex(m[c][r], digits);
        t += r < 3 ? " \\\\ " : " \\end{bmatrix}";
    }
    return t;
}

std::string sub(int i) {  // ₁ ₂ ₃
    static const char* const k[] = {"₀", "₁", "₂", "₃", "₄"};
    return k[i];
}

// "p₁v₁ + p₂v₂ + p₃v₃ + O" with the numbers: "2·v₁ + (−1)·v₂ + 0·v₃ + O_v".
std::string combination(dvec3 c, const char* axis, const char* origin, int digits = 4) {
    std::string t;
    for (int i = 0; i < 3; ++i) {
        const std::string n = num(c[i], digits);
        t += (i ? " + " : "") + (c[i] < 0 ? "(" + n + ")" : n) + "·" + axis + sub(i + 1);
    }
    return origin ? t + " + " + origin : t;
}

// (x, y, z, w) for a point (w = 1) or a vector (w = 0).
std::string homogeneous(dvec3 p, int w) {
    return "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ", " + std::to_string(w) + ")";
}

// The same in LaTeX: "2 w_1 + 1 w_2 + 0 w_3 + O_w".
std::string combination_tex(dvec3 c, const char* axis, const char* origin, int digits = 4) {
    std::string t;
    for (int i = 0; i < 3; ++i)
        t += (i ? " + " : "") + (c[i] < 0 ? "(" + tex(c[i], digits) + ")" : tex(c[i], digits)) +
             "\\, " + axis + "_" + std::to_string(i + 1);
    return origin ? t + " + " + origin : t;
}

void check_number(double x, const std::string& field) {
    if (!std::isfinite(x)) throw InputError(field, "must be a finite number (got " + given(x) + ")");
    if (std::fabs(x) > ChangeOfBasis::kMaxMagnitude)
        throw InputError(field, "must be within ±1e100 (got " + given(x) +
                                    "): larger numbers overflow once three of them are multiplied");
}

void check_frame(const Frame& f, const std::string& name, const std::string& course) {
    for (int c = 0; c < 3; ++c)
        check_number(f.origin[c], name + ".origin[" + std::to_string(c) + "]");
    for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c)
            check_number(f.axes[i][c],
                         name + ".axes[" + std::to_string(i) + "][" + std::to_string(c) + "]");
    for (int i = 0; i < 3; ++i) {
        const std::string field = name + ".axes[" + std::to_string(i) + "]";
        if (f.axes[i] == dvec3(0))
            throw InputError(field, "must not be the zero vector: the three axes of " + course +
                                        " must span space");
        if (max_abs(f.axes[i]) < ChangeOfBasis::kMinAxis)
            throw InputError(field, "is too short (" + given(f.axes[i]) +
                                        "): an axis must have a component of at least 1e-100");
    }
    const Scaled sc = scaled(f);
    for (int j = 1; j < 3; ++j)
        for (int i = 0; i < j; ++i) {
            const double sine = glm::length(glm::cross(sc.a[i], sc.a[j])) /
                                (glm::length(sc.a[i]) * glm::length(sc.a[j]));
            if (sine <= ChangeOfBasis::kSingularTolerance)
                throw InputError(
                    name + ".axes[" + std::to_string(j) + "]",
                    std::string(f.axes[i] == f.axes[j] ? "is the same as " : "is parallel to ") +
                        name + ".axes[" + std::to_string(i) + "] (" + given(f.axes[j]) + " and " +
                        given(f.axes[i]) + "): " + course + " needs three independent axes");
        }
    if (sc.ratio <= ChangeOfBasis::kSingularTolerance)
        throw InputError(name + ".axes", "are linearly dependent (det = " + given(determinant(f)) +
                                             ", |det| / (|a₁| |a₂| |a₃|) = " + given(sc.ratio) +
                                             "): the three axes lie in one plane, so " + course +
                                             " is not a frame and has no inverse");
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& ChangeOfBasis::spec() {
    static const Spec spec{
        "change-of-basis",
        "Change of basis: coordinates relative to another frame",
        "Change of Basis",
        {
            "world_from_F1 ← [v₁ v₂ v₃ O_v; 0 0 0 1];  P = p₁v₁ + p₂v₂ + p₃v₃ + O_v = "
            "world_from_F1 p",
            "world_from_F2 ← [w₁ w₂ w₃ O_w; 0 0 0 1]",
            "F2_from_world ← (world_from_F2)⁻¹   ▷ F2 orthonormal: rows w_iᵀ, translation "
            "−w_i · O_w",
            "M₁,₂ ← F2_from_world · world_from_F1   ▷ F2 orthonormal: f_ij = w_i · v_j, "
            "f_i4 = (O_v − O_w) · w_i",
            "for each point p (w = 1):  p' ← M₁,₂ p   ▷ world_from_F2 p' = P: the point has not "
            "moved",
            "for each vector u (w = 0):  u' ← M₁,₂ u   ▷ no translation",
        },
        {
            {"world-from-f1",
             "F1's axes and origin as the columns of a matrix; the points' world "
             "positions"},
            {"world-from-f2", "F2's axes and origin as the columns of a matrix"},
            {"inverse", "F2_from_world as the inverse of world_from_F2 (F2 is not orthonormal)"},
            {"inverse-orthonormal",
             "F2 is orthonormal: its inverse is the transpose, with "
             "translation −w_i · O_w"},
            {"compose", "the change-of-basis matrix M₁,₂ = F2_from_world · world_from_F1"},
            {"map-point", "one point's F1 coordinates rewritten relative to F2"},
            {"map-vector",
             "one vector's F1 coordinates rewritten relative to F2, without the "
             "translation"},
        },
        {},  // no sliders
        {
            .predict = {
                {"world-from-f2", {"world_from_F2"}},
                {"inverse-orthonormal", {"F2_from_world"}},
                {"compose", {"M12"}},
                {"map-point", {"p'"}},
                {"map-vector", {"u'"}},
            },
            .mistakes = {
                {"world-from-f2", "world_from_F2", "transpose",
                 "wrote F2's basis vectors into the rows instead of the columns"},
                {"inverse-orthonormal", "F2_from_world", "transpose",
                 "transposed the whole 4x4 to invert it, translation included"},
                {"map-point", "p'", "copy:p",
                 "kept the old coordinates: the point does not move, so they must be the same"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void ChangeOfBasis::validate(const Input& in) {
    check_frame(in.from, "from", "F1");
    check_frame(in.to, "to", "F2");
    for (std::size_t k = 0; k < in.points.size(); ++k)
        for (int c = 0; c < 3; ++c)
            check_number(in.points[k][c],
                         "points[" + std::to_string(k) + "][" + std::to_string(c) + "]");
    for (std::size_t k = 0; k < in.vectors.size(); ++k)
        for (int c = 0; c < 3; ++c)
            check_number(in.vectors[k][c],
                         "vectors[" + std::to_string(k) + "][" + std::to_string(c) + "]");
    // Within these ranges the matrices are finite; a point far out given in a frame with long
    // axes, rewritten in a frame with short ones, may still not be.
    const Result r = transform(in);
    if (!finite(r.f2_from_world) || !finite(r.matrix))
        throw InputError("to.axes", "are too short to invert within range");
    for (std::size_t k = 0; k < r.points.size(); ++k)
        if (!finite(r.points[k]) || !finite(r.world[k]))
            throw InputError(
                "points[" + std::to_string(k) + "]",
                "its coordinates relative to \"to\" overflow a double: F2's axes are too short "
                "for a point this far out");
    for (std::size_t k = 0; k < r.vectors.size(); ++k)
        if (!finite(r.vectors[k]))
            throw InputError(
                "vectors[" + std::to_string(k) + "]",
                "its coordinates relative to \"to\" overflow a double: F2's axes are too short "
                "for a vector this long");
}

ChangeOfBasis::State ChangeOfBasis::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

ChangeOfBasis::State ChangeOfBasis::begin(Shared<Input> in) {
    State s;
    s.in = std::move(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

dmat4 ChangeOfBasis::world_from(const Frame& f) {
    dmat4 m(1.0);
    for (int i = 0; i < 3; ++i) m[i] = dvec4(f.axes[i], 0.0);
    m[3] = dvec4(f.origin, 1.0);
    return m;
}

bool ChangeOfBasis::orthonormal(const Frame& f) {
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j)
            if (!(std::fabs(glm::dot(f.axes[i], f.axes[j]) - (i == j ? 1.0 : 0.0)) <=
                  kOrthonormalTolerance))
                return false;
    return true;
}

// L⁻¹ for L = [a₁ a₂ a₃]: its rows are a₂ × a₃, a₃ × a₁, a₁ × a₂ over det L (each row is
// perpendicular to two axes and has dot 1 with the third); the translation is −L⁻¹ O.
dmat4 ChangeOfBasis::inverse_general(const Frame& f) {
    const Scaled sc = scaled(f);
    dmat4 m(1.0);
    for (int i = 0; i < 3; ++i) {
        const dvec3 row = glm::cross(sc.a[(i + 1) % 3], sc.a[(i + 2) % 3]) / sc.det / sc.s[i];
        for (int c = 0; c < 3; ++c) m[c][i] = row[c];
        m[3][i] = -glm::dot(row, f.origin);
    }
    return m;
}

dmat4 ChangeOfBasis::inverse_orthonormal(const Frame& f) {
    dmat4 m(1.0);
    for (int i = 0; i < 3; ++i) {
        for (int c = 0; c < 3; ++c) m[c][i] = f.axes[i][c];
        m[3][i] = -glm::dot(f.axes[i], f.origin);
    }
    return m;
}

void ChangeOfBasis::advance(State& s) {
    s.last = s.phase;
    Result& r = s.r;
    switch (s.phase) {
        case Phase::WorldFromF1:  // The frame F1 as a matrix; where the points are
            r.world_from_f1 = world_from(s.in->from);
            r.world.reserve(s.in->points.size());
            for (const dvec3& p : s.in->points) r.world.push_back(point(r.world_from_f1, p));
            s.phase = Phase::WorldFromF2;
            return;
        case Phase::WorldFromF2:  // The frame F2 as a matrix
            r.world_from_f2 = world_from(s.in->to);
            s.phase = Phase::Inverse;
            return;
        case Phase::Inverse:  // Invert it (the shortcut when F2 is orthonormal)
            r.orthonormal_to = orthonormal(s.in->to);
            r.f2_from_world =
                r.orthonormal_to ? inverse_orthonormal(s.in->to) : inverse_general(s.in->to);
            s.phase = Phase::Compose;
            return;
        case Phase::Compose:  // The change-of-basis matrix
            r.matrix = r.f2_from_world * r.world_from_f1;
            r.points.reserve(s.in->points.size());
            r.vectors.reserve(s.in->vectors.size());
            s.phase = !s.in->points.empty()    ? Phase::Points
                      : !s.in->vectors.empty() ? Phase::Vectors
                                              : Phase::Done;
            return;
        case Phase::Points:  // Rewrite one point
            r.points.push_back(point(r.matrix, s.in->points[r.points.size()]));
            if (r.points.size() == s.in->points.size())
                s.phase = s.in->vectors.empty() ? Phase::Done : Phase::Vectors;
            return;
        case Phase::Vectors:  // Rewrite one vector
            r.vectors.push_back(vector(r.matrix, s.in->vectors[r.vectors.size()]));
            if (r.vectors.size() == s.in->vectors.size()) s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void ChangeOfBasis::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

[[gnu::flatten]] ChangeOfBasis::Result ChangeOfBasis::transform(const Input& in) {
    Result r;
    r.world_from_f1 = world_from(in.from);
    r.world.reserve(in.points.size());
    for (const dvec3& p : in.points) r.world.push_back(point(r.world_from_f1, p));
    r.world_from_f2 = world_from(in.to);
    r.orthonormal_to = orthonormal(in.to);
    r.f2_from_world = r.orthonormal_to ? inverse_orthonormal(in.to) : inverse_general(in.to);
    r.matrix = r.f2_from_world * r.world_from_f1;
    r.points.reserve(in.points.size());
    for (const dvec3& p : in.points) r.points.push_back(point(r.matrix, p));
    r.vectors.reserve(in.vectors.size());
    for (const dvec3& u : in.vectors) r.vectors.push_back(vector(r.matrix, u));
    return r;
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string frame_text(const Frame& f, const char* axis, const char* origin) {
    std::string t;
    for (int i = 0; i < 3; ++i) t += std::string(axis) + sub(i + 1) + " = " + num(f.axes[i]) + ", ";
    return t + origin + " = " + num(f.origin);
}

void narrate_f1(const State& s, StepInfo& info) {
    const ChangeOfBasis::Result& r = s.r;
    info.event = "world-from-f1";
    info.line = kLineF1;
    info.narration = "F1 has " + frame_text(s.in->from, "v", "O_v") +
                     " (in world coordinates). As columns, with the homogeneous row 0 0 0 1, "
                     "they make world_from_F1 = " +
                     matrix_text(r.world_from_f1) +
                     ": coordinates (p₁, p₂, p₃, 1) relative to F1 mean the world point "
                     "P = p₁v₁ + p₂v₂ + p₃v₃ + O_v.";
    info.math =
        "M_{W \\leftarrow F_1} = \\begin{bmatrix} v_1 & v_2 & v_3 & O_v \\\\ 0 & 0 & 0 & 1 "
        "\\end{bmatrix} = " +
        matrix_tex(r.world_from_f1);
    const std::size_t shown = std::min<std::size_t>(r.world.size(), 3);
    for (std::size_t k = 0; k < shown; ++k) {
        const std::string name = "P" + std::to_string(k);
        info.narration += " " + name + " = " + combination(s.in->points[k], "v", "O_v") + " = " +
                          num(r.world[k], 4) + " in the world.";
        info.math += ",\\ P_" + std::to_string(k) + " = " + tex(r.world[k], 4);
    }
    if (r.world.size() > shown)
        info.narration += " (and " + std::to_string(r.world.size() - shown) + " more points)";
    if (r.world.empty()) info.narration += " No points are given: the matrices alone.";
}

void narrate_f2(const State& s, StepInfo& info) {
    info.event = "world-from-f2";
    info.line = kLineF2;
    info.narration = "F2 has " + frame_text(s.in->to, "w", "O_w") +
                     ", so world_from_F2 = " + matrix_text(s.r.world_from_f2) +
                     " turns coordinates relative to F2 into world coordinates. We need the "
                     "opposite direction.";
    info.math =
        "M_{W \\leftarrow F_2} = \\begin{bmatrix} w_1 & w_2 & w_3 & O_w \\\\ 0 & 0 & 0 & "
        "1 \\end{bmatrix} = " +
        matrix_tex(s.r.world_from_f2);
}

void narrate_inverse(const State& s, StepInfo& info) {
    const ChangeOfBasis::Result& r = s.r;
    const Frame& f = s.in->to;
    info.line = kLineInverse;
    if (r.orthonormal_to) {
        info.event = "inverse-orthonormal";
        std::string t;
        for (int i = 0; i < 3; ++i)
            t += std::string(i ? ", " : "") + "−w" + sub(i + 1) +
                 " · O_w = " + num(r.f2_from_world[3][i] + 0.0, 4);
        info.narration =
            "w₁, w₂, w₃ are orthonormal (w_i · w_j = 1 when i = j, 0 otherwise), so "
            "the inverse of their 3×3 is its transpose: the rows of F2_from_world "
            "are w₁ᵀ, w₂ᵀ, w₃ᵀ and the translation is " +
            t + ". F2_from_world = " + matrix_text(r.f2_from_world) + ".";
        info.math =
            "M_{F_2 \\leftarrow W} = \\begin{bmatrix} w_1^T & -w_1 \\cdot O_w \\\\ w_2^T & "
            "-w_2 \\cdot O_w \\\\ w_3^T & -w_3 \\cdot O_w \\\\ 0 & 1 \\end{bmatrix} = " +
            matrix_tex(r.f2_from_world);
    } else {
        info.event = "inverse";
        info.narration =
            "w₁, w₂, w₃ are not orthonormal, so there is no transpose shortcut. With "
            "L = [w₁ w₂ w₃] (det L = " +
            num(determinant(f), 4) +
            "), L⁻¹ has the rows (w₂ × w₃, w₃ × w₁, w₁ × w₂) / det L, and the "
            "translation is −L⁻¹ O_w: F2_from_world = " +
            matrix_text(r.f2_from_world) + ".";
        info.math =
            "M_{F_2 \\leftarrow W} = \\begin{bmatrix} L^{-1} & -L^{-1} O_w \\\\ 0 & 1 "
            "\\end{bmatrix} = " +
            matrix_tex(r.f2_from_world);
    }
}

void narrate_compose(const State& s, StepInfo& info) {
    const ChangeOfBasis::Result& r = s.r;
    info.event = "compose";
    info.line = kLineCompose;
    info.narration = "M₁,₂ = F2_from_world · world_from_F1 = " + matrix_text(r.matrix) +
                     ": first from F1 coordinates to the world, then from the world to F2 "
                     "coordinates (the course's F1 = F2 M₁,₂).";
    info.math = "M_{1,2} = M_{F_2 \\leftarrow W} M_{W \\leftarrow F_1} = " + matrix_tex(r.matrix);
    if (r.orthonormal_to) {
        const Frame &f1 = s.in->from, &f2 = s.in->to;
        const dvec3 d = f1.origin - f2.origin;
        info.narration +=
            " Since F2 is orthonormal, each entry is a dot product: f_ij = w_i · v_j "
            "(e.g. f₁₁ = w₁ · v₁ = " +
            num(glm::dot(f2.axes[0], f1.axes[0]), 4) +
            ") and the last column is (O_v − O_w) · w_i = (" + num(glm::dot(d, f2.axes[0]), 4) +
            ", " + num(glm::dot(d, f2.axes[1]), 4) + ", " + num(glm::dot(d, f2.axes[2]), 4) +
            ") with O_v − O_w = " + num(d, 4) + ".";
        info.math += ",\\ f_{ij} = w_i \\cdot v_j,\\ f_{i4} = (O_v - O_w) \\cdot w_i";
    }
}

void narrate_point(const State& s, StepInfo& info) {
    const ChangeOfBasis::Result& r = s.r;
    const std::size_t k = r.points.size() - 1;
    const std::string name = "P" + std::to_string(k);
    const dvec3 p = s.in->points[k], q = r.points[k];
    const dvec3 back = point(r.world_from_f2, q);
    info.event = "map-point";
    info.line = kLinePoint;
    const double off = max_abs(back - r.world[k]);
    info.narration = name + " has coordinates " + num(p) + " relative to F1; M₁,₂ " +
                     homogeneous(p, 1) + "ᵀ = " + num(q, 6) +
                     " are its coordinates relative to F2. Check: " + combination(q, "w", "O_w") +
                     " = " + num(back, 4) + ", the same world point " + name + " = " +
                     num(r.world[k], 4) +
                     (off == 0 ? " exactly" : " up to round-off (" + num(off, 2) + ")") +
                     ": the point has not moved, only its representation has.";
    info.math = "M_{1,2} " + tex(p) + " = " + tex(q, 6) + ",\\ " + combination_tex(q, "w", "O_w") +
                " = " + tex(back, 4);
}

void narrate_vector(const State& s, StepInfo& info) {
    const ChangeOfBasis::Result& r = s.r;
    const std::size_t k = r.vectors.size() - 1;
    const std::string name = "u" + std::to_string(k);
    const dvec3 u = s.in->vectors[k], q = r.vectors[k];
    const dvec3 world = vector(r.world_from_f1, u), back = vector(r.world_from_f2, q);
    info.event = "map-vector";
    info.line = kLineVector;
    info.narration = name + " = " + num(u) + " relative to F1 is the world vector " +
                     combination(u, "v", nullptr) + " = " + num(world, 4) +
                     ". With w = 0 the translation column of M₁,₂ drops out: M₁,₂ " +
                     homogeneous(u, 0) + "ᵀ = " + num(q, 6) + " relative to F2, and " +
                     combination(q, "w", nullptr) + " = " + num(back, 4) + " is the same vector.";
    info.math = "M_{1,2} " + tex(u) + "_{w=0} = " + tex(q, 6);
}

void fill_vars(const State& s, StepInfo& info) {
    const ChangeOfBasis::Result& r = s.r;
    info.vars = {{"v1", vec(s.in->from.axes[0])}, {"v2", vec(s.in->from.axes[1])},
                 {"v3", vec(s.in->from.axes[2])}, {"O_v", vec(s.in->from.origin)},
                 {"w1", vec(s.in->to.axes[0])},   {"w2", vec(s.in->to.axes[1])},
                 {"w3", vec(s.in->to.axes[2])},   {"O_w", vec(s.in->to.origin)}};
    info.vars.push_back({"world_from_F1", rows(r.world_from_f1)});
    if (s.last >= Phase::WorldFromF2) info.vars.push_back({"world_from_F2", rows(r.world_from_f2)});
    if (s.last >= Phase::Inverse) {
        info.vars.push_back({"orthonormal_F2", r.orthonormal_to});
        info.vars.push_back({"F2_from_world", rows(r.f2_from_world)});
    }
    if (s.last >= Phase::Compose) info.vars.push_back({"M12", rows(r.matrix)});
    if (s.last == Phase::Points) {
        const std::size_t k = r.points.size() - 1;
        info.vars.push_back({"k", static_cast<long long>(k)});
        info.vars.push_back({"p", vec(s.in->points[k])});
        info.vars.push_back({"P_world", vec(r.world[k])});
        info.vars.push_back({"p'", vec(r.points[k])});
    }
    if (s.last == Phase::Vectors) {
        const std::size_t k = r.vectors.size() - 1;
        info.vars.push_back({"k", static_cast<long long>(k)});
        info.vars.push_back({"u", vec(s.in->vectors[k])});
        info.vars.push_back({"u'", vec(r.vectors[k])});
    }
}

}  // namespace

void ChangeOfBasis::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::WorldFromF1:
            narrate_f1(s, info);
            break;
        case Phase::WorldFromF2:
            narrate_f2(s, info);
            break;
        case Phase::Inverse:
            narrate_inverse(s, info);
            break;
        case Phase::Compose:
        case Phase::Done:
            narrate_compose(s, info);
            break;
        case Phase::Points:
            narrate_point(s, info);
            break;
        case Phase::Vectors:
            narrate_vector(s, info);
            break;
    }
    fill_vars(s, info);
}

}  // namespace cg
