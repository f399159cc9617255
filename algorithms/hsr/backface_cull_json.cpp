// Back-face culling's JSON:
//   input  {"vertices": [[x, y, z], …], "faces": [[i, j, k, …], …], and exactly one of
//           "eye": [x, y, z] (perspective: V = P_0 − eye) or "view_dir": [x, y, z] (parallel)}
//   result {"culled": [bool per face], "normals": [[x, y, z] unit, …], "dots": [N̂·V, …]}
#include "hsr/backface_cull.hpp"
#include "io/registry.hpp"

namespace cg {

template <>
struct JsonIo<BackfaceCull> {
    static BackfaceCull::Input input(const json& j) {
        Reader r(j);
        r.only({"vertices", "faces", "eye", "view_dir"});
        BackfaceCull::Input in;
        in.vertices = r.points3("vertices");
        const json& faces = r.get("faces");
        if (!faces.is_array())
            throw InputError(r.field("faces"), "must be a list of faces, got " + describe(faces));
        for (std::size_t k = 0; k < faces.size(); ++k) {
            const std::string field = r.field("faces") + "[" + std::to_string(k) + "]";
            if (!faces[k].is_array())
                throw InputError(field,
                                 "must be a list of vertex indices, got " + describe(faces[k]));
            std::vector<int> f;
            for (std::size_t i = 0; i < faces[k].size(); ++i) {
                const json& v = faces[k][i];
                if (!v.is_number_integer() || v.get<long long>() < -1'000'000'000 ||
                    v.get<long long>() > 1'000'000'000)
                    throw InputError(field + "[" + std::to_string(i) + "]",
                                     "must be a vertex index (an integer), got " + describe(v));
                f.push_back(static_cast<int>(v.get<long long>()));
            }
            in.faces.push_back(std::move(f));
        }
        const bool eye = r.has("eye"), dir = r.has("view_dir");
        if (eye == dir)
            throw InputError(
                eye ? r.field("view_dir") : r.field("eye"),
                eye ? "give either \"eye\" (perspective) or \"view_dir\" (parallel), not both"
                    : "missing: give \"eye\": [x, y, z] (perspective) or \"view_dir\": [x, y, z] "
                      "(parallel)");
        in.perspective = eye;
        if (eye)
            in.eye = r.point3("eye");
        else
            in.view_dir = r.point3("view_dir");
        return in;
    }

    static json input_json(const BackfaceCull::Input& in) {
        json j = json::object();
        json v = json::array();
        for (const auto& p : in.vertices) v.push_back(nice_point(p));
        j["vertices"] = std::move(v);
        j["faces"] = in.faces;
        if (in.perspective)
            j["eye"] = nice_point(in.eye);
        else
            j["view_dir"] = nice_point(in.view_dir);
        return j;
    }

    static json result(const BackfaceCull::Result& r) {
        json culled = json::array(), normals = json::array(), dots = json::array();
        for (bool c : r.culled) culled.push_back(c);
        for (const auto& n : r.normals) normals.push_back(to_json(n));
        for (double d : r.dots) dots.push_back(d);
        return json{{"culled", std::move(culled)},
                    {"normals", std::move(normals)},
                    {"dots", std::move(dots)}};
    }

    static json example() {
        // The unit cube seen from the front, above and to the right: three faces kept.
        return json{
            {"vertices",
             {{0, 0, 0},
              {1, 0, 0},
              {1, 1, 0},
              {0, 1, 0},
              {0, 0, 1},
              {1, 0, 1},
              {1, 1, 1},
              {0, 1, 1}}},
            {"faces",
             {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}}},
            {"eye", {3, 2.5, 4}}};
    }
};

Algorithm backface_cull_algorithm() {
    return make_algorithm<BackfaceCull>(
        [](const BackfaceCull::Input& in) { return BackfaceCull::cull(in); });
}

}  // namespace cg
