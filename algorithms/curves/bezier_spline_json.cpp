// The Bézier spline's JSON; the input is exactly one of
//   {"segments": [[P0, P1, P2, P3], …]}                       cubic segments as given
//   {"hermite": {"points": [[x, y], …], "tangents": [[x, y], …]}}   points and derivatives
//   {"catmull_rom": {"points": [[x, y], …]}}                   points only
// result {"segments": [[P0, P1, P2, P3], …],
//         "joints": [{"c0", "c1", "g1", "beta": β | null, "c2"}, …]  (joint j: segments j, j + 1)
//         "tangents": [[x, y], …] | null}                        (the v_i used; null for segments)
#include "curves/bezier_spline.hpp"
#include "curves/curves_json.hpp"
#include "io/registry.hpp"

namespace cg {

namespace {

std::vector<glm::dvec2> points2(const Reader& r, const char* key) {
    int dim = 2;
    std::vector<glm::dvec2> out;
    for (const glm::dvec3& p : curves::read_points(r, key, dim, false)) out.push_back({p.x, p.y});
    return out;
}

json points_json(const std::vector<glm::dvec2>& ps, bool nice) {
    json out = json::array();
    for (glm::dvec2 p : ps) out.push_back(nice ? nice_point(p) : to_json(p));
    return out;
}

json segments_json(const std::vector<BezierSpline::Segment>& segments, bool nice) {
    json out = json::array();
    for (const auto& seg : segments) out.push_back(points_json({seg.begin(), seg.end()}, nice));
    return out;
}

}  // namespace

template <>
struct JsonIo<BezierSpline> {
    static BezierSpline::Input input(const json& j) {
        Reader r(j);
        r.only({"segments", "hermite", "catmull_rom"});
        const int given = r.has("segments") + r.has("hermite") + r.has("catmull_rom");
        if (given == 0)
            throw InputError("",
                             "the input needs one of \"segments\", \"hermite\" or \"catmull_rom\"");
        BezierSpline::Input in;
        if (r.has("segments")) {
            if (given > 1)
                throw InputError(r.has("hermite") ? "hermite" : "catmull_rom",
                                 "give only one of \"segments\", \"hermite\" and \"catmull_rom\"");
            in.mode = BezierSpline::Mode::Segments;
            const json& v = r.get("segments");
            if (!v.is_array())
                throw InputError("segments", "must be a list of segments, got " + describe(v));
            for (std::size_t i = 0; i < v.size(); ++i) {
                const std::string field = "segments[" + std::to_string(i) + "]";
                if (!v[i].is_array() || v[i].size() != 4)
                    throw InputError(field,
                                     "must be 4 points [P0, P1, P2, P3], got " + describe(v[i]));
                BezierSpline::Segment seg;
                for (std::size_t c = 0; c < 4; ++c)
                    seg[c] = as_point2(v[i][c], field + "[" + std::to_string(c) + "]");
                in.segments.push_back(seg);
            }
        } else if (r.has("hermite")) {
            if (given > 1)
                throw InputError("catmull_rom",
                                 "give only one of \"segments\", \"hermite\" and \"catmull_rom\"");
            in.mode = BezierSpline::Mode::Hermite;
            Reader h = r.object("hermite");
            h.only({"points", "tangents"});
            in.points = points2(h, "points");
            in.tangents = points2(h, "tangents");
        } else {
            in.mode = BezierSpline::Mode::CatmullRom;
            Reader c = r.object("catmull_rom");
            c.only({"points"});
            in.points = points2(c, "points");
        }
        return in;
    }

    static json input_json(const BezierSpline::Input& in) {
        switch (in.mode) {
            case BezierSpline::Mode::Segments:
                return json{{"segments", segments_json(in.segments, true)}};
            case BezierSpline::Mode::Hermite:
                return json{{"hermite",
                             {{"points", points_json(in.points, true)},
                              {"tangents", points_json(in.tangents, true)}}}};
            case BezierSpline::Mode::CatmullRom:
                break;
        }
        return json{{"catmull_rom", {{"points", points_json(in.points, true)}}}};
    }

    static json result(const BezierSpline::Result& r) {
        json joints = json::array();
        for (const auto& j : r.joints)
            joints.push_back(json{{"c0", j.c0},
                                  {"c1", j.c1},
                                  {"g1", j.g1},
                                  {"beta", j.beta ? json(*j.beta) : json(nullptr)},
                                  {"c2", j.c2}});
        return json{{"segments", segments_json(r.segments, false)},
                    {"joints", std::move(joints)},
                    {"tangents", r.tangents ? points_json(*r.tangents, false) : json(nullptr)}};
    }

    static json example() {
        // Three cubics: a C2 joint (the A-frame closes) and a G1 joint with β = 2.
        return json{{"segments",
                     {{{0, 0}, {1, 2}, {3, 3}, {4, 3}},
                      {{4, 3}, {5, 3}, {5, 2}, {7, 1}},
                      {{7, 1}, {8, 0.5}, {9, 1}, {10, 3}}}}};
    }
};

Algorithm bezier_spline_algorithm() {
    return make_algorithm<BezierSpline>();
}

}  // namespace cg
