// Sections: [helpers] [spec] [validate] [advance] [narrate]; the picture is in
// normal_transform_draw.cpp
#include "transforms/normal_transform.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dmat3;
using glm::dvec3;
using Phase = NormalTransform::Phase;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line { kLineLinear = 1, kLineTangents, kLineNaive, kLineInverse, kLineCorrect };

double cos_between(dvec3 a, dvec3 b) { return glm::dot(a, b) / (glm::length(a) * glm::length(b)); }

// Two tangents perpendicular to n, unnormalised so that integer normals give integer tangents:
// t₁ = n × e for the axis e least aligned with n, t₂ = n × t₁.
std::array<dvec3, 2> built_tangents(dvec3 n) {
    const dvec3 a = glm::abs(n);
    const dvec3 e = a.x <= a.y && a.x <= a.z ? dvec3(1, 0, 0) : a.y <= a.z ? dvec3(0, 1, 0) : dvec3(0, 0, 1);
    const dvec3 t1 = glm::cross(n, e);
    return {t1, glm::cross(n, t1)};
}

// (L⁻¹)ᵀ from the columns a, b, c of L: columns b × c, c × a, a × b over det = a · (b × c).
dmat3 inverse_transpose(const dmat3& l, double det) {
    return dmat3(glm::cross(l[1], l[2]) / det, glm::cross(l[2], l[0]) / det,
                 glm::cross(l[0], l[1]) / det);
}

double determinant(const dmat3& l) { return glm::dot(l[0], glm::cross(l[1], l[2])); }

bool finite(dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const dmat3& m) { return finite(m[0]) && finite(m[1]) && finite(m[2]); }

std::vector<std::vector<double>> rows(const dmat3& m) {
    return {{m[0][0], m[1][0], m[2][0]}, {m[0][1], m[1][1], m[2][1]}, {m[0][2], m[1][2], m[2][2]}};
}

std::string matrix_text(const dmat3& m) {
    std::string t = "[";
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) t += (c ? " " : "") + num(m[c][r], 4);
        t += r < 2 ? "; " : "]";
    }
    return t;
}

std::string matrix_tex(const dmat3& m) {
    std::string t = "\\begin{bmatrix} ";
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) t += (c ? " & " : "") + tex(m[c][r], 4);
        t += r < 2 ? " \\\\ " : " \\end{bmatrix}";
    }
    return t;
}

void check_finite(dvec3 v, const std::string& field) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i]))
            throw InputError(field + "[" + std::to_string(i) + "]",
                             "must be a finite number (got " + given(v[i]) + ")");
}

}  // namespace

std::array<dvec3, 2> NormalTransform::tangents_of(const Input& in) {
    return in.has_tangents ? in.tangents : built_tangents(in.normal);
}

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& NormalTransform::spec() {
    static const Spec spec{
        "normal-transform",
        "Transforming normals by the inverse transpose",
        "World and Viewing Frames",
        {
            "L ← the linear part (upper 3×3) of the transformation;  det L ≠ 0",
            "t₁, t₂ ← two tangents with n · tᵢ = 0;  they transform as L tᵢ",
            "naive: L n — is it still perpendicular to L t₁ and L t₂?",
            "N ← (L⁻¹)ᵀ = [b × c, c × a, a × b] / det L   (a, b, c the columns of L)",
            "n' ← N n:  (N n) · (L t) = nᵀ L⁻¹ L t = n · t = 0",
        },
        {
            {"linear-part", "the linear part of the transformation and its determinant"},
            {"tangents", "two tangents of the surface, perpendicular to the normal"},
            {"naive-fails", "L n is no longer perpendicular to the transformed tangents"},
            {"naive-works", "L n stays perpendicular: L is a rotation times a uniform scale"},
            {"inverse-transpose", "the normal matrix (L⁻¹)ᵀ"},
            {"normal-correct", "N n, perpendicular to every transformed tangent"},
        },
        {},  // no sliders
        {
            .predict = {
                {"tangents", {"Lt1", "Lt2"}},
                {"naive-fails", {"Ln"}},
                {"inverse-transpose", {"N"}},
                {"normal-correct", {"n_prime"}},
            },
            .mistakes = {
                {"inverse-transpose", "N", "copy:L", "transformed the normal by L, like a tangent"},
                {"naive-fails", "naive_ok", "not",
                 "took L n to be still perpendicular to the tangents"},
                {"normal-correct", "n_prime", "copy:n",
                 "left the normal as it was: thought normals are unchanged by the transform"},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void NormalTransform::validate(const Input& in) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(in.linear[c][r]))
                throw InputError("matrix[" + std::to_string(r) + "][" + std::to_string(c) + "]",
                                 "must be a finite number (got " + given(in.linear[c][r]) + ")");
    check_finite(in.normal, "normal");
    const double det = determinant(in.linear);
    const double size = glm::length(in.linear[0]) * glm::length(in.linear[1]) * glm::length(in.linear[2]);
    if (!std::isfinite(det) || !std::isfinite(size))
        throw InputError("matrix", "is too large to invert");
    if (std::fabs(det) <= 1e-12 * size)
        throw InputError("matrix", "is singular (det = " + given(det) +
                                       "): it flattens space, so it has no inverse and no normal "
                                       "matrix");
    if (!finite(inverse_transpose(in.linear, det)))
        throw InputError("matrix", "is too small or too large to invert (det = " + given(det) + ")");
    if (in.normal == dvec3(0)) throw InputError("normal", "must not be the zero vector");
    if (!std::isfinite(glm::length(in.normal)) || glm::length(in.normal) < 1e-150)
        throw InputError("normal", "is too large or too small to normalise (" + given(in.normal) + ")");
    const std::array<dvec3, 2> t = in.has_tangents ? in.tangents : built_tangents(in.normal);
    for (int i = 0; i < 2; ++i) {
        const std::string f = "tangents[" + std::to_string(i) + "]";
        if (!in.has_tangents) break;
        check_finite(t[i], f);
        if (t[i] == dvec3(0)) throw InputError(f, "must not be the zero vector");
        if (!std::isfinite(glm::length(t[i])) || glm::length(t[i]) < 1e-150)
            throw InputError(f, "is too large or too small to use (" + given(t[i]) + ")");
        if (std::fabs(cos_between(t[i], in.normal)) > kPerpTolerance)
            throw InputError(f, "must be perpendicular to the normal (t · n = " +
                                    given(glm::dot(t[i], in.normal)) + ")");
    }
    if (in.has_tangents &&
        glm::length(glm::cross(t[0], t[1])) <= 1e-9 * glm::length(t[0]) * glm::length(t[1]))
        throw InputError("tangents[1]", "must not be parallel to tangents[0]: they must span the "
                                        "surface's plane");
    // The results are normalised and compared by cosines, so each mapped vector's length must be
    // finite and not underflow (det = 1e-300 maps n = (1, 1, 0) to (1e300, 1, 0), whose |n'|²
    // overflows and made the unit normal (0, 0, 0)).
    const auto usable = [](dvec3 v) {
        const double len = glm::length(v);
        return std::isfinite(len) && len >= 1e-150;
    };
    for (int i = 0; i < 2; ++i)
        if (!usable(in.linear * t[i]) || !usable(in.linear * in.normal) ||
            !usable(inverse_transpose(in.linear, det) * in.normal))
            throw InputError("matrix", "maps the vectors out of range");
}

NormalTransform::State NormalTransform::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

NormalTransform::State NormalTransform::begin(Shared<Input> in) {
    State s;
    s.in = std::move(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void NormalTransform::advance(State& s) {
    s.last = s.phase;
    Result& r = s.r;
    switch (s.phase) {
        case Phase::Linear:
            r.det = determinant(s.in->linear);
            s.phase = Phase::Tangents;
            return;
        case Phase::Tangents:
            r.tangents = s.in->has_tangents ? s.in->tangents : built_tangents(s.in->normal);
            r.images = {s.in->linear * r.tangents[0], s.in->linear * r.tangents[1]};
            s.phase = Phase::Naive;
            return;
        case Phase::Naive:
            r.naive = s.in->linear * s.in->normal;
            r.naive_cos = {cos_between(r.naive, r.images[0]), cos_between(r.naive, r.images[1])};
            r.naive_ok = std::fabs(r.naive_cos[0]) <= kPerpTolerance &&
                         std::fabs(r.naive_cos[1]) <= kPerpTolerance;
            s.phase = Phase::InverseTranspose;
            return;
        case Phase::InverseTranspose:
            r.inverse_transpose = inverse_transpose(s.in->linear, r.det);
            s.phase = Phase::Correct;
            return;
        case Phase::Correct:
            r.normal = r.inverse_transpose * s.in->normal;
            r.unit_normal = glm::normalize(r.normal);
            r.cos = {cos_between(r.normal, r.images[0]), cos_between(r.normal, r.images[1])};
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// Straight through, for the benchmark's comparison (the tests check it equals the steps).
[[gnu::flatten]] NormalTransform::Result NormalTransform::transform(const Input& in) {
    Result r;
    r.det = determinant(in.linear);
    r.tangents = in.has_tangents ? in.tangents : built_tangents(in.normal);
    r.images = {in.linear * r.tangents[0], in.linear * r.tangents[1]};
    r.naive = in.linear * in.normal;
    r.naive_cos = {cos_between(r.naive, r.images[0]), cos_between(r.naive, r.images[1])};
    r.naive_ok = std::fabs(r.naive_cos[0]) <= kPerpTolerance && std::fabs(r.naive_cos[1]) <= kPerpTolerance;
    r.inverse_transpose = inverse_transpose(in.linear, r.det);
    r.normal = r.inverse_transpose * in.normal;
    r.unit_normal = glm::normalize(r.normal);
    r.cos = {cos_between(r.normal, r.images[0]), cos_between(r.normal, r.images[1])};
    return r;
}

// ---- [narrate] ------------------------------------------------------------------------------

void NormalTransform::narrate(const State& s, StepInfo& info) {
    const Result& r = s.r;
    info.math.clear();
    switch (s.last) {
        case Phase::Linear:
            info.event = "linear-part";
            info.line = kLineLinear;
            info.narration = "The linear part L = " + matrix_text(s.in->linear) + " (det L = " +
                             num(r.det, 4) + "): tangents transform by L; translations do not "
                                             "act on vectors at all.";
            info.math = "L = " + matrix_tex(s.in->linear) + ",\\ \\det L = " + tex(r.det, 4);
            break;
        case Phase::Tangents:
            info.event = "tangents";
            info.line = kLineTangents;
            info.narration = "n = " + num(s.in->normal) + " stands on the plane spanned by t₁ = " +
                             num(r.tangents[0], 4) + " and t₂ = " + num(r.tangents[1], 4) +
                             (s.in->has_tangents ? " (as given)" : " (t₁ = n × e for the axis e "
                                                                   "least aligned with n, t₂ = n × t₁)") +
                             "; after the transformation they are L t₁ = " + num(r.images[0], 4) +
                             " and L t₂ = " + num(r.images[1], 4) + ".";
            info.math = "L t_1 = " + tex(r.images[0], 4) + ",\\ L t_2 = " + tex(r.images[1], 4);
            break;
        case Phase::Naive:
            info.event = r.naive_ok ? "naive-works" : "naive-fails";
            info.line = kLineNaive;
            info.narration = "Transforming n like a tangent gives L n = " + num(r.naive, 4) +
                             ": (L n) · (L t₁) = " + num(glm::dot(r.naive, r.images[0]), 4) +
                             ", (L n) · (L t₂) = " + num(glm::dot(r.naive, r.images[1]), 4) +
                             (r.naive_ok ? ": still perpendicular — L only rotates and scales "
                                           "uniformly here."
                                         : ": no longer perpendicular (" +
                                               num(std::acos(std::clamp(r.naive_cos[0], -1.0, 1.0)) * 180 /
                                                       3.14159265358979323846, 4) +
                                               "° to L t₁ instead of 90°): L n is not a normal.");
            info.math = "(L n) \\cdot (L t_1) = " + tex(glm::dot(r.naive, r.images[0]), 4) +
                        ",\\ (L n) \\cdot (L t_2) = " + tex(glm::dot(r.naive, r.images[1]), 4);
            break;
        case Phase::InverseTranspose:
            info.event = "inverse-transpose";
            info.line = kLineInverse;
            info.narration = "The normal matrix N = (L⁻¹)ᵀ, column by column the cross products "
                             "of L's columns over det L = " +
                             num(r.det, 4) + ": N = " + matrix_text(r.inverse_transpose) + ".";
            info.math = "N = (L^{-1})^T = \\frac{1}{\\det L}[b \\times c,\\ c \\times a,\\ a \\times b] = " +
                        matrix_tex(r.inverse_transpose);
            break;
        case Phase::Correct:
        case Phase::Done:
            info.event = "normal-correct";
            info.line = kLineCorrect;
            info.narration = "n' = N n = " + num(r.normal, 4) + " (unit " + num(r.unit_normal, 4) +
                             "): n' · (L t₁) = " + num(glm::dot(r.normal, r.images[0]), 3) +
                             " and n' · (L t₂) = " + num(glm::dot(r.normal, r.images[1]), 3) +
                             ", perpendicular as a normal must be" +
                             (r.naive_ok ? " (and parallel to L n, since L is a similarity)."
                                         : ", where L n was not.");
            info.math = "n' = N n = " + tex(r.normal, 4) +
                        ",\\ n'^T L t = n^T L^{-1} L t = n \\cdot t = 0";
            break;
    }
    info.vars = {{"L", rows(s.in->linear)}, {"n", vec(s.in->normal)}};
    if (s.last >= Phase::Linear) info.vars.push_back({"det", r.det});
    if (s.last >= Phase::Tangents) {
        info.vars.push_back({"t1", vec(r.tangents[0])});
        info.vars.push_back({"t2", vec(r.tangents[1])});
        info.vars.push_back({"Lt1", vec(r.images[0])});
        info.vars.push_back({"Lt2", vec(r.images[1])});
    }
    if (s.last >= Phase::Naive) {
        info.vars.push_back({"Ln", vec(r.naive)});
        info.vars.push_back({"naive_ok", r.naive_ok});
    }
    if (s.last >= Phase::InverseTranspose) info.vars.push_back({"N", rows(r.inverse_transpose)});
    if (s.last >= Phase::Correct) info.vars.push_back({"n_prime", vec(r.normal)});
}

void NormalTransform::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

}  // namespace cg
