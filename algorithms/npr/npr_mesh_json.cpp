#include "npr/npr_mesh_json.hpp"

namespace cg::npr {

Mesh read_mesh(const Reader& r) {
    const bool listed = r.has("vertices") || r.has("faces"), made = r.has("shape");
    if (listed && made)
        throw InputError(r.field("shape"),
                         "give either \"vertices\" and \"faces\" or \"shape\" and \"segments\", not both");
    if (made) {
        const std::string shape = r.string("shape");
        if (shape != "sphere" && shape != "torus")
            throw InputError(r.field("shape"), "must be \"sphere\" or \"torus\" (got \"" + shape + "\")");
        const long long n = r.integer("segments", kMinSegments, kMaxSegments,
                                      "an even number of segments, 4 to 128");
        if (n % 2) throw InputError(r.field("segments"), "must be even (got " + std::to_string(n) + ")");
        return generate(shape, static_cast<int>(n));
    }
    if (r.has("segments"))
        throw InputError(r.field("segments"), "only goes with \"shape\"");
    Mesh m;
    m.vertices = r.points3("vertices");
    const json& faces = r.get("faces");
    if (!faces.is_array())
        throw InputError(r.field("faces"), "must be a list of faces, got " + describe(faces));
    if (faces.size() > kMaxFaces)
        throw InputError(r.field("faces"), "at most " + std::to_string(kMaxFaces) + " faces, got " +
                                               std::to_string(faces.size()));
    for (std::size_t k = 0; k < faces.size(); ++k) {
        const std::string field = element(r.field("faces"), k);
        if (!faces[k].is_array())
            throw InputError(field, "must be a list of vertex indices, got " + describe(faces[k]));
        std::vector<int> f;
        for (std::size_t i = 0; i < faces[k].size(); ++i) {
            const json& v = faces[k][i];
            if (!v.is_number_integer() || v.get<long long>() < -1'000'000'000 ||
                v.get<long long>() > 1'000'000'000)
                throw InputError(element(field, i), "must be a vertex index (an integer), got " + describe(v));
            f.push_back(static_cast<int>(v.get<long long>()));
        }
        m.faces.push_back(std::move(f));
    }
    return m;
}

void write_mesh(json& j, const Mesh& m) {
    if (!m.shape.empty()) {
        j["shape"] = m.shape;
        j["segments"] = m.segments;
        return;
    }
    json v = json::array();
    for (const auto& p : m.vertices) v.push_back(nice_point(p));
    j["vertices"] = std::move(v);
    j["faces"] = m.faces;
}

}  // namespace cg::npr
