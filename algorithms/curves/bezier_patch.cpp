// Sections: [spec] [start] [shared math] [advance] [narrate] [step and result] [draw].
#include "curves/bezier_patch.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "curves/de_casteljau.hpp"

namespace cg {

namespace {

using curves::bezier_derivative;
using curves::bezier_point;
using curves::subscript;

// Pseudocode, 1-based lines as the steps report them.
enum Line {
    kLineColumns = 1,
    kLineColumn,
    kLineColumnDerivative,
    kLinePoint,
    kLineDerivatives,
    kLineNormal,
    kLineTessellate,
};

// Column j of the grid, P_0j .. P_mj, copied into `out`; returns the count m + 1.
std::size_t gather_column(const BezierPatch::Input& in, int j, BezierPatch::Row& out) {
    const std::size_t rows = in.control_points.size();
    for (std::size_t i = 0; i < rows; ++i) out[i] = in.control_points[i][static_cast<std::size_t>(j)];
    return rows;
}

std::span<const glm::dvec3> first(const BezierPatch::Row& row, int count) {
    return {row.data(), static_cast<std::size_t>(count)};
}

std::string name(const char* letter, int i, int j) {
    return letter + subscript(i) + subscript(j);
}

// The de Casteljau triangle of a list of points at u, from the curve algorithm itself.
DeCasteljau::Result triangle(std::span<const glm::dvec3> points, double u) {
    DeCasteljau::Input in;
    in.control_points.assign(points.begin(), points.end());
    in.dim = 3;
    in.t = u;
    in.extrapolate = true;
    return DeCasteljau::evaluate(in);
}

// The inner levels 1 .. degree − 1 of a triangle as text ("" for degree 1; shortened when long).
std::string levels_text(const DeCasteljau::Result& tri, const char* letter) {
    std::string out;
    for (int k = 1; k < tri.n; ++k) {
        out += "level " + std::to_string(k) + ": ";
        const auto level = tri.level(k);
        for (std::size_t i = 0; i < level.size(); ++i) {
            if (level.size() > 4 && i == 2) {
                out += ", …";
                i = level.size() - 2;
                continue;
            }
            out += (i ? ", " : "") + std::string(letter) + subscript(static_cast<int>(i)) +
                   curves::superscript(k) + " = " + num(level[i]);
        }
        out += "; ";
    }
    return out;
}

std::vector<std::vector<double>> coords(std::span<const glm::dvec3> ps) {
    std::vector<std::vector<double>> m;
    for (const glm::dvec3& p : ps) m.push_back(vec(p));
    return m;
}

}  // namespace

// --- [spec] -------------------------------------------------------------------------------------

const Spec& BezierPatch::spec() {
    static const Spec spec{
        "bezier-patch",
        "Tensor-product Bézier patches: de Casteljau along s, then along t",
        "Splines",
        {
            "for j = 0 .. n:   (column j, P_0j .. P_mj, is a Bézier curve in s)",
            "    Q_j ← de Casteljau(P_0j .. P_mj; s)",
            "    R_j ← m (P_1j^{m−1} − P_0j^{m−1})   (the column's s-derivative)",
            "P(s, t) ← de Casteljau(Q_0 .. Q_n; t)",
            "∂P/∂t ← n (Q_1^{n−1} − Q_0^{n−1}),   ∂P/∂s ← de Casteljau(R_0 .. R_n; t)",
            "N ← (∂P/∂s × ∂P/∂t) / |∂P/∂s × ∂P/∂t|   (undefined where the cross product is 0)",
            "mesh ← P(a/N, b/N) for a, b = 0 .. N; each cell → 2 triangles",
        },
        {
            {"column",
             "de Casteljau in s on one column of the grid gives Q_j, a control point of the "
             "curve t ↦ P(s, t)"},
            {"point", "de Casteljau in t on the Q_j gives the surface point P(s, t)"},
            {"derivatives", "the partial derivatives ∂P/∂s and ∂P/∂t, tangent to the surface"},
            {"normal", "their cross product, scaled to length 1: the surface normal"},
            {"tessellate",
             "the surface sampled on an (N + 1) × (N + 1) grid and split into 2N² triangles"},
        },
        {},  // no sliders
        {
            .predict = {
                {"column", {"Q_j"}},
                {"point", {"P(s,t)"}},
                {"derivatives", {"dP/ds", "dP/dt"}},
                {"normal", {"N"}},
            },
            .mistakes = {
                {"normal", "N", "negate", "crossed dP/dt × dP/ds: the normal points inwards"},
                {"derivatives", "dP/ds", "swap:dP/dt", "mixed up the s and t directions"},
            },
        },
    };
    return spec;
}

std::array<int, 3> BezierPatch::Result::triangle(int k) const {
    const int N = tessellation, cell = k / 2, a = cell / N, b = cell % N;
    const int v00 = a * (N + 1) + b, v10 = v00 + N + 1, v11 = v10 + 1, v01 = v00 + 1;
    return k % 2 == 0 ? std::array<int, 3>{v00, v10, v11} : std::array<int, 3>{v00, v11, v01};
}

// --- [start] ------------------------------------------------------------------------------------

void BezierPatch::validate(const Input& in) {
    const auto& grid = in.control_points;
    const std::size_t max_count = kMaxDegree + 1;
    if (grid.size() < 2)
        throw InputError("control_points",
                         "needs at least 2 rows (degree 1 in s), got " + std::to_string(grid.size()));
    if (grid.size() > max_count)
        throw InputError("control_points", "takes at most " + std::to_string(max_count) +
                                               " rows (degree 10 in s), got " +
                                               std::to_string(grid.size()));
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const std::string field = "control_points[" + std::to_string(i) + "]";
        if (i > 0 && grid[i].size() != grid[0].size())
            throw InputError(field, "has " + std::to_string(grid[i].size()) +
                                        " points but control_points[0] has " +
                                        std::to_string(grid[0].size()) +
                                        ": every row of the grid needs the same number");
        curves::validate_points(grid[i], 3, field, 2, max_count);
    }
    curves::validate_t(in.s, in.extrapolate, "s");
    curves::validate_t(in.t, in.extrapolate, "t");
    if (in.tessellation < 1 || in.tessellation > kMaxTessellation)
        throw InputError("tessellation", "must be an integer from 1 to " +
                                             std::to_string(kMaxTessellation) + " (got " +
                                             std::to_string(in.tessellation) + ")");
}

BezierPatch::State BezierPatch::start(const Input& in) {
    validate(in);
    return begin(in);
}

BezierPatch::State BezierPatch::begin(const Input& in) {
    State s;
    s.in = Shared<Input>(in);
    s.m = static_cast<int>(in.control_points.size()) - 1;
    s.n = static_cast<int>(in.control_points[0].size()) - 1;
    for (const auto& row : in.control_points) s.scale = std::max(s.scale, curves::coordinate_scale(row));
    return s;
}

// --- [shared math] ------------------------------------------------------------------------------

glm::dvec3 BezierPatch::point_at(const Input& in, double s, double t) {
    const int columns = static_cast<int>(in.control_points[0].size());
    Row column, q;
    for (int j = 0; j < columns; ++j) {
        const std::size_t count = gather_column(in, j, column);
        q[static_cast<std::size_t>(j)] = bezier_point({column.data(), count}, s);
    }
    return bezier_point(first(q, columns), t);
}

bool BezierPatch::unit_normal(glm::dvec3 ds, glm::dvec3 dt, double scale, glm::dvec3& normal) {
    // Each vector is first divided by its largest |coordinate|, so the cross product neither
    // overflows for huge coordinates nor underflows for tiny ones; it is then sin(angle) long.
    const double tiny = 1e-12 * scale;
    auto direction = [tiny](glm::dvec3 v) {
        const double big = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
        if (!(big > tiny) || big == 0) return glm::dvec3(0);
        v /= big;
        return v / glm::length(v);
    };
    const glm::dvec3 c = glm::cross(direction(ds), direction(dt));
    const double sine = glm::length(c);
    if (!(sine > 1e-12)) {
        normal = glm::dvec3(0);
        return false;
    }
    normal = c / sine;
    return true;
}

std::vector<glm::dvec3> BezierPatch::tessellate(const Input& in, int N) {
    const int columns = static_cast<int>(in.control_points[0].size());
    std::vector<glm::dvec3> out(static_cast<std::size_t>((N + 1) * (N + 1)));
    Row column, q;
    glm::dvec3* v = out.data();
    for (int a = 0; a <= N; ++a) {
        const double s = static_cast<double>(a) / N;
        // The Q_j of this s serve the whole row of vertices (as in point_at, term for term).
        for (int j = 0; j < columns; ++j) {
            const std::size_t count = gather_column(in, j, column);
            q[static_cast<std::size_t>(j)] = bezier_point({column.data(), count}, s);
        }
        for (int b = 0; b <= N; ++b) *v++ = bezier_point(first(q, columns), static_cast<double>(b) / N);
    }
    return out;
}

// --- [advance] ----------------------------------------------------------------------------------

void BezierPatch::advance(State& s) {
    const Input& in = *s.in;
    switch (s.phase) {
        case Phase::Column: {  // de Casteljau in s down column j: Q_j and its derivative R_j
            Row column;
            const std::size_t count = gather_column(in, s.j, column);
            const std::span<const glm::dvec3> c{column.data(), count};
            s.q[static_cast<std::size_t>(s.j)] = bezier_point(c, in.s);
            s.r[static_cast<std::size_t>(s.j)] = bezier_derivative(c, in.s);
            if (++s.j > s.n) s.phase = Phase::Point;
            return;
        }
        case Phase::Point:  // de Casteljau in t on the Q_j
            s.point = bezier_point(first(s.q, s.n + 1), in.t);
            s.phase = Phase::Derivatives;
            return;
        case Phase::Derivatives:
            s.dt = bezier_derivative(first(s.q, s.n + 1), in.t);
            s.ds = bezier_point(first(s.r, s.n + 1), in.t);
            s.phase = Phase::Normal;
            return;
        case Phase::Normal:
            s.normal_defined = unit_normal(s.ds, s.dt, s.scale, s.normal);
            s.phase = Phase::Tessellate;
            return;
        case Phase::Tessellate:
            s.vertices = tessellate(in, in.tessellation);
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// --- [narrate] ----------------------------------------------------------------------------------

void BezierPatch::narrate(const State& s, StepInfo& info) {
    const Input& in = *s.in;
    const std::string ss = num(in.s), ts = num(in.t);
    info.vars = {{"s", in.s},
                 {"t", in.t},
                 {"m", static_cast<long long>(s.m)},
                 {"n", static_cast<long long>(s.n)}};
    const std::string outside =
        (in.s < 0 || in.s > 1 || in.t < 0 || in.t > 1)
            ? "(s, t) lies outside [0, 1]²: this extrapolates the polynomial surface. "
            : "";
    switch (s.phase) {
        case Phase::Column:
        case Phase::Point:
            {  // Column j − 1 was just done.
                const int j = s.j - 1;
                Row column;
                const std::size_t count = gather_column(in, j, column);
                const DeCasteljau::Result tri = triangle({column.data(), count}, in.s);
                const glm::dvec3 q = s.q[static_cast<std::size_t>(j)],
                                 r = s.r[static_cast<std::size_t>(j)];
                info.event = "column";
                info.line = kLineColumn;
                info.narration = (j == 0 ? outside : "") + "Column " + std::to_string(j) + ", " +
                                 name("P", 0, j) + " … " + name("P", s.m, j) +
                                 ", is a Bézier curve in s; de Casteljau at s = " + ss + ": " +
                                 levels_text(tri, "P") + "its last level is Q" + subscript(j) +
                                 " = " + num(q) + ", and " + std::to_string(s.m) +
                                 " times its last segment is the column's s-derivative R" +
                                 subscript(j) + " = " + num(r) + ".";
                info.math = "Q_{" + std::to_string(j) + "} = \\sum_{i=0}^{" + std::to_string(s.m) +
                            "} P_{i" + std::to_string(j) + "} B_i^{" + std::to_string(s.m) + "}(" +
                            tex(in.s) + ") = " + tex(q) + ",\\quad R_{" + std::to_string(j) +
                            "} = " + tex(r);
                info.vars.push_back({"j", static_cast<long long>(j)});
                info.vars.push_back({"Q_j", vec(q)});
                info.vars.push_back({"R_j", vec(r)});
                info.vars.push_back({"Q", coords(first(s.q, s.j))});
                return;
            }
        case Phase::Derivatives: {
            const DeCasteljau::Result tri = triangle(first(s.q, s.n + 1), in.t);
            info.event = "point";
            info.line = kLinePoint;
            info.narration = "Q₀ … Q" + subscript(s.n) +
                             " are the control points of the surface curve t ↦ P(" + ss +
                             ", t); de Casteljau at t = " + ts + ": " + levels_text(tri, "Q") +
                             "its last level is the surface point P(" + ss + ", " + ts +
                             ") = " + num(s.point) + ".";
            info.math = "P(" + tex(in.s) + ", " + tex(in.t) + ") = \\sum_{j=0}^{" +
                        std::to_string(s.n) + "} Q_j B_j^{" + std::to_string(s.n) + "}(" +
                        tex(in.t) + ") = " + tex(s.point);
            info.vars.push_back({"Q", coords(first(s.q, s.n + 1))});
            info.vars.push_back({"P(s,t)", vec(s.point)});
            return;
        }
        case Phase::Normal: {
            const DeCasteljau::Result tri = triangle(first(s.q, s.n + 1), in.t);
            const glm::dvec3 a = tri.at(s.n - 1, 0), b = tri.at(s.n - 1, 1);
            info.event = "derivatives";
            info.line = kLineDerivatives;
            info.narration = "Along t the surface moves like the Q curve: ∂P/∂t = " +
                             std::to_string(s.n) + "·(" + num(b) + " − " + num(a) + ") = " +
                             num(s.dt) + ". Along s it moves as the columns do: their " +
                             "s-derivatives R₀ … R" + subscript(s.n) + " blended in t give ∂P/∂s = " +
                             num(s.ds) + ".";
            info.math = "\\frac{\\partial P}{\\partial s} = \\sum_j R_j B_j^{" +
                        std::to_string(s.n) + "}(" + tex(in.t) + ") = " + tex(s.ds) +
                        ",\\quad \\frac{\\partial P}{\\partial t} = " + std::to_string(s.n) +
                        "\\left(Q_1^{" + std::to_string(s.n - 1) + "} - Q_0^{" +
                        std::to_string(s.n - 1) + "}\\right) = " + tex(s.dt);
            info.vars.push_back({"P(s,t)", vec(s.point)});
            info.vars.push_back({"dP/ds", vec(s.ds)});
            info.vars.push_back({"dP/dt", vec(s.dt)});
            return;
        }
        case Phase::Tessellate: {
            info.event = "normal";
            info.line = kLineNormal;
            if (s.normal_defined) {
                info.narration = "The cross product ∂P/∂s × ∂P/∂t = " +
                                 num(glm::cross(s.ds, s.dt)) +
                                 " is perpendicular to both tangents; scaled to length 1 it is "
                                 "the surface normal N = " +
                                 num(s.normal) + ".";
                info.math = "N = \\frac{\\partial_s P \\times \\partial_t P}{\\lVert \\partial_s "
                            "P \\times \\partial_t P \\rVert} = " +
                            tex(s.normal);
            } else {
                const double tiny = 1e-12 * s.scale;
                auto zero = [tiny](glm::dvec3 v) {
                    const double big = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
                    return !(big > tiny) || big == 0;
                };
                const std::string why =
                    zero(s.ds) && zero(s.dt) ? "both ∂P/∂s and ∂P/∂t are zero"
                    : zero(s.ds)             ? "∂P/∂s is zero (control points collapsed along s)"
                    : zero(s.dt)             ? "∂P/∂t is zero (control points collapsed along t)"
                                             : "∂P/∂s and ∂P/∂t are parallel";
                info.narration = "No normal here: " + why +
                                 ", so their cross product is the zero vector and has no "
                                 "direction. This happens where control points coincide (a "
                                 "collapsed corner or edge); the surface may still have a "
                                 "tangent plane in the limit, but this formula cannot give it.";
                info.math = "\\frac{\\partial P}{\\partial s} \\times \\frac{\\partial P}{\\partial "
                            "t} = 0 \\Rightarrow N \\text{ undefined}";
            }
            info.vars.push_back({"N", vec(s.normal)});
            info.vars.push_back({"normal defined", s.normal_defined});
            return;
        }
        case Phase::Done: {
            const int N = in.tessellation;
            info.event = "tessellate";
            info.line = kLineTessellate;
            info.narration = "Tessellation: the surface at s, t = 0, 1/" + std::to_string(N) +
                             ", …, 1 gives (" + std::to_string(N) + " + 1)² = " +
                             std::to_string((N + 1) * (N + 1)) + " vertices; each of the " +
                             std::to_string(N * N) +
                             " cells is split along its diagonal into 2 triangles, " +
                             std::to_string(2 * N * N) +
                             " in all, ordered counter-clockwise around ∂P/∂s × ∂P/∂t. The "
                             "corners are the corner control points.";
            info.math = "V_{ab} = P\\left(\\tfrac{a}{" + std::to_string(N) + "}, \\tfrac{b}{" +
                        std::to_string(N) + "}\\right),\\quad 2N^2 = " +
                        std::to_string(2 * N * N) + " \\text{ triangles}";
            info.vars.push_back({"N", static_cast<long long>(N)});
            info.vars.push_back({"vertices", static_cast<long long>((N + 1) * (N + 1))});
            info.vars.push_back({"triangles", static_cast<long long>(2 * N * N)});
            return;
        }
    }
}

// --- [step and result] --------------------------------------------------------------------------

void BezierPatch::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

namespace {

BezierPatch::Result view(const BezierPatch::State& s) {
    BezierPatch::Result r;
    r.m = s.m, r.n = s.n, r.s = s.in->s, r.t = s.in->t;
    r.point = s.point, r.ds = s.ds, r.dt = s.dt, r.normal = s.normal;
    r.normal_defined = s.normal_defined;
    r.column_points.assign(s.q.begin(), s.q.begin() + s.j);
    r.tessellation = s.in->tessellation;
    return r;
}

}  // namespace

BezierPatch::Result BezierPatch::result(const State& s) {
    Result r = view(s);
    r.vertices = s.vertices;
    return r;
}

BezierPatch::Result BezierPatch::result(State&& s) {
    Result r = view(s);
    r.vertices = std::move(s.vertices);
    return r;
}

BezierPatch::Result BezierPatch::evaluate(const Input& in) {
    Result r;
    r.m = static_cast<int>(in.control_points.size()) - 1;
    r.n = static_cast<int>(in.control_points[0].size()) - 1;
    r.s = in.s, r.t = in.t, r.tessellation = in.tessellation;
    Row column, q, d;
    double scale = 0;
    for (int j = 0; j <= r.n; ++j) {
        const std::size_t count = gather_column(in, j, column);
        const std::span<const glm::dvec3> c{column.data(), count};
        q[static_cast<std::size_t>(j)] = bezier_point(c, in.s);
        d[static_cast<std::size_t>(j)] = bezier_derivative(c, in.s);
    }
    for (const auto& row : in.control_points) scale = std::max(scale, curves::coordinate_scale(row));
    r.column_points.assign(q.begin(), q.begin() + r.n + 1);
    r.point = bezier_point(first(q, r.n + 1), in.t);
    r.dt = bezier_derivative(first(q, r.n + 1), in.t);
    r.ds = bezier_point(first(d, r.n + 1), in.t);
    r.normal_defined = unit_normal(r.ds, r.dt, scale, r.normal);
    r.vertices = tessellate(in, in.tessellation);
    return r;
}

// --- [draw] -------------------------------------------------------------------------------------

namespace {

// A curve drawn as a chain of 3D segments.
void curve3(Scene& scene, std::span<const glm::dvec3> control, Style style, int samples = 32) {
    glm::dvec3 prev = control.front();
    for (int k = 1; k <= samples; ++k) {
        const glm::dvec3 p = bezier_point(control, static_cast<double>(k) / samples);
        scene.segments3.push_back({prev, p, "", style, false});
        prev = p;
    }
}

// The inner levels of a de Casteljau triangle: segments and points in the levels' shades.
void triangle3(Scene& scene, const DeCasteljau::Result& tri, bool labels, const char* letter) {
    for (int k = 1; k < tri.n; ++k) {
        const Style style{Role::Neutral, 1.5f, false, curves::shade(k)};
        const auto level = tri.level(k);
        for (std::size_t i = 0; i + 1 < level.size(); ++i)
            scene.segments3.push_back({level[i], level[i + 1], "", style, false});
        for (std::size_t i = 0; i < level.size(); ++i)
            scene.points3.push_back(
                {level[i],
                 labels ? letter + subscript(static_cast<int>(i)) + curves::superscript(k) : "",
                 style, 3.5f});
    }
}

}  // namespace

void BezierPatch::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const auto& grid = in.control_points;
    const bool finished = s.phase == Phase::Done;
    const bool small = (s.m + 1) * (s.n + 1) <= 16;

    // The size of the picture, for arrows: the control points' bounding-box diagonal.
    glm::dvec3 lo = grid[0][0], hi = grid[0][0];
    for (const auto& row : grid)
        for (const glm::dvec3& p : row) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const double size = std::max(glm::length(hi - lo), 1e-300);

    // The surface: the finished mesh, or a faint preview of it while the steps run.
    const int N = finished ? in.tessellation : std::min(in.tessellation, 12);
    const std::vector<glm::dvec3> preview = finished ? std::vector<glm::dvec3>{} : tessellate(in, N);
    const std::vector<glm::dvec3>& mesh = finished ? s.vertices : preview;
    const auto vertex = [&](int a, int b) {
        return mesh[static_cast<std::size_t>(a * (N + 1) + b)];
    };
    for (int a = 0; a < N; ++a)
        for (int b = 0; b < N; ++b) {
            const Style style = finished ? Style{Role::Kept, 1.0f} : Style{Role::Construction, 1.0f};
            const float alpha = finished ? 0.3f : 0.1f;
            scene.faces3.push_back({{vertex(a, b), vertex(a + 1, b), vertex(a + 1, b + 1)},
                                    style, alpha, finished, true});
            scene.faces3.push_back({{vertex(a, b), vertex(a + 1, b + 1), vertex(a, b + 1)},
                                    style, alpha, finished, true});
        }

    // The control net.
    const Style net{Role::Subject, 1.5f};
    for (std::size_t i = 0; i < grid.size(); ++i)
        for (std::size_t j = 0; j < grid[i].size(); ++j) {
            if (j + 1 < grid[i].size())
                scene.segments3.push_back({grid[i][j], grid[i][j + 1], "", net, false});
            if (i + 1 < grid.size())
                scene.segments3.push_back({grid[i][j], grid[i + 1][j], "", net, false});
            scene.points3.push_back(  // named, but the step's subject is placed first
                {grid[i][j],
                 small ? name("P", static_cast<int>(i), static_cast<int>(j)) : "", net, 4.0f, -1});
        }

    // The column just done: its curve in s and its de Casteljau construction.
    if (s.j > 0 && (s.phase == Phase::Column || s.phase == Phase::Point)) {
        Row column;
        const std::size_t count = gather_column(in, s.j - 1, column);
        const std::span<const glm::dvec3> c{column.data(), count};
        curve3(scene, c, {Role::Active, 2.5f});
        triangle3(scene, triangle(c, in.s), small, "P");
    }
    // The Q_j so far; once all are there, their polygon and the surface curve t ↦ P(s, t).
    for (int j = 0; j < s.j; ++j)
        scene.points3.push_back(
            {s.q[static_cast<std::size_t>(j)], "Q" + subscript(j), {Role::Entering}, 5.0f});
    if (s.j == s.n + 1 && s.phase != Phase::Point) {
        const auto q = first(s.q, s.n + 1);
        for (int j = 0; j < s.n; ++j)
            scene.segments3.push_back({q[static_cast<std::size_t>(j)],
                                       q[static_cast<std::size_t>(j) + 1], "",
                                       {Role::Entering, 1.5f, true}, false});
        curve3(scene, q, {Role::Entering, 3.0f});
        if (s.phase == Phase::Derivatives) triangle3(scene, triangle(q, in.t), true, "Q");
    }
    if (s.phase == Phase::Column || s.phase == Phase::Point) return;

    // The point, then the tangents (drawn 1/m and 1/n long: the last segments of the
    // constructions), then the normal.
    const std::string at = "P(" + num(in.s, 4) + ", " + num(in.t, 4) + ")";
    if (s.phase != Phase::Derivatives) {
        // A zero derivative (a collapsed row or column) is named instead of drawn.
        auto arrow = [&](glm::dvec3 d, int degree, const std::string& what, Role role) {
            if (d == glm::dvec3(0)) {
                scene.labels3.push_back({s.point, what + " = 0", {role}});
                return;
            }
            Segment3 tangent{s.point, s.point + d / static_cast<double>(degree),
                             what + " / " + std::to_string(degree), {role, 3.0f}, true};
            tangent.min_pixels = 30;
            scene.segments3.push_back(tangent);
        };
        arrow(s.ds, s.m, "∂P/∂s", Role::Active);
        arrow(s.dt, s.n, "∂P/∂t", Role::Leaving);
    }
    if (s.phase == Phase::Tessellate || finished) {
        if (s.normal_defined)
            scene.segments3.push_back({s.point, s.point + 0.25 * size * s.normal, "N",
                                       {Role::Window, 3.0f}, true, 30, 1});
        else
            scene.labels3.push_back({s.point, "normal undefined here", {Role::Discarded}});
    }
    scene.points3.push_back({s.point, at, {Role::Kept}, 6.5f, 1});
}

}  // namespace cg
