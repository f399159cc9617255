// L-system exam problems: "the string after 2 generations", with short productions a student
// rewrites by hand — a Koch-like curve (F → a few F and turns), a branching plant (X → F[+X]−X,
// F → FF), Lindenmayer's algae (A → AB, B → A), the Sierpinski arrowhead (A → B−A−B,
// B → A+B+A); one time in ten a production that erases a symbol (X → nothing), the degenerate
// case where the string can shrink. Every answer stays under 60 symbols.
#include "modelling/l_system.hpp"

namespace cg {

LSystem::Input LSystem::exam_input(Rng& rng) {
    Input in;
    in.generations = 2;
    in.heading = 90;
    in.step = 1;
    static const char* curves[] = {"F+F-F", "F-F+F", "FF+F", "F+F--F+F", "F[+F]F", "F[-F]F"};
    static const char* plants[] = {"F[+X]-X", "F-[X]+X", "F[+X][-X]", "F[-X]+X"};
    static const char* axioms[] = {"F", "F+F", "-F", "F-F"};
    static const double angles[] = {90, 60, 45, 25};
    in.angle = angles[rng.integer(0, 3)];
    const double kind = rng.uniform(0, 1);
    if (kind < 0.1) {  // an erasing production
        in.axiom = "FX";
        in.rules = {{'F', "F+X"}, {'X', ""}};
    } else if (kind < 0.45) {
        const std::string curve = curves[rng.integer(0, 5)];
        // The longest production (four F) from one F only: 36 symbols after 2 generations.
        in.axiom = curve.size() > 6 ? "F" : axioms[rng.integer(0, 3)];
        in.rules = {{'F', curve}};
    } else if (kind < 0.75) {
        in.axiom = "X";
        in.rules = {{'X', plants[rng.integer(0, 3)]}, {'F', "FF"}};
    } else if (kind < 0.9) {
        in.axiom = rng.chance(0.5) ? "A" : "B";
        in.rules = {{'A', "AB"}, {'B', "A"}};
    } else {
        in.axiom = "A";
        in.rules = {{'A', "B-A-B"}, {'B', "A+B+A"}};
        in.draw = "AB";
        in.angle = 60;
    }
    return in;
}

std::string LSystem::question(const Input& in) {
    std::string rules;
    for (const auto& r : in.rules)
        rules += (rules.empty() ? "" : ", ") + std::string(1, r.symbol) + " → " +
                 (r.replacement.empty() ? std::string("(nothing: the symbol is erased)")
                                        : r.replacement);
    return "An L-system has the axiom ω = " + in.axiom + " and the productions " + rules +
           "; a symbol without a production copies itself. Rewrite in parallel (every symbol of "
           "the string replaced at once) for " +
           std::to_string(in.generations) +
           " generations. Give the string after 2 generations (string) and its length after 0, "
           "1 and 2 generations (lengths).";
}

std::vector<std::string> LSystem::answer_fields() {
    return {"string", "lengths"};
}

}  // namespace cg
