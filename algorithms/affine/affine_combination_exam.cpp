// Affine-combination exam problems: points P, Q, R and a vector v, and five expressions of the
// kinds the course asks about — integer combinations whose coefficients sum to 1, 0 or
// something else; averages; a point plus a vector; a dot or cross product (of vectors, or
// wrongly of points); a blend in t; a Bernstein sum. Roughly a third are meaningless.
#include <cstdlib>

#include "affine/affine_combination.hpp"

namespace cg {

namespace {

// "2P − 3Q + 2R": a coefficient, then a name, written as a student would.
std::string affine_term(long long a, const std::string& name, bool first) {
    std::string s;
    if (first)
        s = a < 0 ? "−" : "";
    else
        s = a < 0 ? " − " : " + ";
    const long long m = std::llabs(a);
    if (m != 1) s += std::to_string(m);
    return s + name;
}

// Three nonzero integers in [-3, 3] summing to `target`, when there are any.
std::string integer_combination(Rng& rng, long long target) {
    for (;;) {
        const long long a = rng.integer(-3, 3), b = rng.integer(-3, 3);
        const long long c = target - a - b;
        if (a == 0 || b == 0 || c == 0 || c < -3 || c > 3) continue;
        return affine_term(a, "P", true) + affine_term(b, "Q", false) + affine_term(c, "R", false);
    }
}

std::string affine_pick(Rng& rng, std::initializer_list<const char*> options) {
    const auto k = rng.integer(0, static_cast<long long>(options.size()) - 1);
    return *(options.begin() + k);
}

}  // namespace

AffineCombination::Input AffineCombination::exam_input(Rng& rng) {
    Input in;
    in.points = {"P", "Q", "R"};
    in.vectors = {"v"};
    const long long targets[] = {1, 0, 2, -1};
    in.expressions.push_back(integer_combination(rng, targets[rng.integer(0, 3)]));
    in.expressions.push_back(affine_pick(rng, {"(P + Q)/2", "(P + Q + R)/3", "(P + Q)/3",
                                               "(2P + R)/3", "P/2 + Q/2 − R", "(P − Q)/2"}));
    in.expressions.push_back(
        affine_pick(rng, {"P + 2v", "P − Q + 2v", "P + Q + v", "2P − v", "v − 3v", "Q − P − v"}));
    in.expressions.push_back(affine_pick(
        rng, {"P · Q", "(P − Q) · v", "(P − Q) × (R − Q)", "P × v", "(P − R) · (Q − R)", "P Q"}));
    in.expressions.push_back(affine_pick(
        rng,
        {"(1 − t)P + t Q", "(1 − t)P + t Q + v", "t P + t Q", "(1 − t)^2 P + 2t(1 − t) Q + t^2 R",
         "sum_{i=0}^{2} B(2,i,t) P_i", "cos(t)^2 P + sin(t)^2 Q", "P + t(Q − P)"}));
    return in;
}

std::string AffineCombination::question(const Input& in) {
    std::string q =
        "P, Q and R are points (P_0, P_1, … too) and v is a vector; t is a scalar. "
        "For each expression say whether it is a point, a vector, a scalar or "
        "invalid (meaningless in affine geometry):";
    for (std::size_t k = 0; k < in.expressions.size(); ++k)
        q += " (" + std::to_string(k + 1) + ") " + in.expressions[k] +
             (k + 1 < in.expressions.size() ? ";" : ".");
    return q + " Answer as the list kinds, in order.";
}

std::vector<std::string> AffineCombination::answer_fields() {
    return {"kinds"};
}

}  // namespace cg
