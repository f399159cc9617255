// The painter's algorithm's JSON:
//   input  {"width", "height", "polygons": [{"vertices": [[x, y, z], …], "color": [r, g, b]}, …]}
//   result {"ids": H rows of W, "order": parents back to front, "names": the same by name (pieces
//           "P2a", "P2b", …), "pairs": [[P, Q], …] every pair tested, "tests": what decided each
//           ("1" … "6", "same", "move", "split"), "pair_tests", "moves", "splits"}
#include "hsr/painters.hpp"
#include "hsr/screen_scene_json.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<Painters> {
    static Painters::Input input(const json& j) {
        Reader r(j);
        r.only({"width", "height", "polygons"});
        return {hsr::read_screen_scene(r)};
    }

    static json input_json(const Painters::Input& in) {
        json j = json::object();
        hsr::write_screen_scene(in.scene, j);
        return j;
    }

    static json result(const Painters::Result& r) {
        json pairs = json::array(), tests = json::array();
        for (const auto& d : r.decisions) {
            pairs.push_back(json::array({d.p, d.q}));
            tests.push_back(Painters::test_code(d));
        }
        return json{{"ids", hsr::ids_json(r.ids, r.width, r.height)},
                    {"order", r.order},
                    {"names", r.names},
                    {"pairs", std::move(pairs)},
                    {"tests", std::move(tests)},
                    {"pair_tests", r.pair_tests},
                    {"moves", r.moves},
                    {"splits", r.splits}};
    }

    static json example() {
        // Three strips woven over each other — P0 over P1, P1 over P2, P2 over P0: a cycle, resolved
        // by splitting P2 — in front of a backdrop P3.
        return json{{"width", 12},
                    {"height", 12},
                    {"polygons",
                     {{{"vertices", {{0, 1, 6}, {10, 1, 1}, {10, 3, 1}, {0, 3, 6}}}, {"color", {0.85, 0.25, 0.2}}},
                      {{"vertices", {{7, 0, 3}, {9, 0, 3}, {9, 11, 8.5}, {7, 11, 8.5}}}, {"color", {0.2, 0.5, 0.9}}},
                      {{"vertices", {{1, 0, -4}, {3, 0, -4}, {11, 10, 16}, {9, 10, 16}}}, {"color", {0.3, 0.75, 0.3}}},
                      {{"vertices", {{0, 0, 20}, {12, 0, 20}, {12, 12, 20}, {0, 12, 20}}}, {"color", {0.85, 0.85, 0.8}}}}}};
    }
};

Algorithm painters_algorithm() {
    return make_algorithm<Painters>(
        [](const Painters::Input& in) { return Painters::render(in); });
}

}  // namespace cg
