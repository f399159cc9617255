// The z-buffer's JSON:
//   input  {"width", "height", "polygons": [{"vertices": [[x, y, z], …], "color": [r, g, b]}, …],
//           "granularity": "polygon" | "pixel" (optional, default "polygon")}
//   result {"ids": H rows of W, "depth": H rows of W (null for background), "compares", "writes"}
#include <cmath>

#include "hsr/screen_scene_json.hpp"
#include "hsr/z_buffer.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<ZBuffer> {
    static ZBuffer::Input input(const json& j) {
        Reader r(j);
        r.only({"width", "height", "polygons", "granularity"});
        ZBuffer::Input in;
        in.scene = hsr::read_screen_scene(r);
        if (r.has("granularity")) {
            const std::string g = r.string("granularity");
            if (g == "polygon") in.granularity = ZBuffer::Granularity::Polygon;
            else if (g == "pixel") in.granularity = ZBuffer::Granularity::Pixel;
            else
                throw InputError(r.field("granularity"),
                                 "must be \"polygon\" (one step per polygon) or \"pixel\" (one step "
                                 "per pixel), got \"" + g + "\"");
        }
        return in;
    }

    static json input_json(const ZBuffer::Input& in) {
        json j = json::object();
        hsr::write_screen_scene(in.scene, j);
        if (in.granularity == ZBuffer::Granularity::Pixel) j["granularity"] = "pixel";
        return j;
    }

    static json result(const ZBuffer::Result& r) {
        json depth = json::array();
        for (long long j = 0; j < r.height; ++j) {
            json row = json::array();
            for (long long i = 0; i < r.width; ++i) {
                const double z = r.depth[static_cast<std::size_t>(j * r.width + i)];
                row.push_back(std::isinf(z) ? json(nullptr) : json(z));
            }
            depth.push_back(std::move(row));
        }
        return json{{"ids", hsr::ids_json(r.ids, r.width, r.height)},
                    {"depth", std::move(depth)},
                    {"compares", r.compares},
                    {"writes", r.writes}};
    }

    static json example() {
        // Two overlapping squares: the tilted one passes in front of the flat one on the right.
        return json{{"width", 8},
                    {"height", 6},
                    {"polygons",
                     {{{"vertices", {{1, 1, 5}, {5, 1, 5}, {5, 5, 5}, {1, 5, 5}}}, {"color", {0.9, 0.3, 0.2}}},
                      {{"vertices", {{3, 0, 8}, {7, 0, 2}, {7, 4, 2}, {3, 4, 8}}}, {"color", {0.2, 0.5, 0.9}}}}}};
    }
};

Algorithm z_buffer_algorithm() {
    return make_algorithm<ZBuffer>(
        [](const ZBuffer::Input& in) { return ZBuffer::render(in); });
}

}  // namespace cg
