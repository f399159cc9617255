// Which combinations of points and vectors mean something: the course's opening rule of
// affine geometry, applied to a list of expressions one step each.
//
// Points P_i and vectors v_j: Σ a_i P_i + Σ b_j v_j is a point when Σ a_i = 1, a vector when
// Σ a_i = 0, and meaningless otherwise (it would depend on where the origin is). A point plus a
// vector is a point; point minus point is a vector; points are never multiplied, divided,
// dotted or crossed; vectors are added, scaled, dotted (a scalar) and crossed (a vector).
// The expression language and the analysis are in affine_expr.hpp.
//
// Steps: one per expression — its parse tree bottom-up with the type of every sub-expression
// (the variables list them), the point-coefficient sum S, and the verdict (the event: point,
// vector, scalar or invalid).
#pragma once

#include <string>
#include <vector>

#include "affine/affine_expr.hpp"
#include "core/rng.hpp"
#include "core/run.hpp"
#include "core/shared.hpp"

namespace cg {

struct AffineCombination {
    static constexpr int kMaxNames = 64;
    static constexpr int kMaxExpressions = 100;

    struct Input {
        std::vector<std::string> points, vectors;
        std::vector<std::string> scalars;  // when given, every other name is refused
        bool scalars_declared = false;
        std::vector<std::string> expressions;
        bool operator==(const Input&) const = default;
    };

    // One expression's verdict.
    struct Row {
        std::string expression;
        affine::Kind kind = affine::Kind::Invalid;
        bool has_sum = false;      // points or vectors appear (a coefficient sum exists)
        bool sum_constant = true;  // the sum is a number ...
        double sum = 0;            // ... this one
        std::string sum_formula;   // ... else this formula in the scalars ("(1 − t) + t")
        bool depends = false;      // a formula that is 1 or 0 only for some values
        struct Term {
            std::string name;  // "P", "P_2", "(P − Q) × v"
            bool constant = true;
            double value = 0;     // a number (when constant) ...
            std::string formula;  // ... as a student writes it ("1/3"), or a formula in the scalars
            bool operator==(const Term&) const = default;
        };
        std::vector<Term> coefficients;
        std::string reason;
        bool operator==(const Row&) const = default;
    };

    struct Result {
        std::vector<Row> rows;
        bool operator==(const Result&) const = default;
    };

    // The input with its expressions parsed, shared by every copy of a state.
    struct Parsed : Input {
        affine::Names names;
        std::vector<affine::Tree> trees;
        bool operator==(const Parsed&) const = default;
    };

    struct State {
        Shared<Parsed> in;
        int k = -1;                 // the expression analysed last
        affine::Analysis analysis;  // ... its analysis
        std::vector<Row> rows;      // the verdicts so far
        bool operator==(const State&) const = default;
    };

    static const Spec& spec();
    static void validate(const Input& in);
    static State start(const Input& in);
    static void step(State& s, StepInfo* info);
    static bool done(const State& s) { return s.k + 1 >= static_cast<int>(s.in->trees.size()); }
    static Result result(const State& s) { return Result{s.rows}; }
    static Result result(State&& s) { return Result{std::move(s.rows)}; }
    static void draw(const State& s, Scene& scene);

    static Input exam_input(Rng& rng);
    static std::string question(const Input& in);
    static std::vector<std::string> answer_fields();

    // Every expression classified in one go, for the benchmark.
    static Result classify(const Input& in);

    static Row row_of(const std::string& expression, const affine::Analysis& a);

    // An expression as a person writes it rather than as it is typed: Σ with its limits, sub-
    // and superscripts, Bᵢⁿ(t), sin²(t), the minus sign ("sum_{i=0}^{3} B(3,i,t) P_i" →
    // "Σᵢ₌₀³ Bᵢ³(t) Pᵢ"). For the picture; a part Unicode cannot raise or lower stays as typed.
    static std::string display(const std::string& expression);

  private:
    static Parsed parse(const Input& in);
    [[gnu::cold]] static void narrate(const State& s, StepInfo& info);
};

}  // namespace cg
