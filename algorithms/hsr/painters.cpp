// Sections: [pieces] [tests] [pair] [spec] [advance] [narrate] [result and render]; the picture is
// in painters_draw.cpp
#include "hsr/painters.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>

#include <glm/common.hpp>

#include "core/format.hpp"
#include "raster/orient2d.hpp"

namespace cg {

namespace {

using glm::dvec2;
using glm::dvec3;
using hsr::PixelSpan;
using hsr::Plane;
using Piece = Painters::Piece;
using Cut = Painters::Cut;
using Test = Painters::Test;
using Outcome = Painters::Outcome;
using Decision = Painters::Decision;

constexpr double kRelativeMargin = 1e-9;

// What the tests read: the scene, its planes and spans, and the rounding margin.
struct Ctx {
    const hsr::ScreenScene& scene;
    const std::vector<Plane>& planes;
    const std::vector<std::vector<PixelSpan>>& spans;
    double margin;
};

// What a pair test did, for the narration.
struct Report {
    Decision& d;
    bool& cycle;
    std::string& split_name;
    Cut& cut;
    std::vector<std::string>& made;
};

// ---- [pieces] -------------------------------------------------------------------------------

double slope(const Plane& p) { return (std::fabs(p.a) + std::fabs(p.b)) / std::fabs(p.c); }

// 1e-9 of the largest coordinate (at least 1): far above the rounding of a depth, far below
// anything a scene means.
double scene_margin(const hsr::ScreenScene& scene) {
    double size = 1;
    for (const auto& p : scene.polygons)
        for (const auto& v : p.vertices) size = std::max({size, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    return kRelativeMargin * size;
}

// Is the centre (x, y) on the piece's side of all its cuts? A plane cut asks what
// hsr::visible_ids asks there: is the cutting polygon in front (the tie rule included)?
bool on_side(const Ctx& c, const Piece& p, double x, double y) {
    for (const Cut& cut : p.cuts) {
        bool low_or_far = false;
        switch (cut.kind) {
            case Cut::Kind::Plane: {
                const double zp = hsr::depth_at(c.planes[static_cast<std::size_t>(p.parent)], x, y);
                const double zq = hsr::depth_at(c.planes[static_cast<std::size_t>(cut.other)], x, y);
                low_or_far = hsr::in_front(zq, cut.other, zp, p.parent);
                break;
            }
            case Cut::Kind::Column: low_or_far = x < cut.other; break;
            case Cut::Kind::Row: low_or_far = y < cut.other; break;
        }
        if (low_or_far != cut.low_or_far) return false;
    }
    return true;
}

bool piece_covers(const Ctx& c, const Piece& p, double x, double y) {
    return hsr::covers(c.scene.polygons[static_cast<std::size_t>(p.parent)], x, y) && on_side(c, p, x, y);
}

// The pixel centres a piece covers: how many, and their columns and rows.
void count_centres(const Ctx& c, Piece& p) {
    p.centres = 0;
    p.i_lo = p.j_lo = INT_MAX, p.i_hi = p.j_hi = INT_MIN;
    for (const PixelSpan& sp : c.spans[static_cast<std::size_t>(p.parent)]) {
        const double y = sp.j + 0.5;
        if (y < p.lo.y || y > p.hi.y) continue;
        for (int i = sp.i_first; i < sp.i_end; ++i) {
            if (!p.cuts.empty() && !on_side(c, p, i + 0.5, y)) continue;
            ++p.centres;
            p.i_lo = std::min(p.i_lo, i), p.i_hi = std::max(p.i_hi, i);
            p.j_lo = std::min(p.j_lo, sp.j), p.j_hi = std::max(p.j_hi, sp.j);
        }
    }
    if (p.centres == 0) p.i_lo = p.i_hi = p.j_lo = p.j_hi = 0;
}

// Extents from the outline; a piece's are padded by the margin (its outline is rounded).
void set_extents(const Ctx& c, Piece& p) {
    p.lo = p.hi = p.vertices.empty() ? dvec3(0) : p.vertices[0];
    for (const auto& v : p.vertices) p.lo = glm::min(p.lo, v), p.hi = glm::max(p.hi, v);
    if (p.cuts.empty()) return;
    const double m = c.margin, mz = c.margin * (1 + slope(c.planes[static_cast<std::size_t>(p.parent)]));
    p.lo -= dvec3(m, m, mz), p.hi += dvec3(m, m, mz);
}

Piece whole(const Ctx& c, int k) {
    Piece p;
    p.parent = k;
    p.name = "P";  // not "P" + to_string(k): GCC 12 warns falsely on that insert (bug 105329)
    p.name += std::to_string(k);
    p.vertices = c.scene.polygons[static_cast<std::size_t>(k)].vertices;
    set_extents(c, p);
    count_centres(c, p);
    return p;
}

// The part of a convex outline where g ≥ 0 (Sutherland-Hodgman against one half-space).
template <class G>
std::vector<dvec3> clip(const std::vector<dvec3>& v, G g) {
    std::vector<dvec3> out;
    const std::size_t n = v.size();
    for (std::size_t k = 0; k < n; ++k) {
        const dvec3& a = v[k];
        const dvec3& b = v[(k + 1) % n];
        const double ga = g(a), gb = g(b);
        if (ga >= 0) out.push_back(a);
        if ((ga > 0 && gb < 0) || (ga < 0 && gb > 0)) out.push_back(a + (b - a) * (ga / (ga - gb)));
    }
    return out;
}

// The two pieces of p on either side of a cut (low / far first); each keeps p's cuts plus its side.
void cut_piece(const Ctx& c, const Piece& p, Cut::Kind kind, int other, Piece out[2]) {
    for (int side = 0; side < 2; ++side) {
        Piece& r = out[side];
        r.parent = p.parent;
        r.name = p.name + (side == 0 ? "a" : "b");
        r.cuts = p.cuts;
        r.cuts.push_back({kind, other, side == 0});
        const double sign = side == 0 ? 1 : -1;
        switch (kind) {
            case Cut::Kind::Plane: {
                const Plane& pl = c.planes[static_cast<std::size_t>(other)];
                r.vertices = clip(p.vertices, [&](const dvec3& v) { return sign * (v.z - hsr::depth_at(pl, v.x, v.y)); });
                break;
            }
            case Cut::Kind::Column:
                r.vertices = clip(p.vertices, [&](const dvec3& v) { return sign * (other - v.x); });
                break;
            case Cut::Kind::Row:
                r.vertices = clip(p.vertices, [&](const dvec3& v) { return sign * (other - v.y); });
                break;
        }
        if (r.vertices.empty()) r.vertices = p.vertices;  // rounding lost it: the parent's outline contains it
        set_extents(c, r);
        count_centres(c, r);
    }
}

// ---- [tests] --------------------------------------------------------------------------------

enum class Side : std::uint8_t { Far, Near, Neither };

// Is piece a wholly on the far side of polygon k's plane, wholly on the near side, or neither
// (crossing or touching it)? A piece cut by that plane knows its side exactly; two polygons in
// one flat plane z = c are ordered by the tie rule; otherwise every vertex must clear the plane
// by the margin.
Side side_of(const Ctx& c, const Piece& a, int k) {
    for (const Cut& cut : a.cuts)
        if (cut.kind == Cut::Kind::Plane && cut.other == k) return cut.low_or_far ? Side::Far : Side::Near;
    const Plane& pl = c.planes[static_cast<std::size_t>(k)];
    const Plane& own = c.planes[static_cast<std::size_t>(a.parent)];
    if (pl.a == 0 && pl.b == 0 && own.a == 0 && own.b == 0 && hsr::depth_at(pl, 0, 0) == hsr::depth_at(own, 0, 0))
        return a.parent > k ? Side::Far : Side::Near;  // equal z: the lower index is in front
    const double tol = c.margin * (1 + slope(pl) + slope(own));
    bool far = true, near = true;
    for (const auto& v : a.vertices) {
        const double d = v.z - hsr::depth_at(pl, v.x, v.y);
        far = far && d > tol;
        near = near && d < -tol;
    }
    return far ? Side::Far : near ? Side::Near : Side::Neither;
}

// Is there a line with a on one side and b on the other (touching allowed for whole polygons,
// whose orientation tests are exact; a piece must clear it by the margin)?
bool separated_by_edges(const Ctx& c, const Piece& a, const Piece& b) {
    const auto& v = a.vertices;
    const std::size_t n = v.size();
    if (n < 2) return false;
    double area = 0;
    for (std::size_t k = 0; k < n; ++k) area += v[k].x * v[(k + 1) % n].y - v[(k + 1) % n].x * v[k].y;
    const bool exact = a.cuts.empty() && b.cuts.empty();
    for (std::size_t k = 0; k < n; ++k) {
        dvec2 p(v[k]), q(v[(k + 1) % n]);
        if (area < 0) std::swap(p, q);
        if (p == q) continue;
        const double len = std::sqrt((q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y));
        bool all_out = true;
        for (const auto& w : b.vertices) {
            const dvec2 r(w);
            const bool out = exact ? orient2d(p, q, r) <= 0
                                   : (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x) < -c.margin * len;
            if (!out) {
                all_out = false;
                break;
            }
        }
        if (all_out) return true;
    }
    return false;
}

bool projections_apart(const Ctx& c, const Piece& a, const Piece& b) {
    return separated_by_edges(c, a, b) || separated_by_edges(c, b, a);
}

// Test 6, for a piece with at most one pixel centre: may p be drawn before q there?
bool centre_allows(const Ctx& c, const Piece& p, const Piece& q) {
    const Piece& small = p.centres <= q.centres ? p : q;
    const Piece& other = &small == &p ? q : p;
    if (small.centres == 0) return true;
    const double x = small.i_lo + 0.5, y = small.j_lo + 0.5;
    if (!piece_covers(c, other, x, y)) return true;
    const double zp = hsr::depth_at(c.planes[static_cast<std::size_t>(p.parent)], x, y);
    const double zq = hsr::depth_at(c.planes[static_cast<std::size_t>(q.parent)], x, y);
    return hsr::in_front(zq, q.parent, zp, p.parent);
}

// May p be drawn before q? The first test that says so, or Test::None.
Test may_precede(const Ctx& c, const Piece& p, const Piece& q) {
    if (p.parent == q.parent) return Test::Same;
    if (p.hi.x <= q.lo.x || q.hi.x <= p.lo.x) return Test::XExtent;
    if (p.hi.y <= q.lo.y || q.hi.y <= p.lo.y) return Test::YExtent;
    if (side_of(c, p, q.parent) == Side::Far) return Test::PBehind;
    if (side_of(c, q, p.parent) == Side::Near) return Test::QInFront;
    if (projections_apart(c, p, q)) return Test::Projection;
    if ((p.centres <= 1 || q.centres <= 1) && centre_allows(c, p, q)) return Test::Centre;
    return Test::None;
}

// The reversed tests 3′ and 4′ (and 6): may q be drawn before p?
Test may_follow(const Ctx& c, const Piece& p, const Piece& q) {
    if (side_of(c, q, p.parent) == Side::Far) return Test::PBehind;
    if (side_of(c, p, q.parent) == Side::Near) return Test::QInFront;
    if ((p.centres <= 1 || q.centres <= 1) && centre_allows(c, q, p)) return Test::Centre;
    return Test::None;
}

// ---- [pair] ---------------------------------------------------------------------------------

// The first Q at or after `from` that is not wholly in front of P in z.
std::size_t next_overlap(const std::vector<Piece>& list, std::size_t from) {
    for (std::size_t i = from; i < list.size(); ++i)
        if (list[i].hi.z >= list[0].lo.z) return i;
    return list.size();
}

// Replaces list[at] by its cut (the pieces that cover a centre), and says their names.
void replace_by_cut(const Ctx& c, std::vector<Piece>& list, std::size_t at, Cut::Kind kind, int other,
                    Report& r) {
    Piece two[2];
    cut_piece(c, list[at], kind, other, two);
    r.split_name = list[at].name;
    r.cut = {kind, other, true};
    std::vector<std::string>& made = r.made;
    list.erase(list.begin() + static_cast<std::ptrdiff_t>(at));
    made.clear();
    std::size_t pos = at;
    for (Piece& p : two)
        if (p.centres > 0) {
            made.push_back(p.name);
            list.insert(list.begin() + static_cast<std::ptrdiff_t>(pos++), std::move(p));
        }
}

// Cuts a piece with at least two centres in two along the grid line between the middle columns
// (or rows, when all its centres are in one column): both halves keep at least one centre.
void halve(const Ctx& c, std::vector<Piece>& list, std::size_t at, Report& r) {
    const Piece& p = list[at];
    if (p.i_hi > p.i_lo) replace_by_cut(c, list, at, Cut::Kind::Column, (p.i_lo + p.i_hi + 1) / 2, r);
    else replace_by_cut(c, list, at, Cut::Kind::Row, (p.j_lo + p.j_hi + 1) / 2, r);
}

struct Counters {
    long long pair_tests = 0, moves = 0, splits = 0;
};

// Tests P = list[0] against Q = list[q]: passes, moves Q to the far end, or splits. Returns the
// next Q to test (list.size() when P is settled).
std::size_t resolve_pair(const Ctx& c, std::vector<Piece>& list, std::size_t q, Counters& n, Report& r) {
    Decision& d = r.d;
    bool& cycle = r.cycle;
    ++n.pair_tests;
    const Piece& P = list[0];
    const Piece& Q = list[q];
    d.p = P.name, d.q = Q.name;
    d.test = may_precede(c, P, Q);
    cycle = false;
    if (d.test != Test::None) {
        d.outcome = Outcome::Pass;
        return next_overlap(list, q + 1);
    }
    d.test = may_follow(c, P, Q);
    if (d.test != Test::None && !Q.marked) {  // Q goes first: to the far end, marked
        d.outcome = Outcome::Move;
        ++n.moves;
        Piece moved = std::move(list[q]);
        moved.marked = true;
        list.erase(list.begin() + static_cast<std::ptrdiff_t>(q));
        list.insert(list.begin(), std::move(moved));
        return next_overlap(list, 1);
    }
    // Neither order is safe, or Q would move again (a cycle): split.
    d.outcome = Outcome::Split;
    cycle = d.test != Test::None;
    ++n.splits;
    const int pp = P.parent, qp = Q.parent;
    if (side_of(c, P, qp) == Side::Neither) {
        replace_by_cut(c, list, 0, Cut::Kind::Plane, qp, r);
    } else if (side_of(c, Q, pp) == Side::Neither) {
        replace_by_cut(c, list, q, Cut::Kind::Plane, pp, r);
    } else {
        // A cycle of polygons each wholly on one side of the others' planes: cut along the grid.
        std::size_t at = list.size();
        if (P.centres >= 2) at = 0;
        else if (Q.centres >= 2) at = q;
        else
            for (std::size_t i = 0; i < list.size(); ++i)
                if (list[i].marked && list[i].centres >= 2 && (at == list.size() || list[i].centres > list[at].centres)) at = i;
        if (at == list.size()) throw std::logic_error("painter's algorithm: a cycle with nothing left to split");
        halve(c, list, at, r);
    }
    for (Piece& p : list) p.marked = false;
    return next_overlap(list, 1);
}

// The list at the start: whole polygons sorted on their farthest z, farthest first; at equal
// farthest z the higher index first (it must lose the ties, so it is drawn earlier).
std::vector<Piece> sorted_list(const Ctx& c) {
    std::vector<Piece> list;
    list.reserve(c.scene.polygons.size());
    for (std::size_t k = 0; k < c.scene.polygons.size(); ++k) list.push_back(whole(c, static_cast<int>(k)));
    std::stable_sort(list.begin(), list.end(), [](const Piece& a, const Piece& b) {
        return a.hi.z > b.hi.z || (a.hi.z == b.hi.z && a.parent > b.parent);
    });
    return list;
}

// Scan-converts a piece into the buffer: its parent's spans, the centres on its side of the cuts.
long long paint(const Ctx& c, const Piece& p, std::vector<int>& ids) {
    long long pixels = 0;
    const std::size_t W = static_cast<std::size_t>(c.scene.width);
    for (const PixelSpan& sp : c.spans[static_cast<std::size_t>(p.parent)]) {
        const std::size_t row = static_cast<std::size_t>(sp.j) * W;
        for (int i = sp.i_first; i < sp.i_end; ++i)
            if (p.cuts.empty() || on_side(c, p, i + 0.5, sp.j + 0.5)) ids[row + static_cast<std::size_t>(i)] = p.parent, ++pixels;
    }
    return pixels;
}

}  // namespace

const char* Painters::test_name(Test t) {
    switch (t) {
        case Test::None: return "none";
        case Test::Depth: return "z extents";
        case Test::Same: return "pieces of one polygon";
        case Test::XExtent: return "x extents";
        case Test::YExtent: return "y extents";
        case Test::PBehind: return "P behind Q's plane";
        case Test::QInFront: return "Q in front of P's plane";
        case Test::Projection: return "projections";
        case Test::Centre: return "its one pixel centre";
    }
    return "?";
}

std::string Painters::test_code(const Decision& d) {
    if (d.outcome == Outcome::Move) return "move";
    if (d.outcome == Outcome::Split) return "split";
    switch (d.test) {
        case Test::XExtent: return "1";
        case Test::YExtent: return "2";
        case Test::PBehind: return "3";
        case Test::QInFront: return "4";
        case Test::Projection: return "5";
        case Test::Centre: return "6";
        case Test::Same: return "same";
        default: return "-";
    }
}

bool Painters::covers(const State& s, const Piece& p, double x, double y) {
    return piece_covers(Ctx{s.in.scene, s.planes, s.spans, s.margin}, p, x, y);
}

// ---- [spec] ---------------------------------------------------------------------------------

namespace {

enum Line {
    kLineSort = 1,
    kLineHead,
    kLineOverlap,
    kLineTests,
    kLineMove,
    kLineSplit,
    kLineSettle,
    kLineDraw,
    kLineDone,
};

}  // namespace

const Spec& Painters::spec() {
    static const Spec spec{
        "painters",
        "Painter's algorithm (depth sort)",
        "Hidden Surface Removal",
        {
            "sort the polygons on farthest z, farthest first",
            "while the list is not empty: P ← the farthest polygon of the list",
            "    for each Q whose z extent overlaps P's:",
            "        P may go before Q if 1 x extents apart, 2 y apart, 3 P behind Q's plane, "
            "4 Q in front of P's plane, 5 projections apart",
            "        else if Q may go before P (3′, 4′) and Q is unmarked: move Q to the far end, mark it",
            "        else (cyclic, or each crosses the other's plane): split P or Q, replace it by its pieces",
            "    P obscures nothing: settle it (next in the drawing order)",
            "scan-convert the settled polygons back to front, each overwriting what is behind",
            "done: every pixel shows the last polygon drawn there",
        },
        {
            {"sort", "the list sorted on farthest z, farthest first"},
            {"pass", "a test shows P cannot hide Q: the pair needs nothing"},
            {"move", "every test failed but Q may go before P: Q moves to the far end, marked"},
            {"split", "no order is safe for the pair (or a cycle): a polygon is split in two"},
            {"settle", "P hides none of the polygons left: it is drawn next"},
            {"draw", "one polygon scan-converted over what is behind it"},
            {"done", "every polygon drawn back to front: the visible image"},
        },
        {},  // no sliders
        {
            .predict = {{"pass", {}}, {"move", {}}, {"split", {}}},
            .mistakes = {
                {"pass", "", "event:move", "moved Q although one of the tests had passed"},
                {"move", "", "event:pass", "kept the order although every test failed"},
                {"split", "", "event:move", "moved a polygon of a cycle instead of splitting it"},
                {"pass", "P", "swap:Q", "ran the tests with P and Q the wrong way round"},
            },
            .input_kind = "hsr-scene",
            .compare = {"ids"},
            .costs = {"pair_tests", "moves", "splits"},
        },
    };
    return spec;
}

void Painters::validate(const Input& in) { hsr::validate(in.scene); }

Painters::State Painters::start(const Input& in) {
    validate(in);
    State s;
    s.in = in;
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void Painters::advance(State& s) {
    s.last = s.phase;
    const auto& scene = s.in.scene;
    const Ctx c{scene, s.planes, s.spans, s.margin};
    Report r{s.pair, s.cycle, s.split_name, s.split_cut, s.made};
    Counters n{s.pair_tests, s.moves, s.splits};
    auto next_phase = [&] { s.phase = s.q < s.list.size() ? Phase::Pair : Phase::Settle; };
    switch (s.phase) {
        case Phase::Sort: {  // Sort on farthest z
            s.planes.clear();
            for (const auto& p : scene.polygons) s.planes.push_back(hsr::plane_of(p));
            s.spans.clear();
            for (const auto& p : scene.polygons) s.spans.push_back(hsr::polygon_spans(p, scene.width, scene.height));
            s.margin = scene_margin(scene);
            const Ctx ready{scene, s.planes, s.spans, s.margin};
            s.list = sorted_list(ready);
            s.ids.assign(static_cast<std::size_t>(scene.width * scene.height), -1);
            if (s.list.empty()) {
                s.phase = Phase::Finish;
                return;
            }
            s.q = next_overlap(s.list, 1);
            next_phase();
            return;
        }
        case Phase::Pair: {  // Test P against Q
            s.made.clear();
            s.q = resolve_pair(c, s.list, s.q, n, r);
            s.pair_tests = n.pair_tests, s.moves = n.moves, s.splits = n.splits;
            s.decisions.push_back(s.pair);
            next_phase();
            return;
        }
        case Phase::Settle: {  // P hides nothing left: it is drawn next
            s.name = s.list[0].name;
            s.settled.push_back(std::move(s.list[0]));
            s.list.erase(s.list.begin());
            for (Piece& p : s.list) p.marked = false;
            if (s.list.empty()) {
                s.phase = Phase::Draw;
                return;
            }
            s.q = next_overlap(s.list, 1);
            next_phase();
            return;
        }
        case Phase::Draw: {  // Scan-convert the next settled polygon over the buffer
            const Piece& p = s.settled[s.drawn];
            s.name = p.name;
            s.step_pixels = paint(c, p, s.ids);
            if (++s.drawn == s.settled.size()) s.phase = Phase::Finish;
            return;
        }
        case Phase::Finish:
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;  // a finished machine stays finished
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string names_of(const std::vector<Piece>& list) {
    std::string out;
    for (const Piece& p : list) out += (out.empty() ? "" : ", ") + p.name;
    return out.empty() ? "(empty)" : out;
}

std::string interval(double lo, double hi) { return "[" + num(lo, 4) + ", " + num(hi, 4) + "]"; }

const Piece* find_piece(const std::vector<Piece>& list, const std::string& name) {
    for (const Piece& p : list)
        if (p.name == name) return &p;
    return nullptr;
}

// Why a test held, with the numbers where the pieces are still at hand.
std::string why(const Painters::State& s, const Decision& d, bool reversed) {
    const Piece* P = find_piece(s.list, d.p);
    const Piece* Q = find_piece(s.list, d.q);
    if (!P) P = find_piece(s.settled, d.p);
    const std::string p = reversed ? d.q : d.p, q = reversed ? d.p : d.q;
    switch (d.test) {
        case Test::Same: return d.p + " and " + d.q + " are pieces of one polygon: no pixel centre is in both";
        case Test::XExtent:
            return P && Q ? "x extents " + interval(P->lo.x, P->hi.x) + " and " + interval(Q->lo.x, Q->hi.x) + " do not overlap"
                          : "their x extents do not overlap";
        case Test::YExtent:
            return P && Q ? "y extents " + interval(P->lo.y, P->hi.y) + " and " + interval(Q->lo.y, Q->hi.y) + " do not overlap"
                          : "their y extents do not overlap";
        case Test::PBehind: return p + " lies wholly on the far side of " + q + "'s plane";
        case Test::QInFront: return q + " lies wholly on the near side of " + p + "'s plane";
        case Test::Projection: return "a line separates their projections on the screen";
        case Test::Centre:
            return "one of them covers at most one pixel centre, where " + q + " is in front of " + p +
                   " (or only one covers it)";
        default: return "";
    }
}

std::string test_number(Test t) {
    switch (t) {
        case Test::XExtent: return "1";
        case Test::YExtent: return "2";
        case Test::PBehind: return "3";
        case Test::QInFront: return "4";
        case Test::Projection: return "5";
        case Test::Centre: return "6";
        default: return "";
    }
}

}  // namespace

std::string Painters::cut_text(const Cut& cut) {
    switch (cut.kind) {
        case Cut::Kind::Plane: return "the plane of P" + std::to_string(cut.other);
        case Cut::Kind::Column: return "the grid line x = " + std::to_string(cut.other);
        case Cut::Kind::Row: return "the grid line y = " + std::to_string(cut.other);
    }
    return "";
}

void Painters::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    info.vars.clear();
    const auto& scene = s.in.scene;
    switch (s.last) {
        case Phase::Sort: {
            info.event = "sort";
            info.line = kLineSort;
            std::string list;
            for (const Piece& p : s.list) list += (list.empty() ? "" : ", ") + p.name + " (z ≤ " + num(p.hi.z, 4) + ")";
            info.narration = s.list.empty() ? "No polygons: nothing to sort or draw."
                                            : "Sort the " + std::to_string(scene.polygons.size()) +
                                                  " polygons on their farthest z, farthest first: " + list +
                                                  " (equal farthest z: the higher index first, so the lower is "
                                                  "drawn later and wins ties).";
            info.math = "z_{\\max}:\\ ";
            for (std::size_t k = 0; k < s.list.size(); ++k)
                info.math += (k ? " \\ge " : "") + tex(s.list[k].hi.z, 4) + "\\ (" + s.list[k].name + ")";
            break;
        }
        case Phase::Pair: {
            const Decision& d = s.pair;
            const std::string pair = "P = " + d.p + ", Q = " + d.q + " (their z extents overlap): ";
            if (d.outcome == Outcome::Pass) {
                info.event = "pass";
                info.line = kLineTests;
                const std::string k = test_number(d.test);
                const std::string failed = k.empty() || k == "1" ? ""
                                           : k == "2"             ? " (test 1 fails)"
                                                                  : " (tests 1–" + std::to_string(std::stoi(k) - 1) + " fail)";
                info.narration = pair + (k.empty() ? "" : "test " + k + " (" + test_name(d.test) + ") decides" + failed + ": ") +
                                 why(s, d, false) + ", so " + d.p + " cannot hide " + d.q + ".";
                info.math = k.empty() ? "\\text{same polygon}" : "\\text{test " + k + ": " + std::string(test_name(d.test)) + "}";
            } else if (d.outcome == Outcome::Move) {
                info.event = "move";
                info.line = kLineMove;
                info.narration = pair + "tests 1–5 all fail, so " + d.p + " may hide part of " + d.q +
                                 ". Reversed, test " + test_number(d.test) + "′ holds: " + why(s, d, true) + ". So " +
                                 d.q + " moves to the far end of the list (marked) and becomes P. List: " +
                                 names_of(s.list) + ".";
                info.math = "\\text{test " + test_number(d.test) + "}':\\ " + d.q + " \\to \\text{far end}";
            } else {
                info.event = "split";
                info.line = kLineSplit;
                std::string made;
                for (const auto& m : s.made) made += (made.empty() ? "" : " and ") + m;
                const std::string reason =
                    s.cycle ? "tests 1–5 fail and " + d.q + " may go first, but it was moved already: the overlaps are cyclic"
                            : "tests 1–5 fail both ways: each may hide part of the other";
                info.narration = pair + reason + ". Split " + s.split_name + " by " + cut_text(s.split_cut) + " into " +
                                 (made.empty() ? "nothing that covers a pixel centre" : made) +
                                 " (a centre goes to the side where it lies); the tests restart. List: " +
                                 names_of(s.list) + ".";
                info.math = s.split_name + " \\to " + (made.empty() ? "\\emptyset" : made);
            }
            info.vars.push_back({"P", d.p});
            info.vars.push_back({"Q", d.q});
            info.vars.push_back({"test", test_code(d)});
            break;
        }
        case Phase::Settle: {
            info.event = "settle";
            info.line = kLineSettle;
            std::string order;
            for (const Piece& p : s.settled) order += (order.empty() ? "" : ", ") + p.name;
            info.narration = s.name + " can hide none of the polygons left, so it is settled: drawing order so far " +
                             order + "." + (s.list.empty() ? " The list is empty: now draw." : " List: " + names_of(s.list) + ".");
            info.vars.push_back({"P", s.name});
            break;
        }
        case Phase::Draw: {
            info.event = "draw";
            info.line = kLineDraw;
            info.narration = "Draw " + s.name + " (" + std::to_string(s.drawn) + " of " + std::to_string(s.settled.size()) +
                             "): its " + std::to_string(s.step_pixels) +
                             " pixel centres get its colour, overwriting whatever was drawn there before.";
            info.math = "\\text{pixels written} = " + std::to_string(s.step_pixels);
            info.vars.push_back({"drawn", s.name});
            break;
        }
        case Phase::Finish:
        case Phase::Done: {
            info.event = "done";
            info.line = kLineDone;
            long long shown = 0;
            for (int id : s.ids) shown += id >= 0;
            std::string order;
            for (const Piece& p : s.settled) order += (order.empty() ? "" : ", ") + p.name;
            info.narration = "Done: drawn back to front " + (order.empty() ? std::string("(nothing)") : order) + "; " +
                             std::to_string(s.pair_tests) + " pair tests, " + std::to_string(s.moves) + " moves, " +
                             std::to_string(s.splits) + " splits; " + std::to_string(shown) + " pixels show a polygon.";
            info.math = "\\text{pair tests} = " + std::to_string(s.pair_tests);
            break;
        }
    }
    info.vars.push_back({"list", names_of(s.list)});
    info.vars.push_back({"pair_tests", s.pair_tests});
    info.vars.push_back({"moves", s.moves});
    info.vars.push_back({"splits", s.splits});
}

void Painters::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [result and render] --------------------------------------------------------------------

Painters::Result Painters::result(const State& s) {
    Result r;
    r.width = s.in.scene.width, r.height = s.in.scene.height;
    r.ids = s.ids;
    if (r.ids.empty()) r.ids.assign(static_cast<std::size_t>(r.width * r.height), -1);
    for (std::size_t k = 0; k < s.drawn; ++k) {
        r.order.push_back(s.settled[k].parent);
        r.names.push_back(s.settled[k].name);
    }
    r.decisions = s.decisions;
    r.pair_tests = s.pair_tests, r.moves = s.moves, r.splits = s.splits;
    return r;
}

[[gnu::flatten]] Painters::Result Painters::render(const Input& in) {
    const auto& scene = in.scene;
    std::vector<Plane> planes;
    std::vector<std::vector<PixelSpan>> spans;
    for (const auto& p : scene.polygons) {
        planes.push_back(hsr::plane_of(p));
        spans.push_back(hsr::polygon_spans(p, scene.width, scene.height));
    }
    const Ctx c{scene, planes, spans, scene_margin(scene)};
    Result res;
    res.width = scene.width, res.height = scene.height;
    res.ids.assign(static_cast<std::size_t>(scene.width * scene.height), -1);
    std::vector<Piece> list = sorted_list(c), settled;
    Decision d;
    bool cycle = false;
    std::string split_name;
    Cut cut;
    std::vector<std::string> made;
    Report r{d, cycle, split_name, cut, made};
    Counters n;
    while (!list.empty()) {
        for (std::size_t q = next_overlap(list, 1); q < list.size();) {
            q = resolve_pair(c, list, q, n, r);
            res.decisions.push_back(d);
        }
        settled.push_back(std::move(list[0]));
        list.erase(list.begin());
        for (Piece& p : list) p.marked = false;
    }
    for (const Piece& p : settled) {
        paint(c, p, res.ids);
        res.order.push_back(p.parent);
        res.names.push_back(p.name);
    }
    res.pair_tests = n.pair_tests, res.moves = n.moves, res.splits = n.splits;
    return res;
}

}  // namespace cg
