// Sutherland-Hodgman's JSON:
//   input  {"window": [[x, y], ...], "polygon": [[x, y], ...]}
//   result {"polygon": [[x, y], ...],  in the order the algorithm produces it; [] when nothing
//                                      of the polygon is inside the window
//           "after_edge": [[[x, y], ...], ...]}  the output list of each window edge processed,
//                                      in order (fewer than the window's edges when one came out
//                                      empty); the last equals "polygon"
#include "clipping/sutherland_hodgman.hpp"
#include "io/registry.hpp"

namespace cg {

namespace {

json points_json(const std::vector<glm::dvec2>& points, json (*point)(glm::dvec2)) {
    json a = json::array();
    for (const glm::dvec2& p : points) a.push_back(point(p));
    return a;
}

}  // namespace

template <>
struct JsonIo<SutherlandHodgman> {
    static SutherlandHodgman::Input input(const json& j) {
        Reader r(j);
        r.only({"window", "polygon"});
        SutherlandHodgman::Input in;
        in.window = r.points2("window");
        in.polygon = r.points2("polygon");
        return in;
    }

    // Integral coordinates print as integers ([2, 1], not [2.0, 1.0]), as a student writes them.
    static json input_json(const SutherlandHodgman::Input& in) {
        return json{{"window", points_json(in.window, nice_point)},
                    {"polygon", points_json(in.polygon, nice_point)}};
    }

    static json result(const SutherlandHodgman::Result& r) {
        json after_edge = json::array();
        for (const auto& list : r.after_edge) after_edge.push_back(points_json(list, to_json));
        return json{{"polygon", points_json(r.polygon, to_json)},
                    {"after_edge", std::move(after_edge)}};
    }

    static json example() {
        // A triangle poking out of the square through its right and top edges: all four cases
        // occur, and the result is (2, 4), (2, 1), (4, 2), (4, 4).
        return json{{"window", {{0, 0}, {4, 0}, {4, 4}, {0, 4}}},
                    {"polygon", {{2, 1}, {6, 3}, {2, 6}}}};
    }
};

Algorithm sutherland_hodgman_algorithm() {
    return make_algorithm<SutherlandHodgman>([](const SutherlandHodgman::Input& in) {
        return SutherlandHodgman::clip(in.window, in.polygon);
    });
}

}  // namespace cg
