// JSON helpers shared by the curve algorithms' *_json.cpp files: points of either dimension.
//
// A list of control points is all [x, y] or all [x, y, z]; the first point decides, and a
// point of the other kind is refused by its index ("control_points[2]: must be a point
// [x, y] like control_points[0], got [1, 2, 3]"). In C++ such points are dvec3 with z = 0 in 2D.
#pragma once

#include <string>
#include <vector>

#include "io/json.hpp"

namespace cg::curves {

// Reads `key` as a list of points; `dim` is set to 2 or 3 (2 for an empty list). With
// allow_3d false, only [x, y] points are accepted.
inline std::vector<glm::dvec3> read_points(const Reader& r, const char* key, int& dim,
                                           bool allow_3d = true) {
    const json& v = r.get(key);
    const std::string field = r.field(key);
    if (!v.is_array()) throw InputError(field, "must be a list of points, got " + describe(v));
    dim = 2;
    if (!v.empty() && v[0].is_array() && v[0].size() == 3 && allow_3d) dim = 3;
    std::vector<glm::dvec3> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string at = field + "[" + std::to_string(i) + "]";
        const bool matches = v[i].is_array() && v[i].size() == static_cast<std::size_t>(dim);
        if (!matches && i > 0 && v[i].is_array() &&
            (v[i].size() == 2 || (v[i].size() == 3 && allow_3d)))
            throw InputError(at, std::string("must be a point ") +
                                     (dim == 3 ? "[x, y, z]" : "[x, y]") + " like " + field +
                                     "[0], got " + describe(v[i]));
        if (dim == 3) {
            out.push_back(as_point3(v[i], at));
        } else {
            const glm::dvec2 p = as_point2(v[i], at);
            out.push_back({p.x, p.y, 0});
        }
    }
    return out;
}

// A list of numbers, each finite.
inline std::vector<double> read_numbers(const Reader& r, const char* key) {
    const json& v = r.get(key);
    const std::string field = r.field(key);
    if (!v.is_array()) throw InputError(field, "must be a list of numbers, got " + describe(v));
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i)
        out.push_back(as_number(v[i], field + "[" + std::to_string(i) + "]"));
    return out;
}

// A point as the result writes it: [x, y] or [x, y, z].
inline json point_json(glm::dvec3 p, int dim) {
    return dim == 3 ? to_json(p) : to_json(glm::dvec2(p.x, p.y));
}
inline json points_json(const std::vector<glm::dvec3>& ps, int dim) {
    json out = json::array();
    for (const glm::dvec3& p : ps) out.push_back(point_json(p, dim));
    return out;
}
// The same for an input file: whole numbers as integers.
inline json nice_points(const std::vector<glm::dvec3>& ps, int dim) {
    json out = json::array();
    for (const glm::dvec3& p : ps)
        out.push_back(dim == 3 ? nice_point(p) : nice_point(glm::dvec2(p.x, p.y)));
    return out;
}

}  // namespace cg::curves
