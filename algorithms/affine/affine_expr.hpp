// The small expression language of affine-combination questions, and what each expression is.
//
// Affine geometry keeps points and vectors apart. With points P_i and vectors v_j:
//   Σ a_i P_i + Σ b_j v_j  is a point  when Σ a_i = 1 (an affine combination: (P + Q)/2),
//                          a vector when Σ a_i = 0 (P − Q, A − B + 2v),
//                          meaningless otherwise (P + Q: the answer would move with the origin).
// Only the point coefficients count. Points cannot be multiplied, divided, dotted or crossed;
// vectors can be added, scaled, dotted (a scalar) and crossed (a vector).
//
// The sum is judged on the whole expression, not on its parts: P + Q alone means nothing, yet
// (P + Q)/2 is the midpoint. So the analysis carries every sub-expression as a formal linear
// combination — a coefficient (itself a scalar expression, perhaps in t) per point and vector —
// and only products, quotients, dots and crosses demand that their operands be scalars or
// vectors on the spot.
//
// A coefficient sum in t is decided the way one checks a polynomial identity: by evaluating it
// at several fixed values of every named scalar (a formula that equals 1 at all of them is 1 —
// sin²t + cos²t, Σ B_i^n(t), (1 − t) + t), beside a readable formula for the student.
//
// Grammar (numbers, names, + − * / ^, · or `dot`, × or `cross`, parentheses, implicit
// multiplication "3A", "2(P − Q)"):
//   expr    := term (('+' | '-' | '−') term)*
//   term    := unary ((('*' | '/' | '·' | '×' | 'dot' | 'cross') unary) | unary)*
//   unary   := ('-' | '−') unary | power
//   power   := primary ('^' unary)?
//   primary := number | name subscript? | '(' expr ')' | ('sin' | 'cos') '(' expr ')'
//            | 'B' '(' expr ',' expr ',' expr ')'     Bernstein B_i^n(t) as B(n, i, t)
//            | 'B' '_' index '^' int '(' expr ')'     ... or as the course writes it
//            | ('sum' | 'Σ') '_' '{' name '=' int '}' '^' '{' int '}' term
//   subscript := '_' (digits | name | '{' expr '}')    P_0, A_i, P_{i+1}
// Names declared as points or vectors are those; a subscripted name P_i is the point P_i when
// P_i or the family P is declared. Any other name is a scalar (t, s, alpha).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cg::affine {

enum class Op : std::uint8_t {
    Number,
    Name,  // a point, vector or scalar name, maybe subscripted (kids[0] the subscript)
    Neg,
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Dot,
    Cross,
    Sin,
    Cos,
    Bernstein,  // kids: n, i, t
    Sum         // kids: the body; `name` the index, `lo`..`hi` its range
};

struct Node {
    Op op = Op::Number;
    double number = 0;
    std::string name;           // Name: the base name ("P" of P_i); Sum: the index variable
    long long lo = 0, hi = -1;  // Sum's range
    std::vector<int> kids;
    int begin = 0, end = 0;  // the node's span in the source, in characters (code points)
    bool operator==(const Node&) const = default;
};

struct Tree {
    std::string source;
    std::vector<Node> nodes;  // children before their parents (post-order): the root is last
    std::string span(const Node& n) const;  // the node's source text
    bool operator==(const Tree&) const = default;
};

// Why an expression could not be read: the 1-based character position and what was expected.
struct ParseError {
    int position = 0;
    std::string reason;
};

// The longest expression and deepest nesting accepted, and the most terms one expression may
// expand to through its sums (nested sums multiply).
constexpr int kMaxLength = 2000;
constexpr int kMaxDepth = 64;
constexpr long long kMaxTerms = 4096;

struct Names {
    std::vector<std::string> points, vectors;
    bool is_point(const std::string& s) const;
    bool is_vector(const std::string& s) const;
    bool operator==(const Names&) const = default;
};

// Parses one expression; on failure returns false and fills `error`.
bool parse(const std::string& text, const Names& names, Tree& tree, ParseError& error);

// ---- what an expression is ----

enum class Kind : std::uint8_t { Point, Vector, Scalar, Invalid };
const char* kind_name(Kind k);

// A scalar as the analysis carries it: its value at each sample assignment of the named
// scalars, and a readable formula.
constexpr int kSamples = 7;
struct Scalar {
    std::array<double, kSamples> v{};
    std::string text;
    int prec = 9;  // the formula's precedence, for parentheses: 1 +, 2 *, 3 unary, 4 ^, 9 atom
    bool constant = true;  // built from numbers alone (its value is v[0])
    bool operator==(const Scalar&) const = default;
};

// One sub-expression's type, as the steps list them bottom-up.
struct NodeType {
    std::string text;  // the sub-expression, as written
    std::string
        type;  // "point (Σ = 1)", "vector (Σ = 0)", "scalar", "Σ = 2: not yet …", "invalid: …"
    int node = 0;  // its index in Tree::nodes
    bool operator==(const NodeType&) const = default;
};

struct Coefficient {
    std::string name;  // "P", "A_2", or a cross product's text
    bool point = false;
    Scalar value;
    bool operator==(const Coefficient&) const = default;
};

struct Analysis {
    Kind kind = Kind::Invalid;
    std::vector<Coefficient> coefficients;  // of points and vectors, in order of appearance
    bool has_sum = false;   // a point-coefficient sum exists (points or vectors appear)
    Scalar sum;             // Σ of the point coefficients (its formula simplified: "1 − t + t")
    std::string sum_terms;  // the same sum written term by term: "(1 − t) + t", "3 − 2"
    bool depends = false;   // the sum is a non-constant function of the scalars, not 0 or 1
    std::string identity;   // why a non-constant sum is 1 or 0: "sin² + cos² = 1", …
    std::string reason;     // one line: why this kind
    std::vector<NodeType> nodes;  // every sub-expression, bottom-up (children first)
    bool operator==(const Analysis&) const = default;
};

Analysis analyse(const Tree& tree, const Names& names);

// The names an expression uses as scalars (neither declared points or vectors nor a sum's index),
// with the 1-based character position of each use: for inputs that declare their scalars.
std::vector<std::pair<std::string, int>> scalar_names(const Tree& tree, const Names& names);

}  // namespace cg::affine
