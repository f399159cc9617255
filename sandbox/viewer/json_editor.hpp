// A generic editor for an algorithm's JSON input: the viewer knows no input format, so it
// walks whatever JSON the algorithm's example has.
#pragma once

#include <functional>
#include <string>

#include "io/json.hpp"

namespace cg::viewer {

// Widgets for each field of `object` (objects become tree nodes, numbers InputDouble, short
// arrays of numbers one inline row, longer arrays a list with + and − buttons). Returns true
// when something changed this frame. `note`, if given, is called right after each field's
// widget with the field's JSON pointer ("/window/xmin"), e.g. to remember where it was drawn.
bool edit_json_fields(json& object, const std::function<void(const std::string&)>& note = {});

}  // namespace cg::viewer
