// The slab test: the lesson's cases worked by hand (exact numbers); 100,000 random rays —
// components 0, origins on faces and inside, corners and edges, tiny and huge coordinates —
// against an independent interval computation in long double; no NaN from the infinities;
// run-to-end equals the plain function; errors naming the field; replay; the picture.
#include <catch2/catch.hpp>
#include <cfloat>
#include <cmath>
#include <limits>

#include "accel/ray_aabb.hpp"
#include "core/format.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/registry_run.hpp"
#include "support/replay.hpp"
#include "support/traced.hpp"

using cg::RayAabb;
using glm::dvec3;
using Verdict = RayAabb::Verdict;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

RayAabb::Input ray(dvec3 min, dvec3 max, dvec3 origin, dvec3 direction) {
    return {min, max, origin, direction};
}

cg::test::Traced<RayAabb> traced(const RayAabb::Input& in) {
    return cg::test::run_traced<RayAabb>(in);
}

// ---- The reference: each slab as a long-double interval of t, intersected ----------------

using LD = long double;
constexpr LD kLInf = std::numeric_limits<LD>::infinity();

struct Interval {
    LD lo = -kLInf, hi = kLInf;  // empty when lo > hi
};

// The t for which E + t d is between the planes min and max: a zero component is in the slab
// for all t or for none (never divided), otherwise the two plane crossings in either order.
Interval slab_interval(double min, double max, double e, double d) {
    if (d == 0) {
        if (LD(min) <= LD(e) && LD(e) <= LD(max)) return {-kLInf, kLInf};
        return {kLInf, -kLInf};
    }
    const LD a = (LD(min) - LD(e)) / LD(d), b = (LD(max) - LD(e)) / LD(d);
    return {std::min(a, b), std::max(a, b)};
}

struct Reference {
    Interval axis[3];
    Interval line;                 // all three slabs
    Interval half_line{0, kLInf};  // and t ≥ 0
    int count = 3;                 // axes worked until the running interval is empty
    bool ambiguous_count = false;  // a prefix's running interval is empty only by a hair
    bool overflow = false, near_overflow = false;  // some |t| beyond the double range
};

// Whether a ≤ b could come out the other way in doubles: each t carries at most two roundings
// (≤ 2.3e-16 relative), more once it is subnormal (below 1e-305 here). Equal values are a tie
// the doubles keep only when every plane − E difference is exact in doubles too (`exact`):
// then each t is one correctly rounded quotient, and equal quotients round alike.
bool close(LD a, LD b, bool exact = false) {
    if (std::isinf(a) || std::isinf(b)) return false;
    if (a == b) return !exact;
    const LD scale = std::max(std::fabs(a), std::fabs(b));
    return std::fabs(a - b) <= 1e-13L * scale || scale < 1e-305L;
}

Reference reference(const RayAabb::Input& in) {
    Reference r;
    bool exact = true;
    for (int i = 0; i < 3; ++i)
        for (double c : {in.min[i], in.max[i]})
            exact = exact && LD(c - in.origin[i]) == LD(c) - LD(in.origin[i]);
    LD lo = -kLInf, hi = kLInf;
    bool empty = false;
    for (int i = 0; i < 3; ++i) {
        r.axis[i] = slab_interval(in.min[i], in.max[i], in.origin[i], in.direction[i]);
        for (LD t : {r.axis[i].lo, r.axis[i].hi})
            if (!std::isinf(t)) {
                r.overflow = r.overflow || std::fabs(t) > 1.0000001L * LD(DBL_MAX);
                r.near_overflow = r.near_overflow || std::fabs(t) > 0.9999999L * LD(DBL_MAX);
            }
        lo = std::max(lo, r.axis[i].lo);
        hi = std::min(hi, r.axis[i].hi);
        if (!empty && close(lo, hi, exact)) r.ambiguous_count = true;
        if (!empty && lo > hi) r.count = i + 1, empty = true;
        r.half_line.lo = std::max(r.half_line.lo, r.axis[i].lo);
        r.half_line.hi = std::min(r.half_line.hi, r.axis[i].hi);
    }
    r.line = {lo, hi};
    return r;
}

// A t of the algorithm against the reference's: the same infinity, or within 1e-15 relative
// (1e-321 absolute, for subnormal results).
bool same_t(double t, LD ref) {
    if (std::isnan(t)) return false;
    if (std::isinf(ref) || std::isinf(t)) return LD(t) == ref;
    return std::fabs(LD(t) - ref) <= 1e-15L * std::fabs(ref) + 1e-321L;
}

// ---- Random rays ------------------------------------------------------------------------------

double pick_scale(cg::Rng& rng) {
    static constexpr double kScales[] = {1e-300, 1e-150, 1e-20, 1, 1, 1, 1, 1e20, 1e150, 1e300};
    return kScales[rng.integer(0, 9)];
}

RayAabb::Input random_ray(cg::Rng& rng) {
    RayAabb::Input in;
    const bool integers = rng.chance(0.4);  // exact ties: corners, edges, equal t's
    // Integers times a power of two stay exact through every difference, so their ties are
    // true ties in doubles as in the reference; other coordinates at every decimal scale.
    static constexpr double kPowers[] = {0x1p-990, 0x1p-500, 1, 1, 0x1p500, 0x1p990};
    const double s = integers ? kPowers[rng.integer(0, 5)] : pick_scale(rng);
    auto coord = [&](double lo, double hi) {
        return integers ? s * static_cast<double>(rng.integer(static_cast<long long>(lo),
                                                              static_cast<long long>(hi)))
                        : s * rng.uniform(lo, hi);
    };
    for (int i = 0; i < 3; ++i) {
        const double a = coord(-6, 6), b = coord(-6, 6);
        in.min[i] = std::min(a, b), in.max[i] = std::max(a, b);  // sometimes flat
        in.origin[i] = coord(-12, 12);
    }
    const double ds = rng.chance(0.8) ? 1.0 : pick_scale(rng);
    for (int i = 0; i < 3; ++i) {
        in.direction[i] =
            integers ? ds * static_cast<double>(rng.integer(-3, 3)) : ds * rng.uniform(-2, 2);
        if (rng.chance(0.15)) in.direction[i] = 0;
    }
    const double what = rng.uniform(0, 1);
    if (what < 0.12) {  // the origin on a face (a component on a plane)
        const int i = static_cast<int>(rng.integer(0, 2));
        in.origin[i] = rng.chance(0.5) ? in.min[i] : in.max[i];
    } else if (what < 0.24) {  // the origin inside the box
        for (int i = 0; i < 3; ++i)
            in.origin[i] = in.min[i] + rng.uniform(0, 1) * (in.max[i] - in.min[i]);
    } else if (what < 0.30) {  // aimed at a corner
        const dvec3 c(rng.chance(0.5) ? in.min.x : in.max.x, rng.chance(0.5) ? in.min.y : in.max.y,
                      rng.chance(0.5) ? in.min.z : in.max.z);
        in.origin = c - 2.0 * in.direction;
    }
    if (in.direction == dvec3(0.0)) in.direction.x = s;
    return in;
}

std::string text(const RayAabb::Input& in) {
    return "min " + cg::num(in.min, 17) + " max " + cg::num(in.max, 17) + " E " +
           cg::num(in.origin, 17) + " d " + cg::num(in.direction, 17);
}

// Every coordinate of a scene is finite ("" if so, else what is not).
std::string scene_problem(const cg::Scene& s) {
    auto f2 = [](glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); };
    auto f3 = [](dvec3 p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    for (const auto& g : s.segments)
        if (!f2(g.a) || !f2(g.b)) return "segments";
    for (const auto& l : s.labels)
        if (!f2(l.p)) return "labels";
    for (const auto& panel : s.panels) {
        for (const auto& g : panel.segments)
            if (!f2(g.a) || !f2(g.b)) return "chart segments";
        for (const auto& l : panel.labels)
            if (!f2(l.p)) return "chart labels";
    }
    for (const auto& p : s.points3)
        if (!f3(p.p)) return "points3";
    for (const auto& g : s.segments3)
        if (!f3(g.a) || !f3(g.b)) return "segments3";
    for (const auto& f : s.faces3)
        for (auto q : f.points)
            if (!f3(q)) return "faces3";
    for (const auto& l : s.labels3)
        if (!f3(l.p)) return "labels3";
    return "";
}

const cg::Lesson& lesson() {
    static const cg::LessonLibrary lessons =
        cg::load_lessons(CG_SOURCE_DIR "/lessons", cg::test::registry());
    const cg::Lesson* l = lessons.for_algorithm("ray-aabb");
    if (!l) throw std::runtime_error("no lesson for ray-aabb");
    return *l;
}

// The typed input the JSON adapter reads.
RayAabb::Input input_of(const cg::json& j) {
    auto run = cg::test::algorithm("ray-aabb").create(j);
    return static_cast<const cg::RunOf<RayAabb>&>(*run).state.in;
}

RayAabb::Input preset(const std::string& name) {
    const cg::LessonPreset* p = lesson().preset(name);
    if (!p) throw std::runtime_error("no preset " + name);
    return input_of(p->input);
}

}  // namespace

TEST_CASE("ray-aabb: cases worked by hand", "[accel][ray-aabb]") {
    SECTION("the exam-style hit: x [1, 3], y [0, 2], z [-1, 3], in at 1, out at 2") {
        const auto t = traced(ray({0, 0, 0}, {4, 2, 2}, {-2, 0, 0.5}, {2, 1, 0.5}));
        CHECK(cg::test::events(t) == std::vector<std::string>{"slab", "slab", "slab", "hit"});
        const auto& a = t.result.axes;
        CHECK(t.result.count == 3);
        CHECK((a[0].t_near == 1 && a[0].t_far == 3));
        CHECK((a[1].t_near == 0 && a[1].t_far == 2));
        CHECK((a[2].t_near == -1 && a[2].t_far == 3));
        CHECK(t.result.t_min == 1);
        CHECK(t.result.t_max == 2);
        CHECK(t.result.hit);
        CHECK(t.result.verdict == Verdict::Hit);
        CHECK(t.result.t_hit == 1);
        CHECK_THAT(t.steps[0].narration, Catch::Contains("t_near = (0 − (−2))/2 = 1") &&
                                             Catch::Contains("t_far = (4 − (−2))/2 = 3"));
        CHECK_THAT(t.steps[1].narration, Catch::Contains("Running: t_min = 1, t_max = 2."));
        CHECK_THAT(t.steps[3].narration,
                   Catch::Contains("(0, 1, 1)") && Catch::Contains("(2, 2, 1.5)"));
    }
    SECTION("a miss: x [1, 3] and y [4, 6] (swapped) do not overlap; z is skipped") {
        const auto t = traced(ray({0, 0, 0}, {2, 2, 2}, {-1, 6, 1}, {1, -1, 0.5}));
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"slab", "slab-swapped", "miss-disjoint"});
        CHECK(t.result.count == 2);
        CHECK((t.result.axes[1].t_near == 4 && t.result.axes[1].t_far == 6));
        CHECK(t.result.t_min == 4);
        CHECK(t.result.t_max == 3);
        CHECK_FALSE(t.result.hit);
        CHECK(t.steps[1].line == 7);  // the early-out line
        CHECK_THAT(t.steps[1].narration,
                   Catch::Contains("early-out") && Catch::Contains("z slab is"));
    }
    SECTION("negative components: every axis swaps") {
        const auto t = traced(ray({0, 0, 0}, {2, 2, 2}, {5, 3, 1.5}, {-2, -1, -0.5}));
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"slab-swapped", "slab-swapped", "slab-swapped", "hit"});
        const auto& a = t.result.axes;
        CHECK((a[0].t_near == 1.5 && a[0].t_far == 2.5));
        CHECK((a[1].t_near == 1 && a[1].t_far == 3));
        CHECK((a[2].t_near == -1 && a[2].t_far == 3));
        CHECK((t.result.t_min == 1.5 && t.result.t_max == 2.5 && t.result.hit));
    }
    SECTION("a component 0 inside its slab: (−∞, +∞), t_min and t_max unchanged") {
        const auto t = traced(ray({0, 0, 0}, {2, 2, 2}, {-2, 1, 0.5}, {1, 0.25, 0}));
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"slab", "slab", "parallel-inside", "hit"});
        CHECK((t.result.axes[2].t_near == -kInf && t.result.axes[2].t_far == kInf));
        CHECK((t.result.t_min == 2 && t.result.t_max == 4 && t.result.hit));
        CHECK_THAT(t.steps[2].narration, Catch::Contains("(−∞, +∞)"));
    }
    SECTION("a component 0 outside its slab: empty (+∞, −∞), a miss at the first axis") {
        const auto t = traced(ray({0, 0, 0}, {2, 2, 2}, {3, -2, 1}, {0, 1, 0.5}));
        CHECK(cg::test::events(t) == std::vector<std::string>{"parallel-outside", "miss-disjoint"});
        CHECK(t.result.count == 1);
        CHECK((t.result.axes[0].t_near == kInf && t.result.axes[0].t_far == -kInf));
        CHECK((t.result.t_min == kInf && t.result.t_max == -kInf));
        CHECK_FALSE(t.result.hit);
        CHECK_THAT(t.steps[0].narration, Catch::Contains("y and z slabs are not needed"));
    }
    SECTION("the origin inside: t_min = -1 < 0 < t_max = 2, the hit is the exit") {
        const auto t = traced(ray({0, 0, 0}, {4, 2, 2}, {1, 1, 1}, {1, 0.5, -0.25}));
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"slab", "slab", "slab-swapped", "inside"});
        CHECK((t.result.t_min == -1 && t.result.t_max == 2 && t.result.hit));
        CHECK(t.result.verdict == Verdict::Inside);
        CHECK(t.result.t_hit == 2);
        CHECK_THAT(t.steps[3].narration,
                   Catch::Contains("inside the box") && Catch::Contains("(3, 2, 0.5)"));
    }
    SECTION("the origin on a face, going in: t_min = 0, t_hit = 0") {
        const auto t = traced(ray({0, 0, 0}, {2, 2, 2}, {0, 1, 1}, {1, 0.5, 0.25}));
        CHECK((t.result.t_min == 0 && t.result.t_max == 2));
        CHECK(t.result.verdict == Verdict::Inside);
        CHECK(t.result.t_hit == 0);
        CHECK_FALSE(std::signbit(t.result.axes[0].t_near));
    }
    SECTION("the origin on a face, going out: t_max = 0, a touch at t = 0 (−0 is not behind)") {
        const auto t = traced(ray({0, 0, 0}, {2, 2, 2}, {0, 1, 1}, {-1, 0, 0}));
        CHECK((t.result.t_min == -2 && t.result.t_max == 0));
        CHECK(std::signbit(t.result.t_max) == false);
        CHECK(t.result.hit);
        CHECK(t.result.t_hit == 0);
    }
    SECTION("grazing along an edge: E on two faces with those components 0 — a hit on [1, 3]") {
        const auto t = traced(ray({0, 0, 0}, {2, 2, 2}, {-1, 2, 0}, {1, 0, 0}));
        CHECK(cg::test::events(t) ==
              std::vector<std::string>{"slab", "parallel-inside", "parallel-inside", "hit"});
        CHECK((t.result.t_min == 1 && t.result.t_max == 3 && t.result.hit));
        CHECK_THAT(t.steps[1].narration,
                   Catch::Contains("on a face") && Catch::Contains("0/0, which has no value"));
    }
    SECTION("touching a corner: t_min = t_max = 2") {
        const auto t = traced(ray({0, 0, 0}, {2, 2, 2}, {-2, 2, 0}, {1, -1, 1}));
        CHECK((t.result.t_min == 2 && t.result.t_max == 2 && t.result.hit));
        CHECK_THAT(t.steps.back().narration, Catch::Contains("only a touch"));
    }
    SECTION("the box behind: t_min = -4 ≤ t_max = -2 < 0") {
        const auto t = traced(ray({0, 0, 0}, {2, 2, 2}, {4, 1, 1}, {1, 0.25, 0.25}));
        CHECK(cg::test::events(t).back() == "miss-behind");
        CHECK((t.result.t_min == -4 && t.result.t_max == -2 && !t.result.hit));
        CHECK(t.steps.back().line == 8);
    }
    SECTION("a flat box (min = max on z): the ray through it touches, along it slides") {
        CHECK(RayAabb::intersect(ray({0, 0, 1}, {2, 2, 1}, {1, 1, -1}, {0, 0, 1})).t_min == 2);
        CHECK(RayAabb::intersect(ray({0, 0, 1}, {2, 2, 1}, {1, 1, -1}, {0, 0, 1})).t_max == 2);
        const auto along = RayAabb::intersect(ray({0, 0, 1}, {2, 2, 1}, {-1, 1, 1}, {1, 0, 0}));
        CHECK((along.hit && along.t_min == 1 && along.t_max == 3));
    }
}

TEST_CASE("ray-aabb: the lesson's presets are the cases above", "[accel][ray-aabb]") {
    CHECK(lesson().presets.size() == 10);
    CHECK(RayAabb::intersect(preset("an exam-style hit: in through x = 0, out through y = 2"))
              .t_hit == 1);
    CHECK(RayAabb::intersect(preset("the box behind the ray: t_max < 0")).verdict ==
          Verdict::Behind);
    CHECK(RayAabb::intersect(preset("the origin inside the box: t_min < 0, the hit is the exit"))
              .verdict == Verdict::Inside);
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        const auto in = input_of(p.input);
        const auto r = RayAabb::intersect(in);
        CHECK(r == cg::run_to_end<RayAabb>(RayAabb::start(in)));
    }
}

TEST_CASE("ray-aabb: 100,000 random rays against the long-double interval reference",
          "[accel][ray-aabb]") {
    int checked = 0, refused = 0, hits = 0, inside = 0, behind = 0, disjoint = 0, zero = 0,
        early = 0, ambiguous = 0, on_face = 0;
    for (int trial = 0; trial < 100'000; ++trial) {
        cg::Rng rng(trial);
        const RayAabb::Input in = random_ray(rng);
        const Reference ref = reference(in);
        CAPTURE(trial, text(in));
        RayAabb::State s;
        try {
            s = RayAabb::start(in);
        } catch (const cg::InputError& e) {
            // Refused only when some t is past the double range, naming the component.
            CAPTURE(e.what());
            REQUIRE(ref.near_overflow);
            REQUIRE((e.field().rfind("direction[", 0) == 0 || e.field().rfind("origin[", 0) == 0));
            ++refused;
            continue;
        }
        REQUIRE_FALSE(ref.overflow);
        ++checked;
        const RayAabb::Result r = RayAabb::intersect(in);
        REQUIRE(cg::run_to_end<RayAabb>(s) == r);  // the state machine is the plain function

        // Never NaN; each worked axis's interval as the reference's.
        for (double t : {r.t_min, r.t_max, r.t_hit}) REQUIRE_FALSE(std::isnan(t));
        const int common = std::min(r.count, ref.count);
        for (int i = 0; i < common; ++i) {
            CAPTURE(i);
            REQUIRE(same_t(r.axes[i].t_near, ref.axis[i].lo));
            REQUIRE(same_t(r.axes[i].t_far, ref.axis[i].hi));
            zero += in.direction[i] == 0;
            on_face += in.origin[i] == in.min[i] || in.origin[i] == in.max[i];
        }
        // (A t's sign is exact in doubles — the sign of a difference of doubles — unless the
        // quotient underflows.)
        auto tiny = [](LD t) { return t != 0 && std::fabs(t) < 1e-305L; };
        if (ref.ambiguous_count || tiny(ref.line.hi) ||
            tiny(ref.line.lo)) {  // decided by rounding: skip the verdict
            ++ambiguous;
            continue;
        }
        REQUIRE(r.count == ref.count);
        early += r.count < 3;
        if (ref.count == 3) {  // all three axes: t_min, t_max are the line's interval
            REQUIRE(same_t(r.t_min, ref.line.lo));
            REQUIRE(same_t(r.t_max, ref.line.hi));
        }
        // The half-line meets the closed box exactly when its interval is not empty.
        const bool ref_hit = ref.half_line.lo <= ref.half_line.hi;
        REQUIRE(r.hit == ref_hit);
        if (ref_hit) {
            ++hits;
            const bool ref_inside = ref.line.lo <= 0;
            REQUIRE((r.verdict == Verdict::Inside) == ref_inside);
            inside += ref_inside;
            REQUIRE(
                same_t(r.t_hit, ref.line.lo >= 0 ? ref.line.lo : ref.line.hi));  // exit from inside
            REQUIRE(same_t(std::max(r.t_min, 0.0), ref.half_line.lo));
        } else if (ref.line.lo > ref.line.hi) {
            REQUIRE(r.verdict == Verdict::Disjoint);
            ++disjoint;
        } else {
            REQUIRE(r.verdict == Verdict::Behind);
            ++behind;
        }
    }
    // The mix covers what it is meant to.
    CHECK(checked > 90'000);
    CHECK(hits > 10'000);
    CHECK(inside > 5'000);
    CHECK(behind > 1'000);
    CHECK(disjoint > 10'000);
    CHECK(early > 10'000);
    CHECK(zero > 10'000);
    CHECK(on_face > 10'000);
    CHECK(refused > 100);
    CHECK(ambiguous < checked * 3 / 100);  // decimal rays aimed at a corner: a rounding decides
    WARN("ray-aabb random: " << checked << " checked (" << hits << " hits, " << inside
                             << " from inside, " << disjoint << " disjoint, " << behind
                             << " behind, " << early << " early-outs), " << refused
                             << " refused (t overflows), " << ambiguous << " ties left undecided");
}

TEST_CASE("ray-aabb: infinities never make a NaN", "[accel][ray-aabb]") {
    // Every way a component 0 can meet a plane: E below, on min, inside, on max, above; a flat
    // box; huge and tiny scales.
    for (double scale : {1e-300, 1.0, 1e300})
        for (double e : {-2.0, 0.0, 0.5, 1.0, 2.0})
            for (double flat : {0.0, 1.0}) {
                CAPTURE(scale, e, flat);
                const dvec3 mn(0, 0, 0), mx = scale * dvec3(1, 1, flat);
                const auto in = ray(mn, mx, scale * dvec3(e, 0.5, e), {0, 1, 0});
                auto s = RayAabb::start(in);
                while (!RayAabb::done(s)) {
                    cg::StepInfo info;
                    RayAabb::step(s, &info);
                    CHECK(info.narration.find("nan") == std::string::npos);
                    CHECK(info.narration.find("NaN") == std::string::npos);
                    for (const auto& v : info.vars)
                        if (auto* d = std::get_if<double>(&v.value)) CHECK(std::isfinite(*d));
                }
                const auto r = RayAabb::result(s);
                for (int i = 0; i < r.count; ++i)
                    CHECK_FALSE((std::isnan(r.axes[i].t_near) || std::isnan(r.axes[i].t_far)));
                CHECK_FALSE((std::isnan(r.t_min) || std::isnan(r.t_max) || std::isnan(r.t_hit)));
                const bool in_x = 0 <= e && e * scale <= mx.x,
                           in_z = 0 <= e * scale && e * scale <= mx.z;
                CHECK(r.hit == (in_x && in_z));
            }
}

TEST_CASE("ray-aabb: infinite t's are written \"inf\" and \"-inf\" in JSON", "[accel][ray-aabb]") {
    const cg::json r = cg::test::result_of(
        "ray-aabb",
        std::string(
            R"({"box": {"min": [0, 0, 0], "max": [2, 2, 2]}, "origin": [1, 1, 5], "direction": [0, 1, 0]})"));
    CHECK(r["hit"] == false);
    CHECK(r["verdict"] == "miss-disjoint");
    CHECK(r["axes"] == cg::json::parse(R"([{"t_near": "-inf", "t_far": "inf"},
                                          {"t_near": -1.0, "t_far": 1.0},
                                          {"t_near": "inf", "t_far": "-inf"}])"));
    CHECK(r["t_min"] == "inf");
    CHECK(r["t_max"] == "-inf");
    CHECK(r["t_hit"].is_null());
    const cg::json h = cg::test::result_of(
        "ray-aabb",
        std::string(
            R"({"box": {"min": [0, 0, 0], "max": [2, 2, 2]}, "origin": [1, 1, 1], "direction": [0, 0, -1]})"));
    CHECK(h["verdict"] == "inside");
    CHECK(h["t_min"] == -1.0);
    CHECK(h["t_max"] == 1.0);
    CHECK(h["t_hit"] == 1.0);
    CHECK(h.dump().find("-0.0") == std::string::npos);
}

TEST_CASE("ray-aabb: bad input is refused, naming the field", "[accel][ray-aabb]") {
    auto error = [](const std::string& text) { return cg::test::error_of("ray-aabb", text); };
    CHECK(
        error(
            R"({"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "origin": [-1, 0, 0], "direction": [1, 0, 0]})") ==
        "(accepted)");
    CHECK(
        error(
            R"({"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "origin": [-1, 0, 0], "direction": [0, 0, 0]})") ==
        "direction: must not be the zero vector (0, 0, 0): a ray needs a direction");
    CHECK(
        error(
            R"({"box": {"min": [0, 2, 0], "max": [1, 1, 1]}, "origin": [-1, 0, 0], "direction": [1, 0, 0]})") ==
        "box.max[1]: is less than box.min[1] (1 < 2): the box is empty; it needs min ≤ max on "
        "every axis (a flat box, min = max, is allowed)");
    CHECK(
        error(
            R"({"box": {"min": [0, 1, 0], "max": [1, 1, 1]}, "origin": [-1, 0, 0], "direction": [1, 0, 0]})") ==
        "(accepted)");
    CHECK_THAT(
        error(
            R"({"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "origin": [-1e300, 0, 0], "direction": [1e-300, 0, 0]})"),
        Catch::StartsWith("direction[0]: is too small against the distance to the box"));
    CHECK_THAT(
        error(
            R"({"box": {"min": [0, 0, 0], "max": [1.7e308, 1, 1]}, "origin": [-1.7e308, 0, 0], "direction": [1, 0, 0]})"),
        Catch::StartsWith("origin[0]: is too far from the box"));
    CHECK_THAT(error(R"({"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "origin": [-1, 0, 0]})"),
               Catch::StartsWith("direction: is missing"));
    CHECK_THAT(
        error(R"({"box": {"min": [0, 0, 0]}, "origin": [-1, 0, 0], "direction": [1, 0, 0]})"),
        Catch::StartsWith("box.max: is missing"));
    CHECK_THAT(
        error(
            R"({"box": {"min": [0, 0, 0], "max": [1, 1, 1], "mid": 0}, "origin": [-1, 0, 0], "direction": [1, 0, 0]})"),
        Catch::StartsWith("box.mid: "));
    CHECK_THAT(
        error(
            R"({"box": {"min": [0, 0], "max": [1, 1, 1]}, "origin": [-1, 0, 0], "direction": [1, 0, 0]})"),
        Catch::StartsWith("box.min: "));
    CHECK_THAT(
        error(
            R"({"box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "origin": [-1, "a", 0], "direction": [1, 0, 0]})"),
        Catch::StartsWith("origin[1]: "));
    CHECK_THROWS_WITH(RayAabb::start(ray({0, 0, 0}, {1, 1, 1}, {0, 0, 0}, {1, kInf, 0})),
                      Catch::StartsWith("direction[1]: must be a finite number"));
}

TEST_CASE("ray-aabb: deterministic traces, replay on the example and the presets",
          "[accel][ray-aabb]") {
    const cg::Algorithm& a = cg::test::algorithm("ray-aabb");
    cg::test::check_replay(a, a.example(), cg::test::kEveryStep);
    for (const auto& p : lesson().presets) {
        CAPTURE(p.name);
        cg::test::check_replay(a, p.input, cg::test::kEveryStep);
    }
}

TEST_CASE(
    "ray-aabb: the picture — the box, the current slab's planes, the points, the segment inside",
    "[accel][ray-aabb]") {
    auto s = RayAabb::start(ray({0, 0, 0}, {4, 2, 2}, {-2, 0, 0.5}, {2, 1, 0.5}));
    RayAabb::step(s, nullptr);  // axis x
    cg::Scene scene;
    RayAabb::draw(s, scene);
    CHECK(scene.has_3d());
    int planes = 0, box = 0;
    for (const auto& f : scene.faces3) {
        planes += f.style.role == cg::Role::Active;
        box += f.style.role == cg::Role::Window;
        if (f.style.role == cg::Role::Active)
            for (const auto& p : f.points) CHECK((p.x == 0 || p.x == 4));  // the x planes
    }
    CHECK(planes == 2);
    CHECK(box == 6);
    int entering = 0, leaving = 0;
    for (const auto& p : scene.points3) {
        if (p.style.role == cg::Role::Entering) {
            CHECK(p.p == dvec3(0, 1, 1));
            ++entering;
        }
        if (p.style.role == cg::Role::Leaving) {
            CHECK(p.p == dvec3(4, 3, 2));
            ++leaving;
        }
    }
    CHECK((entering == 1 && leaving == 1));
    while (!RayAabb::done(s)) RayAabb::step(s, nullptr);
    scene.clear();
    RayAabb::draw(s, scene);
    bool inside = false;
    for (const auto& g : scene.segments3)
        if (g.style.role == cg::Role::Kept && g.style.width > 5)
            inside = g.a == dvec3(0, 1, 1) && g.b == dvec3(2, 2, 1.5);
    CHECK(inside);
    for (const auto& f : scene.faces3) CHECK(f.style.role != cg::Role::Active);  // no slab now
    // The t intervals are a chart of their own: x, y, z slabs and the overlap [t_min, t_max]
    // = [1, 2] in green, on a t axis.
    CHECK(!scene.has_2d());
    REQUIRE(scene.panels.size() == 1);
    const cg::Panel& chart = scene.panels[0];
    CHECK(chart.kind == cg::PanelKind::Chart);
    CHECK(chart.x.label == "t");
    // The rows are named on the y axis (x at the top, the overlap at the bottom), not numbered.
    CHECK(chart.y.names ==
          std::vector<std::string>{"[t_min, t_max]", "z slab", "y slab", "x slab"});
    bool overlap = false;
    int bars = 0;
    for (const auto& g : chart.segments) {
        bars += g.style.role == cg::Role::Window;
        overlap |= g.style.role == cg::Role::Kept && g.a == glm::dvec2(1, 0) && g.b == glm::dvec2(2, 0);
    }
    CHECK(bars == 3);
    CHECK(overlap);
    CHECK(scene.focus3.size() == 1);

    // Every step of every preset and of 3,000 random rays (tiny and huge included) draws only
    // finite coordinates.
    std::vector<RayAabb::Input> inputs;
    for (const auto& p : lesson().presets) inputs.push_back(input_of(p.input));
    for (int trial = 0; trial < 3000; ++trial) {
        cg::Rng rng(1'000'000 + trial);
        inputs.push_back(random_ray(rng));
    }
    int drawn = 0;
    for (const auto& in : inputs) {
        RayAabb::State st;
        try {
            st = RayAabb::start(in);
        } catch (const cg::InputError&) {
            continue;
        }
        while (true) {
            cg::Scene sc;
            RayAabb::draw(st, sc);
            CAPTURE(text(in));
            REQUIRE(scene_problem(sc) == "");
            ++drawn;
            if (RayAabb::done(st)) break;
            RayAabb::step(st, nullptr);
        }
    }
    CHECK(drawn > 10'000);
}

TEST_CASE("ray-aabb: exam problems are hand-workable and cover the cases",
          "[accel][ray-aabb][exam]") {
    const cg::Algorithm& a = cg::test::algorithm("ray-aabb");
    int hit = 0, inside = 0, behind = 0, disjoint = 0, zero = 0, early = 0;
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        CAPTURE(seed);
        const cg::ExamProblem p = cg::make_exam(a, seed);
        const auto in = input_of(p.input);
        const auto r = RayAabb::intersect(in);
        for (int i = 0; i < r.count; ++i)
            for (double t : {r.axes[i].t_near, r.axes[i].t_far})
                if (std::isfinite(t)) CHECK(t * 4 == std::round(t * 4));  // quarters
        for (int i = 0; i < 3; ++i) zero += in.direction[i] == 0;
        hit += r.verdict == Verdict::Hit;
        inside += r.verdict == Verdict::Inside;
        behind += r.verdict == Verdict::Behind;
        disjoint += r.verdict == Verdict::Disjoint;
        early += r.count < 3;
        // The student's answer as typed: the infinities as "inf" / "-inf".
        cg::json given = p.expected;
        for (auto& axis : given["axes"])
            for (const char* k : {"t_near", "t_far"})
                if (axis[k].is_string()) axis[k] = cg::parse_answer(axis[k].get<std::string>());
        for (const auto& g : cg::grade(p, given)) CHECK(g.correct);
    }
    CHECK(hit > 250);
    CHECK(inside > 100);
    CHECK(behind > 50);
    CHECK(disjoint > 100);
    CHECK(zero > 150);
    CHECK(early > 50);
    const cg::ExamProblem p = cg::make_exam(a, 7);
    CHECK_THAT(p.question, Catch::Contains("\"inf\""));
    CHECK(p.answers == std::vector<std::string>{"axes", "t_min", "t_max", "hit"});
    // "inf" typed for an infinite t grades right; a number there grades wrong.
    CHECK(cg::answer_matches("inf", cg::parse_answer("inf")));
    CHECK(cg::answer_matches("-inf", cg::parse_answer("-inf")));
    CHECK_FALSE(cg::answer_matches("inf", cg::parse_answer("1e308")));
}
