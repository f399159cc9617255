// Exam practice: fresh exam-style problems from a seed, and grading of a student's answers.
//
// An algorithm with a generator picks an input of the kind the course examines (small integers
// or simple decimals a student can work by hand, sometimes a degenerate case), writes the
// question, and names the result fields that make up the answer. The expected answer is the
// algorithm's own result on that input; the tests check it against an independent reference.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/registry.hpp"

namespace cg {

struct ExamProblem {
    std::string algorithm;             // id
    std::uint64_t seed = 0;
    std::string question;
    json input;
    std::vector<std::string> answers;  // result fields the student must give
    json expected;                     // {field: value}
};

bool has_exam(const Algorithm& a);
// Throws InputError when the algorithm has no generator.
ExamProblem make_exam(const Algorithm& a, std::uint64_t seed);
// The problem for a given input (the question and expected answers for it).
ExamProblem exam_for_input(const Algorithm& a, const json& input);
json exam_to_json(const ExamProblem& p);  // {"question", "input", "answers", "expected"}
// One answer field's value in a result: "a/b" is field b of the object in field a.
const json& answer_value(const json& result, const std::string& field);

struct FieldGrade {
    std::string field;
    bool correct = false;
    std::string why;  // for a wrong answer: what was expected, or why it could not be read
};

// Numbers count as right within `tolerance` relative to max(1, |expected|), so 0.333 is a
// right answer for 1/3 at the default but 0.33 is not (three significant digits); lists
// compare element by element; null means "none".
bool answer_matches(const json& expected, const json& given, double tolerance = 1e-3);
// `given` maps answer fields to values (JSON); a missing field is wrong.
std::vector<FieldGrade> grade(const ExamProblem& p, const json& given, double tolerance = 1e-3);
// Reads what a student typed for one field: JSON ("[1, 3]", "true", "null", "0.25"), or a
// bare word such as yes/no/none.
json parse_answer(const std::string& text);

}  // namespace cg
