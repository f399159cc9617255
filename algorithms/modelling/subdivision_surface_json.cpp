// Subdivision surfaces, JSON:
//   input  {"vertices": [[x, y, z], …],
//           "faces": [[i, j, k], [i, j, k, l], …] (indices into vertices: triangles for Loop,
//                    triangles and quads for Catmull–Clark),
//           "scheme": "loop" | "catmull-clark",
//           "levels": L (0 to 5; the faces after the last level at most 50,000),
//           "focus": {"vertex": v} | {"face": f} | {"edge": [a, b]} (optional: the point whose
//                    rule the narration and the picture show; the exam asks for it)}
//   result {"vertices", "faces": the mesh after the last level (old vertices first, then the
//           face points, then the edge points),
//           "counts": [[V, E, F] before level 1, after level 1, …], "euler": V − E + F,
//           "level1": {"edges": [[a, b], …] (the input's edges, numbered as the steps number
//                     them), "face_points", "edge_points", "vertex_points" (level 1's new points)},
//           "focus_point": level 1's point for the focus (when there is one)}
#include "io/registry.hpp"
#include "modelling/subdivision_surface.hpp"

namespace cg {

namespace subdivision_json {

int index_at(const json& v, const std::string& field, std::size_t count) {
    if (!v.is_number_integer())
        throw InputError(field, "must be an index (an integer), got " + describe(v));
    if (v.is_number_unsigned() ? v.get<std::uint64_t>() >= count
                               : (v.get<long long>() < 0 || v.get<long long>() >= (long long)count))
        throw InputError(field, "index " + v.dump() + " is out of range (" +
                                    (count == 0 ? std::string("there is nothing to index")
                                                : "0 to " + std::to_string(count - 1)) +
                                    ")");
    return int(v.get<long long>());
}

json points(const std::vector<glm::dvec3>& p) {
    json out = json::array();
    for (const auto& q : p) out.push_back(to_json(q));
    return out;
}

}  // namespace subdivision_json

template <>
struct JsonIo<SubdivisionSurface> {
    using S = SubdivisionSurface;

    static S::Input input(const json& j) {
        Reader r(j);
        r.only({"vertices", "faces", "scheme", "levels", "focus"});
        S::Input in;
        in.mesh.vertices = r.points3("vertices");
        const std::size_t nv = in.mesh.vertices.size();
        const json& faces = r.get("faces");
        const std::string ff = r.field("faces");
        if (!faces.is_array())
            throw InputError(ff, "must be a list of faces [i, j, k(, l)], got " + describe(faces));
        if ((long long)faces.size() > S::kMaxFaces)
            throw InputError(ff, "has " + std::to_string(faces.size()) + " faces; at most " +
                                     std::to_string(S::kMaxFaces));
        for (std::size_t k = 0; k < faces.size(); ++k) {
            const std::string f = element(ff, k);
            if (!faces[k].is_array())
                throw InputError(f, "must be a face, a list of 3 or 4 vertex indices, got " +
                                        describe(faces[k]));
            if (faces[k].size() < 3 || faces[k].size() > 4)
                throw InputError(f, "must be a triangle or a quad (3 or 4 vertex indices), got " +
                                        std::to_string(faces[k].size()));
            std::vector<int> face;
            for (std::size_t i = 0; i < faces[k].size(); ++i)
                face.push_back(subdivision_json::index_at(faces[k][i], element(f, i), nv));
            in.mesh.faces.push_back(std::move(face));
        }
        const std::string scheme = r.string("scheme");
        if (scheme == "loop")
            in.scheme = S::Scheme::Loop;
        else if (scheme == "catmull-clark")
            in.scheme = S::Scheme::CatmullClark;
        else
            throw InputError(r.field("scheme"),
                             "must be \"loop\" or \"catmull-clark\", got \"" + scheme + "\"");
        in.levels = int(r.integer("levels", 0, S::kMaxLevels,
                                  "0 to " + std::to_string(S::kMaxLevels)));
        if (r.has("focus")) {
            const Reader focus = r.object("focus");
            focus.only({"vertex", "face", "edge"});
            const int given = int(focus.has("vertex")) + int(focus.has("face")) + int(focus.has("edge"));
            if (given != 1)
                throw InputError(r.field("focus"),
                                 "must name one of \"vertex\", \"face\" or \"edge\"");
            if (focus.has("vertex")) {
                in.focus = S::FocusKind::Vertex;
                in.focus_a = subdivision_json::index_at(focus.get("vertex"), focus.field("vertex"), nv);
            } else if (focus.has("face")) {
                in.focus = S::FocusKind::Face;
                in.focus_a = subdivision_json::index_at(focus.get("face"), focus.field("face"),
                                                        in.mesh.faces.size());
            } else {
                const json& e = focus.get("edge");
                if (!e.is_array() || e.size() != 2)
                    throw InputError(focus.field("edge"),
                                     "must be an edge, two vertex indices [a, b], got " + describe(e));
                in.focus = S::FocusKind::Edge;
                in.focus_a = subdivision_json::index_at(e[0], element(focus.field("edge"), 0), nv);
                in.focus_b = subdivision_json::index_at(e[1], element(focus.field("edge"), 1), nv);
            }
        }
        return in;
    }

    static json input_json(const S::Input& in) {
        json vertices = json::array();
        for (const auto& p : in.mesh.vertices) vertices.push_back(nice_point(p));
        json j{{"vertices", vertices},
               {"faces", in.mesh.faces},
               {"scheme", S::scheme_id(in.scheme)},
               {"levels", in.levels}};
        switch (in.focus) {
            case S::FocusKind::Vertex: j["focus"] = {{"vertex", in.focus_a}}; break;
            case S::FocusKind::Face: j["focus"] = {{"face", in.focus_a}}; break;
            case S::FocusKind::Edge: j["focus"] = {{"edge", {in.focus_a, in.focus_b}}}; break;
            case S::FocusKind::None: break;
        }
        return j;
    }

    static json result(const S::Result& r) {
        json counts = json::array();
        for (const auto& c : r.counts) counts.push_back({c.V, c.E, c.F});
        json j{{"vertices", subdivision_json::points(r.mesh.vertices)},
               {"faces", r.mesh.faces},
               {"counts", counts},
               {"euler", r.counts.back().euler()},
               {"level1",
                {{"edges", r.first_topology.edges},
                 {"face_points", subdivision_json::points(r.first.face)},
                 {"edge_points", subdivision_json::points(r.first.edge)},
                 {"vertex_points", subdivision_json::points(r.first.vertex)}}}};
        if (r.has_focus) j["focus_point"] = to_json(r.focus_point);
        return j;
    }

    static json example() {
        // The cube [−1, 1]³ under one level of Catmull–Clark: the corner V6 = (1, 1, 1), of
        // valence 3, moves to (5/9, 5/9, 5/9).
        return parse_json(R"({
          "vertices": [[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                       [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]],
          "faces": [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [1, 2, 6, 5],
                    [0, 4, 7, 3]],
          "scheme": "catmull-clark", "levels": 1, "focus": {"vertex": 6}})");
    }
};

Algorithm subdivision_surface_algorithm() {
    return make_algorithm<SubdivisionSurface>(
        [](const SubdivisionSurface::Input& in) { return SubdivisionSurface::compute(in); });
}

}  // namespace cg
