// Sutherland-Hodgman's JSON:
//   input  {"window": [[x, y], ...], "polygon": [[x, y], ...]}
//   result {"polygon": [[x, y], ...]}  in the order the algorithm produces it; [] when nothing
//          of the polygon is inside the window
#include "clipping/sutherland_hodgman.hpp"
#include "io/registry.hpp"

namespace cg {

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

    static json input_json(const SutherlandHodgman::Input& in) {
        json window = json::array(), polygon = json::array();
        for (const glm::dvec2& p : in.window) window.push_back(to_json(p));
        for (const glm::dvec2& p : in.polygon) polygon.push_back(to_json(p));
        return json{{"window", std::move(window)}, {"polygon", std::move(polygon)}};
    }

    static json result(const SutherlandHodgman::Result& r) {
        json polygon = json::array();
        for (const glm::dvec2& p : r.polygon) polygon.push_back(to_json(p));
        return json{{"polygon", std::move(polygon)}};
    }

    static json example() {
        // A triangle poking out of the square through its right and top edges: all four cases
        // occur, and the result is (2, 4), (2, 1), (4, 2), (4, 4).
        return json{{"window", {{0, 0}, {4, 0}, {4, 4}, {0, 4}}},
                    {"polygon", {{2, 1}, {6, 3}, {2, 6}}}};
    }
};

Algorithm sutherland_hodgman_algorithm() { return make_algorithm<SutherlandHodgman>(); }

}  // namespace cg
