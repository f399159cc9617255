// Warnock's JSON:
//   input  {"width", "height", "polygons": [{"vertices": [[x, y, z], …], "color": [r, g, b]}, …]}
//   result {"ids": H rows of W (row 0 the bottom, −1 background), "areas", "classifications"}
#include "hsr/screen_scene_json.hpp"
#include "hsr/warnock.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<Warnock> {
    static Warnock::Input input(const json& j) {
        Reader r(j);
        r.only({"width", "height", "polygons"});
        return {hsr::read_screen_scene(r)};
    }

    static json input_json(const Warnock::Input& in) {
        json j = json::object();
        hsr::write_screen_scene(in.scene, j);
        return j;
    }

    static json result(const Warnock::Result& r) {
        return json{{"ids", hsr::ids_json(r.ids, r.width, r.height)},
                    {"areas", r.areas},
                    {"classifications", r.classifications}};
    }

    static json example() {
        // The course's kind of picture: an 8 × 8 screen, a far polygon surrounding it all, and two
        // nearer ones overlapping in the middle.
        return json{{"width", 8},
                    {"height", 8},
                    {"polygons",
                     {{{"vertices", {{-1, -1, 9}, {9, -1, 9}, {9, 9, 9}, {-1, 9, 9}}}, {"color", {0.8, 0.8, 0.6}}},
                      {{"vertices", {{1, 1, 4}, {6, 1, 4}, {6, 5, 4}, {1, 5, 4}}}, {"color", {0.85, 0.25, 0.2}}},
                      {{"vertices", {{3, 2, 2}, {7, 6, 2}, {3, 7, 6}}}, {"color", {0.2, 0.5, 0.9}}}}}};
    }
};

Algorithm warnock_algorithm() {
    return make_algorithm<Warnock>(
        [](const Warnock::Input& in) { return Warnock::render(in); });
}

}  // namespace cg
