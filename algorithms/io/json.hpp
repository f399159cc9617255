// Reading inputs from JSON with errors that name the field, and writing results and traces.
//
// Inputs are strict: every required field must be present with the right type, numbers must
// be finite, and unknown fields are refused (a typo such as "p_0" would otherwise be
// silently ignored). Errors are InputError with the path of the field as the user wrote it:
// "window.xmin", "p0[1]", "polygon[3][0]".
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <glm/fwd.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "core/step.hpp"

namespace cg {

// Insertion-ordered, so results and traces list their fields in the documented order.
using json = nlohmann::ordered_json;

// Parses text as JSON; a syntax error becomes an InputError naming line and column.
json parse_json(const std::string& text);

// A view of one JSON object at a path, reading its fields.
class Reader {
public:
    Reader(const json& j, std::string path = "");  // throws unless j is an object

    bool has(const char* key) const { return j_.contains(key); }
    const json& get(const char* key) const;  // throws if missing
    std::string field(const char* key) const;  // the path of key: "window.xmin"

    double number(const char* key) const;  // finite number
    std::optional<double> optional_number(const char* key) const;
    long long integer(const char* key) const;
    // An integer in [lo, hi]; otherwise "must be <why> (got v)".
    long long integer(const char* key, long long lo, long long hi, const std::string& why) const;
    bool boolean(const char* key) const;
    std::string string(const char* key) const;
    glm::dvec2 point2(const char* key) const;
    glm::dvec3 point3(const char* key) const;
    std::vector<glm::dvec2> points2(const char* key) const;
    std::vector<glm::dvec3> points3(const char* key) const;
    glm::dquat quat(const char* key) const;  // [w, x, y, z], any quaternion
    Reader object(const char* key) const;

    // Refuses any field not in `allowed`.
    void only(std::initializer_list<const char*> allowed) const;

    const json& value() const { return j_; }
    const std::string& path() const { return path_; }

private:
    const json& j_;
    std::string path_;
};

// Value readers for array elements and the like; `field` names the value in errors.
double as_number(const json& v, const std::string& field);
glm::dvec2 as_point2(const json& v, const std::string& field);
glm::dvec3 as_point3(const json& v, const std::string& field);
// The path of element i of the list at `base`: "objects[3]".
std::string element(const std::string& base, std::size_t i);
std::string describe(const json& v);  // "a string (\"abc\")", for error messages

// Pretty-printed JSON that stays readable: objects one field per line, lists of numbers (points,
// matrix rows) on one line.
std::string pretty(const json& j, int indent = 2);
// A number for an input file: integral values as integers ("1", not "1.0").
json nice_number(double x);
json nice_point(glm::dvec2 p);
json nice_point(glm::dvec3 p);
json nice_quat(const glm::dquat& q);  // [w, x, y, z]
// A matrix as the list of its rows (glm stores m[column][row]); `nice` writes the entries with
// nice_number, for input files.
json matrix_rows(const glm::dmat3& m, bool nice = false);
json matrix_rows(const glm::dmat4& m, bool nice = false);

json to_json(const Value& v);
json to_json(glm::dvec2 p);
json to_json(glm::dvec3 p);
json quat_json(const glm::dquat& q);  // [w, x, y, z]
// One line of a trace: {"index", "event", "line", "narration", "math", "variables"}.
json step_to_json(std::size_t index, const StepInfo& info);

}  // namespace cg
