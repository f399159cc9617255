// Inverse kinematics: forward kinematics by hand; the two-link arm against the law of cosines
// worked independently in long double on seeded random arms (both elbows, full reach, folded,
// on the base, unreachable beyond and inside with the nearest pose); every solver's pose checked
// by an independent long-double forward kinematics reaching the target to 1e-9 on seeded random
// planar and 3D chains with reachable targets (and at exactly full reach); the Jacobian's columns
// against central differences in long double; damped least squares against (JᵀJ + λ²I)⁻¹Jᵀe
// solved independently; the transpose step's α; CCD's error never growing (per update and per
// sweep); the state machine equals compute, through the registry too; replay on the presets;
// bad input names the field; the exam problems against hand computations; the narration of the
// exam-style arm; the picture.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "animation/inverse_kinematics.hpp"
#include "core/rng.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::InverseKinematics;
using IK = InverseKinematics;
using Input = IK::Input;
using Method = IK::Method;
using LD = long double;

namespace {

const LD kPiL = 3.141592653589793238462643383279502884L;

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("inverse-kinematics");
    if (!l) throw std::runtime_error("no lesson for inverse-kinematics");
    return *l;
}

// ---- the reference: forward kinematics in long double, written separately ----

struct V {
    LD x = 0, y = 0, z = 0;
};
V operator+(V a, V b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
V operator-(V a, V b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V operator*(LD s, V a) {
    return {s * a.x, s * a.y, s * a.z};
}
LD dot(V a, V b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
V cross(V a, V b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
LD norm(V a) {
    return std::sqrt(dot(a, a));
}
V from(glm::dvec3 p) {
    return {p.x, p.y, p.z};
}

// A frame as three column vectors; rotating a vector v about unit a by θ (Rodrigues on vectors).
V rotate(V v, V a, LD th) {
    return std::cos(th) * v + std::sin(th) * cross(a, v) + ((1 - std::cos(th)) * dot(a, v)) * a;
}

// p_0..p_n for angles in degrees; the axes given in the parent's frame, each column of the
// frame turned about the local axis expressed in the world.
std::vector<V> fk(const Input& in, const std::vector<LD>& deg) {
    const std::size_t n = in.lengths.size();
    V X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};  // the frame's columns
    std::vector<V> p{from(in.base)};
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 a0 = in.axes.empty() ? glm::dvec3(0, 0, 1) : in.axes[i];
        V a = from(a0);
        a = (1 / norm(a)) * a;
        const V aw = a.x * X + a.y * Y + a.z * Z;  // the axis in the world
        const LD th = deg[i] * kPiL / 180;
        X = rotate(X, aw, th);
        Y = rotate(Y, aw, th);
        Z = rotate(Z, aw, th);
        p.push_back(p.back() + LD(in.lengths[i]) * X);
    }
    return p;
}
std::vector<V> fk(const Input& in, const std::vector<double>& deg) {
    return fk(in, std::vector<LD>(deg.begin(), deg.end()));
}

// A random chain: planar (axes z) or 3D (random axes), lengths 0.1 to 2, and a reachable target
// made by forward kinematics of random angles.
Input random_chain(cg::Rng& rng, bool planar, Method m) {
    Input in;
    const int n = int(rng.integer(2, 7));
    for (int i = 0; i < n; ++i) {
        in.lengths.push_back(rng.uniform(0.1, 2));
        in.angles.push_back(rng.uniform(-180, 180));
        if (!planar) {
            glm::dvec3 a;
            do a = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
            while (glm::length(a) < 0.2);
            in.axes.push_back(a);
        }
    }
    if (rng.chance(0.3)) in.base = {rng.uniform(-3, 3), rng.uniform(-3, 3), planar ? 0 : 1.0};
    std::vector<double> goal;
    for (int i = 0; i < n; ++i) goal.push_back(rng.uniform(-180, 180));
    const auto q = fk(in, goal);
    in.target = {double(q.back().x), double(q.back().y), planar ? in.base.z : double(q.back().z)};
    in.has_target = true;
    in.method = m;
    in.iterations = m == Method::CCD ? 2000 : 3000;
    in.damping = 0.05;
    return in;
}

std::string err(const std::string& text) {
    return cg::test::error_of("inverse-kinematics", text);
}

}  // namespace

TEST_CASE("inverse-kinematics: forward kinematics by hand, planar and 3D",
          "[animation][inverse-kinematics]") {
    Input in;
    in.lengths = {2, 1};
    in.angles = {90, -90};
    in.method = Method::Forward;
    const auto r = IK::compute(in);
    REQUIRE(r.positions.size() == 3);
    CHECK(r.positions[1].x == Approx(0).margin(1e-15));
    CHECK(r.positions[1].y == Approx(2));
    CHECK(r.positions[2].x == Approx(1));
    CHECK(r.positions[2].y == Approx(2));
    CHECK(r.stop == "forward");
    // 3D: a hinge about y turns the first link into −z (right-handed: x → −z by +90° about y).
    in.axes = {{0, 1, 0}, {0, 0, 1}};
    in.angles = {90, 90};
    const auto r3 = IK::compute(in);
    CHECK(r3.positions[1].z == Approx(-2));
    CHECK(r3.positions[1].x == Approx(0).margin(1e-15));
    // The second hinge's axis z is in the first link's frame: after the turn about y, local z
    // is world x, and local x (the link) turned by 90° about it becomes world y.
    CHECK(r3.positions[2].x == Approx(0).margin(1e-15));
    CHECK(r3.positions[2].y == Approx(1));
    CHECK(r3.positions[2].z == Approx(-2));
    CHECK_FALSE(r3.planar);
    // The state machine takes one link a step.
    const auto t = cg::test::run_traced<IK>(in);
    CHECK(cg::test::events(t) == std::vector<std::string>{"link", "link", "summary"});
    CHECK(t.result == r3);
}

TEST_CASE("inverse-kinematics: the exam-style two-link arm by the law of cosines",
          "[animation][inverse-kinematics]") {
    Input in;
    in.lengths = {2, 1};
    in.target = {2, 1, 0};
    in.has_target = true;
    in.method = Method::Analytic;
    // d² = 5, cos θ_2 = (5 − 4 − 1)/4 = 0: θ_2 = ∓90°; θ_1 = atan2(1, 2) ± atan2(1, 2).
    const auto t = cg::test::run_traced<IK>(in);
    CHECK(cg::test::events(t) ==
          std::vector<std::string>{"distance", "elbow", "shoulder", "summary"});
    const double a = std::atan2(1.0, 2.0) * 180 / std::numbers::pi;
    CHECK(t.result.two_link.up[0] == Approx(2 * a));
    CHECK(t.result.two_link.up[1] == Approx(-90));
    CHECK(t.result.two_link.down[0] == Approx(0).margin(1e-12));
    CHECK(t.result.two_link.down[1] == Approx(90));
    CHECK(t.result.error < 1e-15);
    CHECK(t.steps[1].narration.find("(5 − 4 − 1) / 4 = 0, so θ_2 = ±90°") != std::string::npos);
    CHECK(t.steps[2].narration.find("θ_1 = 26.5651° + 26.5651° = 53.1301°") != std::string::npos);
}

TEST_CASE("inverse-kinematics: 4,000 two-link arms against the law of cosines in long double",
          "[animation][inverse-kinematics]") {
    cg::Rng rng(324);
    int kinds[6] = {};  // general, full reach, folded inner, on the base, beyond, inside
    for (int trial = 0; trial < 4000; ++trial) {
        Input in;
        const double l1 = rng.uniform(0.1, 3);
        double l2 = rng.uniform(0.1, 3);
        const int kind = int(rng.integer(0, 5));
        if (kind == 3) l2 = l1;
        in.lengths = {l1, l2};
        const double phi = rng.uniform(-std::numbers::pi, std::numbers::pi);
        double d = 0;
        switch (kind) {
            case 0:
                d = rng.uniform(std::fabs(l1 - l2), l1 + l2);
                break;
            case 1:
                d = l1 + l2;
                break;
            case 2:
                d = std::fabs(l1 - l2);
                break;
            case 3:
                d = 0;
                break;
            case 4:
                d = rng.uniform(1.01, 3) * (l1 + l2);
                break;
            case 5:
                d = rng.uniform(0, 0.99) * std::fabs(l1 - l2);
                break;
        }
        in.target = {d * std::cos(phi), d * std::sin(phi), 0};
        in.has_target = true;
        in.method = Method::Analytic;
        in.elbow_up = rng.chance(0.5);
        CAPTURE(trial, kind, l1, l2, in.target.x, in.target.y);
        const auto r = IK::compute(in);
        ++kinds[kind];
        // The reference, from the target's coordinates as stored.
        const LD tx = in.target.x, ty = in.target.y;
        const LD D = std::sqrt(tx * tx + ty * ty);
        const LD L1 = l1, L2 = l2;
        const LD c = (D * D - L1 * L1 - L2 * L2) / (2 * L1 * L2);
        for (int elbow = 0; elbow < 2; ++elbow) {
            const double* got = elbow == 0 ? r.two_link.up : r.two_link.down;
            const std::vector<V> p = fk(in, std::vector<double>{got[0], got[1]});
            const LD miss = norm(p.back() - V{tx, ty, 0});
            if (kind <= 3) {
                CHECK(r.two_link.reachable);
                CHECK(double(miss) <= 1e-9 * std::max(1.0, l1 + l2));
                if (kind == 0 && std::fabs(double(c)) < 0.999) {
                    // θ_2 = ∓acos(c), θ_1 = atan2(t) − atan2(l2 sin θ2, l1 + l2 cos θ2).
                    const LD th2 = (elbow == 0 ? -1 : 1) * std::acos(c);
                    LD th1 = std::atan2(ty, tx) -
                             std::atan2(L2 * std::sin(th2), L1 + L2 * std::cos(th2));
                    th1 = std::remainder(th1, 2 * kPiL);
                    CHECK(std::fabs(double(th2 * 180 / kPiL) - got[1]) < 1e-9);
                    CHECK(std::fabs(std::remainder(double(th1 * 180 / kPiL) - got[0], 360.0)) <
                          1e-9);
                }
            } else {
                CHECK_FALSE(r.two_link.reachable);
                // The nearest reachable pose: |miss| = d − (l1 + l2) or |l1 − l2| − d.
                const LD want = kind == 4 ? D - (L1 + L2) : std::fabs(L1 - L2) - D;
                CHECK(std::fabs(double(miss - want)) <= 1e-12 * std::max(1.0, l1 + l2));
            }
            CHECK((elbow == 0 ? got[1] <= 0 || got[1] == 180 : got[1] >= 0));
        }
        CHECK(r.reachable == (kind <= 3));
        CHECK(std::fabs(r.error - double(norm(fk(in, r.angles).back() - V{tx, ty, 0}))) < 1e-12);
    }
    for (int k : kinds) CHECK(k > 500);
}

TEST_CASE("inverse-kinematics: every solver's pose reaches a reachable target to 1e-9",
          "[animation][inverse-kinematics]") {
    // Each solver on seeded random chains whose target is the end of the same chain at other
    // angles. The pose reported is checked by the independent forward kinematics; "reached"
    // must mean |FK(θ) − target| ≤ 1e-9 (to rounding), and most runs must reach.
    struct Case {
        Method m;
        bool planar;
        int trials;
        double min_reached;  // fraction
    };
    const Case cases[] = {{Method::CCD, true, 1500, 0.97},
                          {Method::CCD, false, 1000, 0.85},
                          {Method::DLS, true, 1500, 0.97},
                          {Method::DLS, false, 1000, 0.9},
                          {Method::JacobianTranspose, true, 500, 0.5}};
    for (const Case& c : cases) {
        cg::Rng rng(1000 + int(c.m) * 10 + c.planar);
        int reached = 0;
        for (int trial = 0; trial < c.trials; ++trial) {
            const Input in = random_chain(rng, c.planar, c.m);
            CAPTURE(IK::method_name(c.m), c.planar, trial);
            const auto r = IK::compute(in);
            const std::vector<V> p = fk(in, r.angles);
            for (std::size_t i = 0; i < p.size(); ++i)
                CHECK(double(norm(p[i] - from(r.positions[i]))) < 1e-12 * 20);
            const double miss = double(norm(p.back() - from(in.target)));
            CHECK(std::fabs(miss - r.error) < 1e-12 * 20);
            if (r.reached) CHECK(miss <= 1e-9 + 1e-12 * 20);
            CHECK(r.reachable);
            reached += r.reached;
        }
        WARN(IK::method_name(c.m) << (c.planar ? " planar" : " 3D") << ": " << reached << " of "
                                  << c.trials);
        CHECK(reached >= c.min_reached * c.trials);
    }
}

TEST_CASE("inverse-kinematics: targets at exactly full reach and on the base",
          "[animation][inverse-kinematics]") {
    cg::Rng rng(77);
    int reached[3] = {};
    const int trials = 300;
    for (int trial = 0; trial < trials; ++trial) {
        Input in;
        const int n = int(rng.integer(2, 5));
        double sum = 0;
        for (int i = 0; i < n; ++i) {
            in.lengths.push_back(double(rng.integer(1, 4)) / 2);  // exact sums
            in.angles.push_back(rng.uniform(-60, 60));
            sum += in.lengths.back();
        }
        const double phi = rng.uniform(-3, 3);
        in.target = {sum * std::cos(phi), sum * std::sin(phi), 0};
        in.has_target = true;
        in.tolerance = 1e-9;
        for (Method m : {Method::CCD, Method::DLS, Method::JacobianTranspose}) {
            in.method = m;
            in.iterations = m == Method::CCD ? 5000 : 10000;
            in.damping = 0.01;
            CAPTURE(trial, IK::method_name(m));
            const auto r = IK::compute(in);
            const double miss = double(norm(fk(in, r.angles).back() - from(in.target)));
            CHECK(std::fabs(miss - r.error) < 1e-12);
            CHECK(std::isfinite(r.error));
            if (m == Method::CCD) CHECK(r.error < 1e-2 * sum);  // it never grows, and creeps on
            CHECK(r.error <= 2 * sum);
            reached[int(m) - 2] += r.error <= 1e-6 * sum;
        }
    }
    // At exactly full reach the pose is the straight arm, a singularity: the error along the arm
    // shrinks only at second order, so every iterative solver creeps (the law of cosines, tested
    // above, is exact there). DLS with a tiny λ can also jump to the straight arm pointing away,
    // where J ⟂ e and no step helps: it stalls.
    WARN("full reach, within 1e-6 of the size: CCD " << reached[0] << ", transpose " << reached[1]
                                                     << ", DLS " << reached[2] << " of " << trials);
    // A target on the base: an arm of two equal links folds onto it; CCD gets there too.
    Input fold;
    fold.lengths = {1, 1};
    fold.angles = {10, 20};
    fold.target = {0, 0, 0};
    fold.has_target = true;
    fold.method = Method::Analytic;
    const auto ra = IK::compute(fold);
    CHECK(ra.reachable);
    CHECK(ra.error < 1e-15);
    CHECK(ra.angles[1] == 180);
    fold.method = Method::CCD;
    const auto rc = IK::compute(fold);
    CHECK(rc.reached);
    // Unequal links cannot reach their base: the folded pose, |l1 − l2| away.
    fold.lengths = {2, 1};
    fold.method = Method::Analytic;
    const auto ru = IK::compute(fold);
    CHECK_FALSE(ru.reachable);
    CHECK(ru.error == Approx(1));
    fold.method = Method::CCD;
    const auto rcu = IK::compute(fold);
    CHECK_FALSE(rcu.reached);
    CHECK(rcu.error == Approx(1).epsilon(1e-6));
}

TEST_CASE("inverse-kinematics: the Jacobian's columns against central differences",
          "[animation][inverse-kinematics]") {
    cg::Rng rng(5);
    for (int trial = 0; trial < 1000; ++trial) {
        Input in = random_chain(rng, rng.chance(0.3), Method::DLS);
        CAPTURE(trial);
        const Input res = IK::resolve(in);
        std::vector<double> theta;
        for (double a : res.angles) theta.push_back(a * std::numbers::pi / 180);
        std::vector<glm::dvec3> p, w, J;
        IK::forward(res, theta, p, &w);
        IK::jacobian(w, p, J);
        const std::size_t n = theta.size();
        for (std::size_t i = 0; i < n; ++i) {
            const LD h = 1e-6L;  // degrees here: the reference works in degrees
            std::vector<LD> a(res.angles.begin(), res.angles.end()), b = a;
            a[i] += h;
            b[i] -= h;
            const V d = (1 / (2 * h * kPiL / 180)) * (fk(in, a).back() - fk(in, b).back());
            const V got = from(J[i]);
            CHECK(double(norm(d - got)) <= 1e-8 * std::max<double>(1, double(norm(d))));
        }
    }
}

TEST_CASE("inverse-kinematics: damped least squares is (JᵀJ + λ²I)⁻¹Jᵀe, transpose's α",
          "[animation][inverse-kinematics]") {
    cg::Rng rng(9);
    for (int trial = 0; trial < 2000; ++trial) {
        const int n = int(rng.integer(1, 8));
        std::vector<glm::dvec3> J(static_cast<std::size_t>(n));
        for (auto& c : J) c = {rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
        if (rng.chance(0.3))
            for (auto& c : J) c.z = 0;               // planar: JJᵀ singular without the damping
        if (n >= 2 && rng.chance(0.2)) J[1] = J[0];  // two equal columns
        const glm::dvec3 e{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        const double lambda = rng.chance(0.5) ? rng.uniform(0.01, 1) : rng.uniform(1, 5);
        CAPTURE(trial, n, lambda);
        std::vector<double> got;
        IK::dls_step(J, e, lambda, got);
        // The n × n system (JᵀJ + λ²I) x = Jᵀe by Gaussian elimination with partial pivoting.
        std::vector<std::vector<LD>> A(std::size_t(n), std::vector<LD>(std::size_t(n) + 1));
        for (int r = 0; r < n; ++r) {
            for (int c = 0; c < n; ++c)
                A[r][c] = dot(from(J[r]), from(J[c])) + (r == c ? LD(lambda) * LD(lambda) : 0);
            A[r][n] = dot(from(J[r]), from(e));
        }
        for (int c = 0; c < n; ++c) {
            int best = c;
            for (int r = c + 1; r < n; ++r)
                if (std::fabs(A[r][c]) > std::fabs(A[best][c])) best = r;
            std::swap(A[c], A[best]);
            for (int r = 0; r < n; ++r) {
                if (r == c) continue;
                const LD f = A[r][c] / A[c][c];
                for (int k = c; k <= n; ++k) A[r][k] -= f * A[c][k];
            }
        }
        LD scale = 0;
        for (int c = 0; c < n; ++c) scale = std::max(scale, std::fabs(A[c][n] / A[c][c]));
        for (int c = 0; c < n; ++c)
            CHECK(std::fabs(double(A[c][n] / A[c][c]) - got[c]) <=
                  1e-9 * std::max<double>(1, double(scale)));
        // Transpose: Δθ = α Jᵀe with α = |Jᵀe|² / |JJᵀe|².
        std::vector<double> dt;
        const double alpha = IK::transpose_step(J, e, dt);
        LD g2 = 0;
        V jjte{};
        for (int i = 0; i < n; ++i) {
            const LD g = dot(from(J[i]), from(e));
            g2 += g * g;
            jjte = jjte + g * from(J[i]);
        }
        const LD a_ref = g2 / dot(jjte, jjte);
        CHECK(alpha == Approx(double(a_ref)).epsilon(1e-10));
        for (int i = 0; i < n; ++i)
            CHECK(dt[i] ==
                  Approx(double(a_ref * dot(from(J[i]), from(e)))).epsilon(1e-9).margin(1e-12));
    }
}

TEST_CASE("inverse-kinematics: CCD's error never grows, per update and per sweep",
          "[animation][inverse-kinematics]") {
    cg::Rng rng(11);
    for (int trial = 0; trial < 1000; ++trial) {
        Input in = random_chain(rng, rng.chance(0.5), Method::CCD);
        in.iterations = 30;
        if (rng.chance(0.2)) in.target *= 3;  // out of reach
        CAPTURE(trial);
        const auto r = IK::compute(in);
        const std::size_t n = in.lengths.size();
        const double slack = 1e-12 * 20;
        for (std::size_t k = 1; k < r.errors.size(); ++k)
            CHECK(r.errors[k] <= r.errors[k - 1] + slack);
        for (std::size_t k = n; k < r.errors.size(); k += n)
            CHECK(r.errors[k] <= r.errors[k - n] + slack);
        CHECK(r.updates + 1 == int(r.errors.size()));
    }
}

TEST_CASE("inverse-kinematics: the state machine gives what compute gives, through the registry",
          "[animation][inverse-kinematics]") {
    cg::Rng rng(17);
    for (int trial = 0; trial < 300; ++trial) {
        CAPTURE(trial);
        Input in = random_chain(rng, rng.chance(0.5), Method(rng.integer(2, 4)));
        in.iterations = 40;
        const auto traced = cg::test::run_traced<IK>(in);
        CHECK(traced.result == IK::compute(in));
        CHECK(cg::run_to_end<IK>(IK::start(in)) == IK::compute(in));
        CHECK(traced.steps.size() == std::size_t(traced.result.updates) + 1);
        CHECK(traced.steps.back().event == "summary");
    }
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        const auto j = cg::test::result_of("inverse-kinematics", p.input);
        const Input in = cg::test::input_of<IK>("inverse-kinematics", p.input);
        CHECK(cg::test::algorithm("inverse-kinematics").plain(p.input) == j);
        CHECK(j["errors"].size() ==
              j["updates"].get<std::size_t>() + (j["errors"].empty() ? 0 : 1));
        (void)in;
    }
}

TEST_CASE("inverse-kinematics: the lesson's presets show what they say",
          "[animation][inverse-kinematics]") {
    const auto& ps = lesson().presets;
    REQUIRE(ps.size() >= 5);
    auto res = [&](std::size_t i) {
        return cg::test::result_of("inverse-kinematics", ps[i].input);
    };
    CHECK(res(0)["reached"].get<bool>());
    CHECK_FALSE(res(1)["reachable"].get<bool>());
    const auto jt = res(4), dls = res(5);
    CHECK(dls["reached"].get<bool>());
    CHECK(dls["iterations"].get<int>() < jt["iterations"].get<int>());
    CHECK_FALSE(res(6)["planar"].get<bool>());
    CHECK(res(6)["reached"].get<bool>());
    CHECK(res(7)["reached"].get<bool>());
    CHECK(res(3)["reached"].get<bool>());
}

TEST_CASE("inverse-kinematics: bad input names the field and the reason",
          "[animation][inverse-kinematics]") {
    CHECK(err(R"({})").find("lengths: is missing") == 0);
    CHECK(err(R"({"lengths": [], "target": [1, 0]})") ==
          "lengths: must have at least 1 link (got none)");
    CHECK(err(R"({"lengths": [1, 0, 1], "target": [1, 0]})")
              .find("lengths[1]: must be > 0 (a link of zero length has no direction)") == 0);
    CHECK(err(R"({"lengths": [1, -1], "target": [1, 0]})").find("lengths[1]: must be > 0") == 0);
    CHECK(err(R"({"lengths": [1, 1]})").find("target: is missing") == 0);
    CHECK(err(R"({"lengths": [1, 1], "method": "forward"})") == "(accepted)");
    CHECK(err(R"({"lengths": [1, 1], "target": [1, 0], "angles": [0]})")
              .find("angles: must give one angle per link: 2 (got 1)") == 0);
    CHECK(err(R"({"lengths": [1, 1], "target": [1, 0], "axes": [[0, 0, 1], [0, 0, 0]]})")
              .find("axes[1]: must not be zero") == 0);
    CHECK(err(R"({"lengths": [1, 1, 1], "target": [1, 0], "method": "analytic"})")
              .find("lengths: analytic solves a two-link arm") == 0);
    CHECK(err(R"({"lengths": [1, 1], "target": [1, 0, 1], "method": "analytic"})")
              .find("target: analytic is the planar arm") == 0);
    CHECK(err(R"({"lengths": [1, 1], "target": [1, 0], "axes": [[0, 1, 0], [0, 0, 1]],
                  "method": "analytic"})")
              .find("axes[0]: analytic is the planar arm") == 0);
    CHECK(err(R"({"lengths": [1, 1], "target": [1, 0], "method": "dls", "damping": 0})")
              .find("damping: must be λ > 0") == 0);
    CHECK(err(R"({"lengths": [1, 1], "target": [1, 0], "tolerance": 0})")
              .find("tolerance: must be > 0") == 0);
    CHECK(err(R"({"lengths": [1, 1], "target": [1, 0], "iterations": 0})")
              .find("iterations: must be 1 to 10000") == 0);
    CHECK(err(R"({"lengths": [1, 1], "target": [1, 0], "method": "fabrik"})")
              .find("method: must be") == 0);
    CHECK(err(R"({"lengths": [1, 1], "target": [1e7, 0]})").find("target: is too large") == 0);
    CHECK(err(R"({"lengths": [1, 1], "target": [1, 0], "elbow": "left"})")
              .find("elbow: must be \"up\" or \"down\"") == 0);
    CHECK(err(R"({"lengths": [1, 1], "target": [1, 0], "angles": [1e7, 0]})")
              .find("angles[0]: must be a finite angle") == 0);
    std::string many = R"({"lengths": [)";
    for (int i = 0; i < 33; ++i) many += std::string(i ? ", " : "") + "1";
    CHECK(err(many + R"(], "target": [1, 0]})").find("lengths: has 33 entries") == 0);
    std::string thirty = R"({"lengths": [)";
    for (int i = 0; i < 30; ++i) thirty += std::string(i ? ", " : "") + "1";
    CHECK(err(thirty + R"(], "target": [1, 0], "iterations": 10000})")
              .find("iterations: 10000 sweeps of 30 joints is too many updates") == 0);
}

TEST_CASE("inverse-kinematics: replay on the example and the presets",
          "[animation][inverse-kinematics]") {
    const auto& a = cg::test::algorithm("inverse-kinematics");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        INFO(p.name);
        cg::test::check_replay(a, p.input, 2);
    }
}

TEST_CASE("inverse-kinematics: exam problems answered by hand",
          "[animation][inverse-kinematics][exam]") {
    const auto& a = cg::test::algorithm("inverse-kinematics");
    int kinds[3] = {}, unreachable = 0;
    for (std::uint64_t seed = 0; seed < 400; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        CAPTURE(seed, p.question);
        const Input in = cg::test::input_of<IK>("inverse-kinematics", p.input);
        if (in.method == Method::Analytic) {
            ++kinds[0];
            REQUIRE(p.answers == std::vector<std::string>{"elbow_up", "elbow_down"});
            const LD tx = in.target.x, ty = in.target.y, L1 = in.lengths[0], L2 = in.lengths[1];
            const LD D = std::sqrt(tx * tx + ty * ty);
            const bool ok = D <= L1 + L2 && D >= std::fabs(L1 - L2);
            unreachable += !ok;
            for (int e = 0; e < 2; ++e) {
                const auto got =
                    p.expected[e == 0 ? "elbow_up" : "elbow_down"].get<std::vector<double>>();
                const LD miss = norm(fk(in, got).back() - V{tx, ty, 0});
                if (ok)
                    CHECK(double(miss) < 1e-9);
                else
                    CHECK(double(miss) ==
                          Approx(double(D > L1 + L2 ? D - L1 - L2 : std::fabs(L1 - L2) - D)));
            }
        } else if (in.method == Method::Forward) {
            ++kinds[1];
            REQUIRE(p.answers == std::vector<std::string>{"positions"});
            const auto q = fk(in, in.angles);
            const auto& got = p.expected["positions"];
            REQUIRE(got.size() == q.size());
            for (std::size_t i = 0; i < q.size(); ++i) {
                CHECK(got[i][0].get<double>() == Approx(double(q[i].x)).margin(1e-12));
                CHECK(got[i][1].get<double>() == Approx(double(q[i].y)).margin(1e-12));
            }
        } else {
            ++kinds[2];
            REQUIRE(p.answers == std::vector<std::string>{"first_update/delta"});
            // By hand: the last joint at p_{n−1}; the angle from (end − p) to (target − p).
            const auto q = fk(in, in.angles);
            const V u = q.back() - q[q.size() - 2], v = from(in.target) - q[q.size() - 2];
            const LD want = std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y) * 180 / kPiL;
            const double got = p.expected["first_update/delta"].get<double>();
            CHECK(std::fabs(std::remainder(got - double(want), 360.0)) < 1e-9);
            CHECK((got > -180 && got <= 180));
        }
    }
    CHECK(kinds[0] > 100);
    CHECK(kinds[1] > 100);
    CHECK(kinds[2] > 40);
    CHECK(unreachable > 5);
}

TEST_CASE("inverse-kinematics: the picture shows the chain, the target and the vectors used",
          "[animation][inverse-kinematics]") {
    Input in;
    in.lengths = {1.5, 1.2, 1, 0.8};
    in.target = {1, 2.5, 0};
    in.has_target = true;
    in.method = Method::CCD;
    auto s = IK::start(in);
    IK::step(s, nullptr);
    cg::Scene scene;
    IK::draw(s, scene);
    CHECK(scene.points.size() >= 6);  // 5 joints and the target
    int arrows = 0, active = 0;
    for (const auto& seg : scene.segments)
        arrows += seg.arrow && (seg.label == "u" || seg.label == "v");
    for (const auto& pt : scene.points) active += pt.style.role == cg::Role::Active;
    CHECK(arrows == 2);
    CHECK(active == 1);
    CHECK(scene.handles.size() == 1);
    in.method = Method::DLS;
    auto d = IK::start(in);
    IK::step(d, nullptr);
    cg::Scene sd;
    IK::draw(d, sd);
    int columns = 0;
    for (const auto& seg : sd.segments) columns += seg.arrow && seg.label.rfind("J", 0) == 0;
    CHECK(columns == 4);
    // The iterative methods chart |e| on a log axis with the tolerance, beside the chain.
    REQUIRE(sd.panels.size() == 1);
    CHECK(sd.panels[0].kind == cg::PanelKind::Chart);
    CHECK(sd.panels[0].y.log);
    CHECK(sd.panels[0].y.lo <= in.tolerance);
    REQUIRE(sd.panels[0].legend.size() == 2);
    CHECK(sd.panels[0].legend[0].style.role == cg::Role::Kept);  // the tolerance
    CHECK(sd.panels[0].polygons[1].points.size() == d.history.size());
    // A 3D chain goes to the 3D canvas, framed with its target; its error chart beside it.
    const auto& p3 = lesson().presets[6];
    auto s3 = IK::start(cg::test::input_of<IK>("inverse-kinematics", p3.input));
    IK::step(s3, nullptr);
    cg::Scene c3;
    IK::draw(s3, c3);
    CHECK(c3.has_3d());
    CHECK_FALSE(c3.has_2d());
    CHECK(c3.panels.size() == 1);
    CHECK(c3.focus3.size() == 1);
}
