// The Bézier spline's JSON; the input is exactly one of
//   {"segments": [[P0, P1, P2, P3], …]}                       cubic segments as given
//   {"hermite": {"points": [[x, y], …], "tangents": [[x, y], …]}}   points and derivatives
//   {"catmull_rom": {"points": [[x, y], …], "closed": true|false (optional)}}   points only
// Points are all [x, y] or all [x, y, z] (segments, points and tangents alike; the first point
// decides, any other is refused naming it). "closed" belongs to catmull_rom only.
// result {"segments": [[P0, P1, P2, P3], …],
//         "joints": [{"c0", "c1", "g1", "beta": β | null, "c2"}, …]  (joint j: segments j, j + 1;
//                                                         closed: the last is segment N into 0)
//         "tangents": [[x, y], …] | null}                        (the v_i used; null for segments)
#include "curves/bezier_spline.hpp"
#include "curves/curves_json.hpp"
#include "io/registry.hpp"

namespace cg {

namespace {

// A point of a given dimension (decided by the input's first point, named `first`).
glm::dvec3 point_of(const json& v, const std::string& field, int dim, const std::string& first) {
    if (v.is_array() && (v.size() == 2 || v.size() == 3) && v.size() != std::size_t(dim))
        throw InputError(field, std::string("must be a point ") +
                                    (dim == 3 ? "[x, y, z]" : "[x, y]") + " like " + first +
                                    ": all points of a spline have the same dimension, got " +
                                    describe(v));
    if (dim == 3) return as_point3(v, field);
    const glm::dvec2 p = as_point2(v, field);
    return {p.x, p.y, 0};
}

json points_json(const std::vector<glm::dvec3>& ps, int dim, bool nice) {
    return nice ? curves::nice_points(ps, dim) : curves::points_json(ps, dim);
}

json segments_json(const std::vector<BezierSpline::Segment>& segments, int dim, bool nice) {
    json out = json::array();
    for (const auto& seg : segments)
        out.push_back(points_json({seg.begin(), seg.end()}, dim, nice));
    return out;
}

}  // namespace

template <>
struct JsonIo<BezierSpline> {
    static BezierSpline::Input input(const json& j) {
        Reader r(j);
        if (r.has("closed"))
            throw InputError("closed",
                             "belongs inside \"catmull_rom\" ({\"catmull_rom\": "
                             "{\"points\": [...], \"closed\": true}}): only a "
                             "Catmull-Rom spline is closed into a loop");
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
                if (i == 0 && v[0][0].is_array() && v[0][0].size() == 3) in.dim = 3;
                BezierSpline::Segment seg;
                for (std::size_t c = 0; c < 4; ++c)
                    seg[c] = point_of(v[i][c], field + "[" + std::to_string(c) + "]", in.dim,
                                      "segments[0][0]");
                in.segments.push_back(seg);
            }
        } else if (r.has("hermite")) {
            if (given > 1)
                throw InputError("catmull_rom",
                                 "give only one of \"segments\", \"hermite\" and \"catmull_rom\"");
            in.mode = BezierSpline::Mode::Hermite;
            Reader h = r.object("hermite");
            if (h.has("closed"))
                throw InputError(h.field("closed"),
                                 "applies to catmull_rom only: a Hermite spline joins its points "
                                 "with the tangents given; to close it, repeat P0 (and v0) at "
                                 "the end");
            h.only({"points", "tangents"});
            in.points = curves::read_points(h, "points", in.dim);
            int tangent_dim = in.dim;
            in.tangents = curves::read_points(h, "tangents", tangent_dim);
            if (!in.tangents.empty() && tangent_dim != in.dim)
                throw InputError(h.field("tangents") + "[0]",
                                 std::string("must be a vector ") +
                                     (in.dim == 3 ? "[x, y, z]" : "[x, y]") +
                                     " like hermite.points[0]: all points and tangents have "
                                     "the same dimension, got " +
                                     describe(h.get("tangents")[0]));
        } else {
            in.mode = BezierSpline::Mode::CatmullRom;
            Reader c = r.object("catmull_rom");
            c.only({"points", "closed"});
            in.points = curves::read_points(c, "points", in.dim);
            if (c.has("closed")) in.closed = c.boolean("closed");
        }
        return in;
    }

    static json input_json(const BezierSpline::Input& in) {
        switch (in.mode) {
            case BezierSpline::Mode::Segments:
                return json{{"segments", segments_json(in.segments, in.dim, true)}};
            case BezierSpline::Mode::Hermite:
                return json{{"hermite",
                             {{"points", points_json(in.points, in.dim, true)},
                              {"tangents", points_json(in.tangents, in.dim, true)}}}};
            case BezierSpline::Mode::CatmullRom:
                break;
        }
        json c{{"points", points_json(in.points, in.dim, true)}};
        if (in.closed) c["closed"] = true;
        return json{{"catmull_rom", std::move(c)}};
    }

    static json result(const BezierSpline::Result& r) {
        json joints = json::array();
        for (const auto& j : r.joints)
            joints.push_back(json{{"c0", j.c0},
                                  {"c1", j.c1},
                                  {"g1", j.g1},
                                  {"beta", j.beta ? json(*j.beta) : json(nullptr)},
                                  {"c2", j.c2}});
        return json{
            {"segments", segments_json(r.segments, r.dim, false)},
            {"joints", std::move(joints)},
            {"tangents", r.tangents ? points_json(*r.tangents, r.dim, false) : json(nullptr)}};
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
    return make_algorithm<BezierSpline>(NoPlain{
        "the stepped joint checks are the only implementation; the tests hold them to joints "
        "built with known continuity and to Hermite and Catmull-Rom interpolation"});
}

}  // namespace cg
