// The shared harness of the degenerate-input tables (tests/robustness/tables/<id>.json).
//
// A table is one JSON file per registered algorithm:
//
//     {"algorithm": "liang-barsky",
//      "base": {...},              // optional: the input rows edit (default: the example)
//      "rows": [
//        {"name": "coincident endpoints", "kind": "coincident",
//         "set": {"/p1": [0, 2]},             // JSON pointer -> new value, applied to base
//         "expect": {"result": {"visible": true, "q0": [1, 2]}}},   // these fields, ±1e-9
//        {"name": "NaN as text", "kind": "nan-inf",
//         "raw": {"/p0/0": "NaN"},            // JSON pointer -> raw text, spliced in as is
//         "expect": {"error": "p0[0]: not valid JSON"}}              // exit 2, this in stderr
//      ]}
//
// A row edits the base with "set", "raw" and "remove" (a list of pointers), or replaces it with
// "input" (a whole JSON value) or "text" (the file's exact text). "expect" is either
// {"error": "..."}: exit code 2, nothing on stdout, one line on stderr starting with
// "cgsandbox: <file>: " and containing the text (which starts with the field it names), or
// {"result": {...}}: exit code 0 and the listed result fields equal (numbers to 1e-9 relative).
// "kind" says which degenerate case the row covers (see kKinds).
#pragma once

#include <string>
#include <vector>

#include "io/json.hpp"

namespace cg::test {

// The kinds of degenerate input a row may cover; every table has at least one row of each
// kind in kRequiredKinds.
inline const std::vector<std::string> kKinds = {
    "nan-inf",   "magnitude", "coincident", "zero-size", "collinear", "non-convex",
    "tangent",   "parallel",  "empty",      "wrong-type", "limit",    "other"};
inline const std::vector<std::string> kRequiredKinds = {"empty", "wrong-type", "magnitude"};

struct Table {
    std::string id;    // the algorithm's registry id
    std::string file;  // where it was read from
    json base;         // the input rows edit
    json rows;
};

// Every tables/*.json, sorted by file name.
std::vector<Table> load_tables();

// The text of a row's input file.
std::string row_text(const json& base, const json& row);

// Every numeric leaf of a JSON value: its JSON pointer and its path as errors write it
// ("window.xmin", "polygon[3][0]").
struct Leaf {
    std::string pointer, path;
};
std::vector<Leaf> numeric_leaves(const json& j);

// `j` with the value at `pointer` replaced by raw text.
std::string splice_raw(const json& j, const std::string& pointer, const std::string& raw);

// Whether `actual` has every field of `expected`, numbers to 1e-9 relative (1e-12 absolute).
bool matches(const json& expected, const json& actual, std::string& why);

// The paths of non-finite numbers in j (a result or a trace line), if any.
std::vector<std::string> non_finite(const json& j, const std::string& path = "");

}  // namespace cg::test
