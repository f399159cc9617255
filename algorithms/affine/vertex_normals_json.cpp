// Vertex normals, JSON:
//   input  {"vertices": [[x, y, z], …] (at least one),
//           "faces": [[i, j, k, …], …] (indices into vertices, at least 3 each, counter-clockwise
//                    seen from outside),
//           "focus": {"vertex": v, "weighting": "unweighted" | "area" | "angle"} (optional: the
//                    normal the exam asks for, labelled with its numbers in the picture)}
//   result {"face_normals": [n_f or null (zero area), …], "face_areas": [A_f, …],
//           "corner_angles_deg": [[θ at each corner, …], …] (the corners after repeats in a row
//           are dropped), "vertex_normals": {"unweighted": [n_V or null, …], "area": […],
//           "angle": […]}, "undefined_faces": [k, …] (zero area),
//           "isolated_vertices": [v, …] (no face with area)}
#include <cmath>

#include "affine/vertex_normals.hpp"
#include "io/registry.hpp"

namespace cg {

namespace {

long long index_at(const json& v, const std::string& field) {
    if (v.is_number_integer()) {
        if (v.is_number_unsigned() &&
            v.get<std::uint64_t>() > std::uint64_t(std::numeric_limits<long long>::max()))
            throw InputError(field, "is too large, got " + describe(v));
        return v.get<long long>();
    }
    if (v.is_number_float()) {
        const double d = v.get<double>();
        if (std::isfinite(d) && d == std::floor(d) && std::fabs(d) < 9e15)
            return static_cast<long long>(d);
    }
    throw InputError(field, "must be a vertex index (an integer), got " + describe(v));
}

VertexNormals::Weighting weighting_of(const std::string& s, const std::string& field) {
    for (auto w : {VertexNormals::Weighting::Unweighted, VertexNormals::Weighting::Area,
                   VertexNormals::Weighting::Angle})
        if (s == VertexNormals::weighting_id(w)) return w;
    throw InputError(field, "must be \"unweighted\", \"area\" or \"angle\", got \"" + s + "\"");
}

json normal_or_null(const std::optional<glm::dvec3>& n) {
    return n ? to_json(*n) : json(nullptr);
}

}  // namespace

template <>
struct JsonIo<VertexNormals> {
    static VertexNormals::Input input(const json& j) {
        Reader r(j);
        r.only({"vertices", "faces", "focus"});
        VertexNormals::Input in;
        in.vertices = r.points3("vertices");
        const json& faces = r.get("faces");
        const std::string ff = r.field("faces");
        if (!faces.is_array())
            throw InputError(ff, "must be a list of faces [i, j, k, …], got " + describe(faces));
        for (std::size_t k = 0; k < faces.size(); ++k) {
            const std::string f = element(ff, k);
            if (!faces[k].is_array())
                throw InputError(f, "must be a face, a list of vertex indices [i, j, k, …], got " +
                                        describe(faces[k]));
            std::vector<long long> face;
            for (std::size_t i = 0; i < faces[k].size(); ++i)
                face.push_back(index_at(faces[k][i], element(f, i)));
            in.faces.push_back(std::move(face));
        }
        if (r.has("focus")) {
            const Reader focus = r.object("focus");
            focus.only({"vertex", "weighting"});
            in.has_focus = true;
            in.focus_vertex = focus.integer("vertex");
            in.focus_weighting = weighting_of(focus.string("weighting"), focus.field("weighting"));
        }
        return in;
    }

    static json input_json(const VertexNormals::Input& in) {
        json vertices = json::array();
        for (const auto& p : in.vertices) vertices.push_back(nice_point(p));
        json j{{"vertices", vertices}, {"faces", in.faces}};
        if (in.has_focus)
            j["focus"] = {{"vertex", in.focus_vertex},
                          {"weighting", VertexNormals::weighting_id(in.focus_weighting)}};
        return j;
    }

    static json result(const VertexNormals::Result& r) {
        json normals = json::array(), areas = json::array(), angles = json::array(),
             undefined = json::array(), isolated = json::array();
        for (std::size_t k = 0; k < r.faces.size(); ++k) {
            const auto& f = r.faces[k];
            normals.push_back(f.defined ? to_json(f.normal) : json(nullptr));
            areas.push_back(f.area);
            json a = json::array();
            for (double t : f.angles) a.push_back(t * (180.0 / 3.14159265358979323846));
            angles.push_back(a);
            if (!f.defined) undefined.push_back(k);
        }
        json by[3] = {json::array(), json::array(), json::array()};
        for (std::size_t v = 0; v < r.vertices.size(); ++v) {
            const auto& vs = r.vertices[v];
            for (int w = 0; w < 3; ++w) by[w].push_back(normal_or_null(vs.normal[w]));
            if (vs.faces.empty()) isolated.push_back(v);
        }
        return json{{"face_normals", normals},
                    {"face_areas", areas},
                    {"corner_angles_deg", angles},
                    {"vertex_normals", {{"unweighted", by[0]}, {"area", by[1]}, {"angle", by[2]}}},
                    {"undefined_faces", undefined},
                    {"isolated_vertices", isolated}};
    }

    static json example() {
        // The long thin face: V0 is a corner of a square half (area 2, a right angle there) and
        // of a sliver along the y axis (area 1/2, about 176° there). Area weighting follows the
        // big face, angle weighting the sliver, the plain average lies between.
        return parse_json(R"({
            "vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, -8, 0.5]],
            "faces": [[0, 1, 2], [0, 2, 3]]})");
    }
};

Algorithm vertex_normals_algorithm() {
    return make_algorithm<VertexNormals>(
        [](const VertexNormals::Input& in) { return VertexNormals::compute(in); });
}

}  // namespace cg
