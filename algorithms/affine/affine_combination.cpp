// Sections: [spec] [validate] [step] [narrate]; the picture is in affine_combination_draw.cpp
#include "affine/affine_combination.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/format.hpp"

namespace cg {

namespace {

using affine::Kind;

enum Line {
    kLineEach = 1,
    kLineParse,
    kLineNodes,
    kLineOperands,
    kLineSum,
    kLinePoint,
    kLineVector,
    kLineInvalid
};

const char* const kReserved[] = {"sin", "cos", "sum", "dot", "cross"};

// A name as the input may declare it: a letter, then letters and digits, optionally one
// subscript of digits or letters ("P", "v2", "P_0", "A_i").
bool valid_name(const std::string& s) {
    std::size_t i = 0;
    auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    if (s.empty() || !letter(s[0])) return false;
    while (i < s.size() && (letter(s[i]) || digit(s[i]))) ++i;
    if (i == s.size()) return true;
    if (s[i] != '_' || i + 1 == s.size()) return false;
    for (++i; i < s.size(); ++i)
        if (!letter(s[i]) && !digit(s[i])) return false;
    return true;
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& AffineCombination::spec() {
    static const Spec spec{
        "affine-combination",
        "Affine combinations: point, vector or meaningless",
        "Affine Geometry",
        {
            "for each expression E:",
            "    parse E into a tree",
            "    type every node, children first: a scalar, or Σ a_i P_i + Σ b_j v_j",
            "    ·, ×, products and quotients check their operands on the spot",
            "    S ← Σ a_i (only the points' coefficients)",
            "    if S = 1: E is a point",
            "    else if S = 0: E is a vector",
            "    else: E is meaningless (it would move with the origin)",
        },
        {
            {"point", "the point coefficients sum to 1: an affine combination, a point"},
            {"vector", "the point coefficients sum to 0 (or only vectors appear): a vector"},
            {"scalar", "no points or vectors remain: a number (a dot product, a coefficient)"},
            {"invalid",
             "meaningless: a sum other than 1 or 0, or an operation points do not have (P · Q, "
             "P Q, 1/P)"},
        },
        {},  // no sliders
        {
            .predict = {{"point", {"S"}}, {"vector", {"S"}}},
            .mistakes =
                {
                    {"point", "", "event:invalid",
                     "judged the whole by a part: P + Q alone is meaningless, but (P + Q)/2 is "
                     "the midpoint"},
                    {"vector", "", "event:point",
                     "read P − Q + v as a point because it ends in \"+ v\": the point "
                     "coefficients 1 − 1 = 0 make it a vector"},
                    {"invalid", "", "event:point",
                     "added all the coefficients, vectors' too, and found 1"},
                    {"point", "S", "negate", "subtracted instead of added a coefficient"},
                },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void AffineCombination::validate(const Input& in) {
    std::map<std::string, std::string> seen;  // name → where it was declared
    auto names = [&](const std::vector<std::string>& list, const char* field) {
        if (list.size() > static_cast<std::size_t>(kMaxNames))
            throw InputError(field, "at most " + std::to_string(kMaxNames) + " names");
        for (std::size_t k = 0; k < list.size(); ++k) {
            const std::string at = std::string(field) + "[" + std::to_string(k) + "]";
            const std::string& s = list[k];
            if (!valid_name(s))
                throw InputError(at, "\"" + s +
                                         "\" is not a name (a letter, then letters and digits, "
                                         "optionally _ and a subscript: P, v2, P_0)");
            if (std::find(std::begin(kReserved), std::end(kReserved), s) != std::end(kReserved))
                throw InputError(at, "\"" + s + "\" is reserved by the expression language");
            if (auto it = seen.find(s); it != seen.end())
                throw InputError(at, "\"" + s + "\" is already declared in " + it->second);
            seen[s] = at;
        }
    };
    names(in.points, "points");
    names(in.vectors, "vectors");
    if (in.scalars_declared) names(in.scalars, "scalars");
    if (in.expressions.empty())
        throw InputError("expressions", "must list at least one expression");
    if (in.expressions.size() > static_cast<std::size_t>(kMaxExpressions))
        throw InputError("expressions",
                         "at most " + std::to_string(kMaxExpressions) + " expressions");
}

AffineCombination::Parsed AffineCombination::parse(const Input& in) {
    validate(in);
    Parsed p;
    static_cast<Input&>(p) = in;
    p.names.points = in.points;
    p.names.vectors = in.vectors;
    p.trees.resize(in.expressions.size());
    for (std::size_t k = 0; k < in.expressions.size(); ++k) {
        const std::string at = "expressions[" + std::to_string(k) + "]";
        affine::ParseError e;
        if (!affine::parse(in.expressions[k], p.names, p.trees[k], e))
            throw InputError(at, "at character " + std::to_string(e.position) + ": " + e.reason);
        if (!in.scalars_declared) continue;
        for (const auto& [name, pos] : affine::scalar_names(p.trees[k], p.names))
            if (std::find(in.scalars.begin(), in.scalars.end(), name) == in.scalars.end())
                throw InputError(at, "at character " + std::to_string(pos) + ": \"" + name +
                                         "\" is not declared (as a point, a vector or a scalar)");
    }
    return p;
}

AffineCombination::State AffineCombination::start(const Input& in) {
    State s;
    s.in = Shared<Parsed>(parse(in));
    s.rows.reserve(in.expressions.size());
    return s;
}

// ---- [step] ---------------------------------------------------------------------------------

AffineCombination::Row AffineCombination::row_of(const std::string& expression,
                                                 const affine::Analysis& a) {
    Row r;
    r.expression = expression;
    r.kind = a.kind;
    r.has_sum = a.has_sum;
    if (a.has_sum) {
        r.sum_constant = a.sum.constant && std::isfinite(a.sum.v[0]);
        r.sum = r.sum_constant ? a.sum.v[0] : 0;
        if (!r.sum_constant) r.sum_formula = a.sum_terms;  // a formula in t, or one that overflows
    }
    r.depends = a.depends;
    r.coefficients.reserve(a.coefficients.size());
    for (const auto& c : a.coefficients)
        r.coefficients.push_back({c.name, c.value.constant, c.value.v[0], c.value.text});
    r.reason = a.reason;
    return r;
}

void AffineCombination::step(State& s, StepInfo* info) {
    if (done(s)) return;
    ++s.k;
    const Parsed& p = *s.in;
    s.analysis = affine::analyse(p.trees[s.k], p.names);
    s.rows.push_back(row_of(p.expressions[s.k], s.analysis));
    if (info) narrate(s, *info);
}

AffineCombination::Result AffineCombination::classify(const Input& in) {
    const Parsed p = parse(in);
    Result r;
    r.rows.reserve(p.trees.size());
    for (std::size_t k = 0; k < p.trees.size(); ++k)
        r.rows.push_back(row_of(in.expressions[k], affine::analyse(p.trees[k], p.names)));
    return r;
}

// ---- [narrate] ------------------------------------------------------------------------------

void AffineCombination::narrate(const State& s, StepInfo& info) {
    const Row& row = s.rows.back();
    const affine::Analysis& a = s.analysis;
    info.event = affine::kind_name(row.kind);
    switch (row.kind) {
        case Kind::Point:
            info.line = kLinePoint;
            break;
        case Kind::Vector:
            info.line = kLineVector;
            break;
        case Kind::Scalar:
            info.line = kLineNodes;
            break;
        case Kind::Invalid:
            info.line = a.has_sum ? kLineInvalid : kLineOperands;
            break;
    }
    const std::string what =
        row.kind == Kind::Invalid ? "meaningless" : std::string("a ") + affine::kind_name(row.kind);
    info.narration = row.expression + " is " + what + ": " + row.reason + ".";
    info.math.clear();
    if (row.has_sum && row.sum_constant) info.math = "S = \\sum_i a_i = " + tex(row.sum);
    info.vars.clear();
    info.vars.push_back({"expression", row.expression});
    info.vars.push_back({"kind", std::string(affine::kind_name(row.kind))});
    if (a.has_sum) {
        if (row.sum_constant)
            info.vars.push_back({"S", row.sum});
        else
            info.vars.push_back({"S", row.sum_formula});
        std::string coeffs;
        for (const auto& t : row.coefficients)
            coeffs += (coeffs.empty() ? "" : ", ") + t.name + ": " + t.formula;
        info.vars.push_back({"coefficients", coeffs});
    }
    // The tree bottom-up: every sub-expression with its type (the root is the expression itself).
    constexpr std::size_t kMaxListed = 24;
    const std::size_t n = a.nodes.size();
    const affine::Tree& tree = s.in->trees[s.k];
    std::size_t listed = 0;
    for (std::size_t j = 0; j + 1 < n && listed < kMaxListed; ++j) {
        const affine::Node& node = tree.nodes[a.nodes[j].node];
        const bool leaf =
            node.op == affine::Op::Name || node.op == affine::Op::Number ||
            (node.op == affine::Op::Neg && tree.nodes[node.kids[0]].op == affine::Op::Number);
        if (leaf) continue;  // names and numbers: their types are obvious
        const bool seen = std::any_of(info.vars.begin(), info.vars.end(),
                                      [&](const Var& v) { return v.name == a.nodes[j].text; });
        if (seen) continue;
        info.vars.push_back({a.nodes[j].text, a.nodes[j].type});
        ++listed;
    }
}

}  // namespace cg
