// L-systems: parallel rewriting for n generations, then the turtle draws the string.
//
// The course ("L-system Plants"): a string, the axiom ω, and productions p → replacement. One
// generation replaces every symbol of the string at once (in parallel, not left to right on its
// own output) by its production; a symbol without one copies itself. Deterministic and
// context-free (Lindenmayer 1968; Prusinkiewicz & Lindenmayer, "The Algorithmic Beauty of
// Plants"). The string after n generations is then read by a turtle, symbol by symbol:
//   F (and any symbol listed in "draw")  move forward by `step`, drawing a line
//   f                                   move forward by `step` without drawing
//   +  /  -                             turn left (counter-clockwise) / right by `angle` degrees
//   [  /  ]                             push the turtle's state (position, heading) / pop it
//   anything else (X, Y, A, …)          ignored by the turtle: it only steers the rewriting
// Headings are degrees counter-clockwise from +x (90 = up, the default: plants grow upward).
// The heading is kept as h₀ + k·angle with k the net number of left turns, so that it never
// drifts, and its cosine and sine are exact at multiples of 30° and 45° (rot::cos_sin_deg).
//
// Steps: one generation of rewriting per step; then the turtle one symbol per step for the first
// kStepped symbols, and the rest in at most kBatches batches (the narration says so); a summary.
// Limits, checked before any rewriting from the growth counts (the number of each symbol after
// each generation, a matrix–vector product per generation): every generation's string at most
// kMaxLength symbols, at most kMaxGenerations generations, a production at most kMaxRule
// symbols. Symbols are printable ASCII (spaces are dropped; the JSON reader reads the Unicode
// minus − as -). Brackets must balance in the axiom and in every production (so they balance in
// every generation), and '[' and ']' have no productions of their own.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct LSystem {
    static constexpr long long kMaxLength = 250000;  // symbols in any generation's string
    static constexpr int kMaxGenerations = 40;
    static constexpr int kMaxRule = 1000;  // symbols in one production
    static constexpr double kMaxStep = 1e6;
    static constexpr int kStepped = 32;  // turtle symbols stepped one at a time
    static constexpr int kBatches = 32;  // then at most this many batches

    struct Rule {
        char symbol = 'F';
        std::string replacement;
        bool operator==(const Rule&) const = default;
    };

    struct Input {
        std::string axiom;        // ω
        std::vector<Rule> rules;  // one per symbol, in the order given
        int generations = 0;      // n
        double angle = 90;        // δ, degrees
        double step = 1;          // the length of one F
        double heading = 90;      // the turtle's start heading, degrees (90: up)
        std::string draw = "F";   // the symbols that draw a line
        bool operator==(const Input&) const = default;
    };

    // The turtle: position and heading h₀ + turns·δ.
    struct Turtle {
        glm::dvec2 p{0, 0};
        long long turns = 0;
        bool operator==(const Turtle&) const = default;
    };

    // What the turtle has done so far.
    struct Tally {
        long long segments = 0, moves = 0, turns = 0, pushes = 0, ignored = 0;
        int max_depth = 0;
        glm::dvec2 lo{0, 0}, hi{0, 0};  // the bounding box of every position visited
        bool operator==(const Tally&) const = default;
    };

    struct Result {
        std::vector<long long> lengths;  // the string's length after 0, 1, …, n generations
        std::string word;                // the string after n generations
        Tally tally;
        glm::dvec2 end{0, 0};
        double end_heading = 0;  // degrees in [0, 360)
        double path_length = 0;  // segments · step
        bool operator==(const Result&) const = default;
    };

    enum class Phase : std::uint8_t { Rewrite, Turtle, Summary, Done };

    struct State {
        Shared<Input> in;
        Phase phase = Phase::Rewrite;
        Phase last = Phase::Rewrite;
        int generation = 0;          // generations done
        Shared<std::string> word;    // the current string
        Shared<std::string> before;  // the string of the generation before (rewrite steps)
        std::vector<long long> lengths;
        std::size_t next = 0;     // the turtle's next symbol
        std::size_t from = 0;     // the first symbol of the last turtle step
        std::size_t batch = 1;    // symbols per step after the first kStepped
        Turtle turtle, previous;  // now, and before the last step
        std::vector<Turtle> stack;
        Tally tally;
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);   // validates, then begin()
    static State begin(Shared<Input> in);  // a fresh state for a valid input
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.phase == Phase::Done; }
    static Result result(const State& s);
    static void draw(const State& s, Scene& scene);
    static std::size_t bytes(const State& s) {
        return heap_bytes(s.lengths) + heap_bytes(s.stack) + s.word->capacity() +
               (&*s.before == &*s.word ? 0 : s.before->capacity());
    }

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // Everything in straight loops, for the benchmark and the tests.
    static Result compute(const Input& in);

    // The pieces both use.
    // The length of the string after 0, 1, …, n generations from the growth counts, without
    // rewriting; stops after the first generation longer than kMaxLength (its length is exact).
    static std::vector<long long> growth(const Input& in);
    // One generation: every symbol replaced at once by its production (or itself).
    static std::string rewrite(const Input& in, const std::string& word);
    // The turtle reads one symbol.
    static void interpret(const Input& in, char c, Turtle& t, std::vector<Turtle>& stack,
                          Tally& tally);
    static glm::dvec2 direction(const Input& in, const Turtle& t);  // unit, along the heading
    static double heading_of(const Input& in, const Turtle& t);     // degrees in [0, 360)
    static bool draws(const Input& in, char c);

  private:
    static void advance(State& s);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
