// Inverse kinematics, the picture. The chain (links grey, joints dots, the base blue), the target
// (teal, draggable in 2D; red when out of reach) and the circle of full reach (dashed, with the
// inner radius when there is one). Forward kinematics draws the links placed so far. The two-link
// arm shows both poses once they are known, the one taken solid. CCD shows the joint being turned
// (orange) with u = joint→end and v = joint→target; the Jacobian methods show e = end→target and
// the columns J_i drawn from the end effector (where joint i alone would move it, per radian,
// scaled together). Iterative methods chart |e| against the update number on a log axis beside
// the chain, with the tolerance. A 3D chain is framed with its target.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "animation/inverse_kinematics.hpp"
#include "core/format.hpp"

namespace cg {

namespace {

using IK = InverseKinematics;
constexpr std::size_t kMaxPlotPoints = 400;
constexpr std::size_t kMaxJointLabels = 8;

glm::dvec2 xy(glm::dvec3 p) {
    return {p.x, p.y};
}

void circle(Scene& scene, glm::dvec2 c, double r, Role role) {
    Polygon2 poly{{}, {role, 1.0f, true}, true, false};
    for (int i = 0; i < 96; ++i) {
        const double a = 2 * std::numbers::pi * i / 96;
        poly.points.push_back(c + r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    scene.polygons.push_back(std::move(poly));
}

// |e| against the update number, in a chart with a logarithmic |e| axis (whole decades from
// below the tolerance to above the start), the tolerance dashed green.
void error_chart(const IK::State& s, Scene& scene) {
    const IK::Input& in = *s.in;
    const bool ccd = in.method == IK::Method::CCD;
    const double floor_e = 1e-16 * std::max(1.0, s.size);
    auto lg = [&](double e) { return std::log10(std::max(e, floor_e)); };
    double lo = lg(in.tolerance), hi = lo;
    for (double e : s.history) lo = std::min(lo, lg(e)), hi = std::max(hi, lg(e));
    // The updates so far (the run stops at the tolerance, usually long before its budget).
    const std::size_t done = s.history.size() - 1;
    const double span = std::max(1.0, double(done));
    Panel& chart = add_chart(
        scene,
        "|e| = " + num(std::max(s.history.back(), floor_e), 3) + (ccd ? ", update " : ", iteration ") +
            std::to_string(done),
        Axis{ccd ? "joint updates" : "iterations", 0, span},
        Axis{"|e| (log)", std::pow(10.0, std::floor(lo - 0.25)), std::pow(10.0, std::ceil(hi + 0.25)),
             true});
    std::vector<glm::dvec2> line;
    const std::size_t stride = (s.history.size() + kMaxPlotPoints - 1) / kMaxPlotPoints;
    auto point = [&](std::size_t q) {
        return glm::dvec2(double(q), std::max(s.history[q], floor_e));
    };
    for (std::size_t q = 0; q < s.history.size(); q += stride) line.push_back(point(q));
    if ((s.history.size() - 1) % stride != 0) line.push_back(point(s.history.size() - 1));
    add_line(chart, {{0, in.tolerance}, {span, in.tolerance}}, {Role::Kept, 1.0f, true},
             "tolerance " + num(in.tolerance, 3));
    add_line(chart, std::move(line), {Role::Active, 2.0f}, "|e|, end to target");
    chart.points.push_back({point(done), "", {Role::Active}, 4.5f});
}

}  // namespace

void IK::draw(const State& s, Scene& scene) {
    const Input& in = *s.in;
    const std::size_t n = in.lengths.size();
    double reach = 0;
    for (double l : in.lengths) reach += l;
    const double longest = *std::max_element(in.lengths.begin(), in.lengths.end());
    const bool iterative = in.method == Method::CCD || in.method == Method::JacobianTranspose ||
                           in.method == Method::DLS;
    const bool ok = reachable(in);
    const std::size_t shown =
        in.method == Method::Forward && s.phase != Phase::Done && s.phase != Phase::Summary
            ? std::size_t(s.links_done)
            : n;
    const bool labels = n <= kMaxJointLabels;
    const bool ccd_now = s.last == Phase::Update && in.method == Method::CCD && s.k > 0;
    const bool jac_now = s.last == Phase::Update && in.method != Method::CCD && s.k > 0;

    if (s.planar) {
        const glm::dvec2 base = xy(in.base);
        circle(scene, base, reach, Role::Construction);
        const double inner = 2 * longest - reach;
        if (inner > 0) circle(scene, base, inner, Role::Construction);
        // Analytic: the other pose, dashed, once both are known.
        if (in.method == Method::Analytic && s.two_link.reachable &&
            (s.phase == Phase::Summary || s.phase == Phase::Done)) {
            const double* other = in.elbow_up ? s.two_link.down : s.two_link.up;
            std::vector<double> th = {other[0] * std::numbers::pi / 180,
                                      other[1] * std::numbers::pi / 180};
            std::vector<glm::dvec3> q;
            forward(in, th, q);
            for (std::size_t i = 1; i < q.size(); ++i)
                scene.segments.push_back({xy(q[i - 1]),
                                          xy(q[i]),
                                          i == 1 ? (in.elbow_up ? "elbow down" : "elbow up") : "",
                                          {Role::Construction, 2.0f, true},
                                          false});
        }
        for (std::size_t i = 1; i <= n; ++i) {
            if (i > shown) {
                scene.segments.push_back(
                    {xy(s.p[i - 1]), xy(s.p[i]), "", {Role::Construction, 1.0f, true}, false});
                continue;
            }
            scene.segments.push_back(
                {xy(s.p[i - 1]), xy(s.p[i]), "", {Role::Subject, 3.0f}, false});
        }
        for (std::size_t i = 0; i <= shown; ++i) {
            const bool active = ccd_now && int(i) == s.joint;
            const Role role = i == 0 ? Role::Window : active ? Role::Active : Role::Neutral;
            std::string label = labels ? "p" + std::to_string(i) : "";
            if (i == n) label = "end";
            scene.points.push_back({xy(s.p[i]), label, {role}, active ? 7.0f : 5.0f});
        }
        if (in.has_target) {
            const glm::dvec2 t = xy(in.target);
            scene.points.push_back({t,
                                    ok ? "target" : "target (out of reach)",
                                    {ok ? Role::Entering : Role::Discarded},
                                    7.0f});
            scene.handles.push_back({t, "target", "/target/0", "/target/1"});
        }
        if (ccd_now) {
            const glm::dvec2 pj = xy(s.p[std::size_t(s.joint)]);
            // u and v as they were before the turn: the end has moved since.
            scene.segments.push_back({pj, pj + xy(s.u), "u", {Role::Leaving, 2.0f}, true});
            scene.segments.push_back({pj, pj + xy(s.v), "v", {Role::Entering, 2.0f}, true});
        }
        if (jac_now) {
            const glm::dvec2 end = xy(s.p[n]);
            double biggest = 0;
            for (const glm::dvec3& c : s.J) biggest = std::max(biggest, glm::length(c));
            const double scale = biggest > 0 ? 0.35 * reach / biggest : 0;
            for (std::size_t i = 0; i < n && i < 12; ++i)
                if (glm::length(s.J[i]) > 0)
                    scene.segments.push_back({end,
                                              end + scale * xy(s.J[i]),
                                              labels ? "J" + std::to_string(i + 1) : "",
                                              {Role::Construction, 1.5f},
                                              true});
            scene.segments.push_back({end, xy(in.target), "e", {Role::Leaving, 2.0f, true}, true});
        }
        if (iterative) error_chart(s, scene);
        return;
    }

    // 3D: the chain on the 3D canvas, the plot on the 2D pane.
    scene.extent3 = glm::length(in.base) + 1.1 * reach;
    for (std::size_t i = 1; i <= n; ++i)
        scene.segments3.push_back(
            {s.p[i - 1],
             s.p[i],
             "",
             {i > shown ? Role::Construction : Role::Subject, i > shown ? 1.0f : 3.0f, i > shown},
             false});
    for (std::size_t i = 0; i <= shown; ++i) {
        const bool active = ccd_now && int(i) == s.joint;
        const Role role = i == 0 ? Role::Window : active ? Role::Active : Role::Neutral;
        scene.points3.push_back({s.p[i],
                                 i == n ? "end" : (labels ? "p" + std::to_string(i) : ""),
                                 {role},
                                 active ? 7.0f : 5.0f});
    }
    // Each joint's hinge axis, short and dashed.
    for (std::size_t i = 0; i < shown && i < s.axes.size(); ++i)
        scene.segments3.push_back({s.p[i] - 0.12 * reach * s.axes[i],
                                   s.p[i] + 0.12 * reach * s.axes[i],
                                   "",
                                   {Role::Window, 1.0f, true},
                                   false});
    if (in.has_target)
        scene.points3.push_back({in.target,
                                 ok ? "target" : "target (out of reach)",
                                 {ok ? Role::Entering : Role::Discarded},
                                 7.0f});
    if (ccd_now) {
        const glm::dvec3 pj = s.p[std::size_t(s.joint)];
        scene.segments3.push_back({pj, pj + s.u, "u", {Role::Leaving, 2.0f}, true});
        scene.segments3.push_back({pj, pj + s.v, "v", {Role::Entering, 2.0f}, true});
    }
    if (jac_now) {
        double biggest = 0;
        for (const glm::dvec3& c : s.J) biggest = std::max(biggest, glm::length(c));
        const double scale = biggest > 0 ? 0.35 * reach / biggest : 0;
        for (std::size_t i = 0; i < n && i < 12; ++i)
            if (glm::length(s.J[i]) > 0)
                scene.segments3.push_back({s.p[n],
                                           s.p[n] + scale * s.J[i],
                                           labels ? "J" + std::to_string(i + 1) : "",
                                           {Role::Construction, 1.5f},
                                           true});
        scene.segments3.push_back({s.p[n], in.target, "e", {Role::Leaving, 2.0f, true}, true});
    }
    if (iterative) error_chart(s, scene);
    // The camera frames the chain as it is now and the target.
    glm::dvec3 lo = s.p[0], hi = lo;
    for (const glm::dvec3& p : s.p) lo = glm::min(lo, p), hi = glm::max(hi, p);
    if (in.has_target) lo = glm::min(lo, in.target), hi = glm::max(hi, in.target);
    add_focus(scene, lo, hi);
}

}  // namespace cg
