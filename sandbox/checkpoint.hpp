// A checkpoint: exactly what a student is looking at, in a small JSON file.
//
//     {"algorithm": "liang-barsky", "input": {...}, "step": 3,
//      "view": {"center": [x, y], "zoom": pixels_per_unit},
//      "lesson": "liang-barsky", "preset": "a segment crossing two edges", "exam_seed": 7}
//
// The viewer saves and opens them; `cgsandbox render --checkpoint FILE` draws them, so a
// student can send the exact picture they have. "view" is optional (fit to the scene); so are
// the open lesson, the preset it loaded, and the exam problem being practised (its seed).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "io/json.hpp"
#include "io/registry.hpp"

namespace cg {

struct View2 {
    glm::dvec2 center{0, 0};
    double zoom = 50;  // screen pixels per world unit
    bool operator==(const View2&) const = default;
};

struct Checkpoint {
    std::string algorithm;
    json input;
    std::size_t step = 0;
    std::optional<View2> view;  // none: fit the scene into the canvas
    std::string lesson;         // the open lesson's id; empty: none
    std::string preset;         // the lesson preset the input came from; empty: none
    std::optional<std::uint64_t> exam_seed;  // exam practice on make_exam(algorithm, seed)
};

// Reads and checks a checkpoint (the algorithm must exist; its input is checked when run).
// Errors are InputError with the field; the caller adds the file name.
Checkpoint checkpoint_from_json(const json& j, const Registry& registry);
json checkpoint_to_json(const Checkpoint& c);

// Reads a whole file ("-" is standard input); throws InputError("", "cannot open file"), or
// when the file is larger than kMaxInputBytes.
constexpr std::size_t kMaxInputBytes = std::size_t{128} << 20;
std::string read_text_file(const std::string& path);

}  // namespace cg
