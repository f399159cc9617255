// Compare side by side: two runs on one input, and where their results part.
//
// Three kinds of pair:
//   - two algorithms that read the same kind of input (Spec::study.input_kind): painter's,
//     z-buffer and Warnock on one polygon scene. Their results are compared on the fields the
//     kind shares (Spec::study.compare: the visible polygon of every pixel) and their costs
//     are set side by side;
//   - one algorithm in two variants ("phong-lighting@phong" against "@blinn-phong"): one input
//     field set two ways (Spec::study.variants);
//   - one algorithm on two inputs (a student's edit against the original).
// When both sides run the same algorithm their traces are compared too, and the first step
// whose event or numbers differ is named.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "study/trace.hpp"

namespace cg::study {

struct Side {
    const Algorithm* algorithm = nullptr;
    const Variant* variant = nullptr;  // null: the input as given
    std::string label;                 // "phong-lighting@phong"
};

// "ID" or "ID@VARIANT". Throws InputError for an unknown id or variant (naming the variants).
Side parse_side(const Registry& registry, const std::string& text);

// The input with the side's variant applied (unchanged without one).
json side_input(const Side& side, json input);

// Throws InputError unless the two sides read the same kind of input: the same algorithm, or
// two algorithms declaring the same Spec::study.input_kind.
void check_comparable(const Side& a, const Side& b);

struct Difference {
    std::string where;  // a JSON pointer into the results: "/ids/3/4"
    json a, b;
};

struct Comparison {
    bool agree = true;                    // the compared results agree (to 1e-9 relative)
    std::vector<Difference> differences;  // the first kMaxListed, in reading order
    std::size_t difference_count = 0;
    json costs = json::object();  // {"<label a>": {...}, "<label b>": {...}}
    std::size_t steps_a = 0, steps_b = 0;
    // Same algorithm only: the first step whose event or variables differ, and what differs.
    std::optional<std::size_t> first_step;
    std::string first_step_note;
};

constexpr std::size_t kMaxListed = 100;

Comparison compare(const Side& a, const Trace& ta, const Side& b, const Trace& tb);

// {"agree", "a", "b", "differences", "difference_count", "costs", "steps", "first_step"}
json comparison_json(const Side& a, const Side& b, const Comparison& c);

// The first step (0-based) at which two traces of one algorithm differ, with a note; nothing
// when every common step agrees and they have the same length.
std::optional<std::size_t> first_differing_step(const Trace& a, const Trace& b, std::string* note);

}  // namespace cg::study
