#include "affine/affine_expr.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "core/format.hpp"
#include "core/rng.hpp"

namespace cg::affine {

// ---- [names] --------------------------------------------------------------------------------

bool Names::is_point(const std::string& s) const {
    return std::find(points.begin(), points.end(), s) != points.end();
}
bool Names::is_vector(const std::string& s) const {
    return std::find(vectors.begin(), vectors.end(), s) != vectors.end();
}

const char* kind_name(Kind k) {
    switch (k) {
        case Kind::Point:
            return "point";
        case Kind::Vector:
            return "vector";
        case Kind::Scalar:
            return "scalar";
        case Kind::Invalid:
            break;
    }
    return "invalid";
}

// ---- [lexer] --------------------------------------------------------------------------------
// The source is UTF-8; positions count characters (code points), as an editor shows them.

namespace {

struct Char {
    char32_t c;
    int byte;  // offset of its first byte
};

std::vector<Char> decode(const std::string& s) {
    std::vector<Char> out;
    for (std::size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        int len = b < 0x80           ? 1
                  : (b >> 5) == 0x6  ? 2
                  : (b >> 4) == 0xE  ? 3
                  : (b >> 3) == 0x1E ? 4
                                     : 0;
        char32_t c = 0xFFFD;
        if (len == 0 || i + len > s.size()) {
            len = 1;
        } else {
            c = len == 1 ? b : b & (0x7F >> len);
            for (int k = 1; k < len; ++k) {
                const auto cb = static_cast<unsigned char>(s[i + k]);
                if ((cb >> 6) != 0x2) {
                    c = 0xFFFD;
                    len = k;
                    break;
                }
                c = (c << 6) | (cb & 0x3F);
            }
        }
        out.push_back({c, static_cast<int>(i)});
        i += len;
    }
    return out;
}

enum class T : std::uint8_t { Number, Ident, Sym, End };

struct Token {
    T t = T::End;
    double number = 0;
    std::string text;  // an identifier; a symbol as one ASCII character ('-' for '−', '.' for '·',
                       // 'x' for '×', 'S' for 'Σ')
    int begin = 0, end = 0;  // characters, 0-based, end exclusive
};

bool is_letter(char32_t c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}
bool is_digit(char32_t c) {
    return c >= '0' && c <= '9';
}

bool lex(const std::vector<Char>& cs, std::vector<Token>& out, ParseError& err) {
    std::size_t i = 0;
    while (i < cs.size()) {
        const char32_t c = cs[i].c;
        const int at = static_cast<int>(i);
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            ++i;
            continue;
        }
        if (is_digit(c) || (c == '.' && i + 1 < cs.size() && is_digit(cs[i + 1].c))) {
            std::string digits;
            bool dot = false;
            while (i < cs.size() && (is_digit(cs[i].c) || (cs[i].c == '.' && !dot))) {
                dot = dot || cs[i].c == '.';
                digits.push_back(static_cast<char>(cs[i].c));
                ++i;
            }
            // An exponent, 1e-3: only when digits follow the e (2e alone is 2 times a scalar e).
            if (i + 1 < cs.size() && (cs[i].c == 'e' || cs[i].c == 'E')) {
                std::size_t j = i + 1;
                if (j < cs.size() && (cs[j].c == '+' || cs[j].c == '-')) ++j;
                if (j < cs.size() && is_digit(cs[j].c)) {
                    digits += 'e';
                    for (std::size_t q = i + 1; q < j; ++q)
                        digits.push_back(static_cast<char>(cs[q].c));
                    i = j;
                    while (i < cs.size() && is_digit(cs[i].c))
                        digits.push_back(static_cast<char>(cs[i++].c));
                    dot = true;  // not a whole-number literal
                }
            }
            const double value = std::strtod(digits.c_str(), nullptr);
            if (!std::isfinite(value)) {
                err = {at + 1, "the number " + digits + " is too large"};
                return false;
            }
            out.push_back({T::Number, value, digits, at, static_cast<int>(i)});
            continue;
        }
        if (is_letter(c)) {
            std::string name;
            while (i < cs.size() && (is_letter(cs[i].c) || is_digit(cs[i].c)))
                name.push_back(static_cast<char>(cs[i++].c));
            out.push_back({T::Ident, 0, name, at, static_cast<int>(i)});
            continue;
        }
        char sym = 0;
        switch (c) {
            case '+':
            case '-':
            case '*':
            case '/':
            case '^':
            case '(':
            case ')':
            case ',':
            case '_':
            case '{':
            case '}':
            case '=':
                sym = static_cast<char>(c);
                break;
            case U'\u2212':
                sym = '-';
                break;  // − minus sign
            case U'\u00B7':
            case U'\u22C5':
                sym = '.';
                break;  // · middle dot, ⋅ dot operator
            case U'\u00D7':
                sym = 'x';
                break;  // × multiplication sign: the cross product
            case U'\u03A3':
            case U'\u2211':
                sym = 'S';
                break;  // Σ, ∑
            default:
                break;
        }
        if (!sym) {
            err = {at + 1, "unexpected character"};
            return false;
        }
        out.push_back({T::Sym, 0, std::string(1, sym), at, at + 1});
        ++i;
    }
    const int n = static_cast<int>(cs.size());
    out.push_back({T::End, 0, "", n, n});
    return true;
}

// ---- [parser] -------------------------------------------------------------------------------

struct Fail {};

class Parser {
  public:
    Parser(std::vector<Token> toks, const Names& names, Tree& tree, ParseError& err)
        : toks_(std::move(toks)), names_(names), tree_(tree), err_(err) {}

    void run() {
        expr();
        if (peek().t != T::End) fail(peek(), "expected an operator or the end of the expression");
    }

  private:
    const Token& peek(int ahead = 0) const {
        const std::size_t k = std::min(pos_ + ahead, toks_.size() - 1);
        return toks_[k];
    }
    bool sym(char c, int ahead = 0) const {
        return peek(ahead).t == T::Sym && peek(ahead).text[0] == c;
    }
    bool ident(const char* s, int ahead = 0) const {
        return peek(ahead).t == T::Ident && peek(ahead).text == s;
    }
    // A word the language reserves, unless the input declares it as a point or vector.
    bool word(const char* s, int ahead = 0) const {
        return ident(s, ahead) && !names_.is_point(s) && !names_.is_vector(s);
    }
    [[noreturn]] void fail(const Token& t, std::string why) {
        err_ = {t.begin + 1, std::move(why)};
        throw Fail{};
    }
    void expect(char c, const char* what) {
        if (!sym(c)) fail(peek(), std::string("expected ") + what);
        ++pos_;
    }
    int add(Node n) {
        tree_.nodes.push_back(std::move(n));
        return static_cast<int>(tree_.nodes.size()) - 1;
    }
    int binary(Op op, int a, int b) {
        Node n;
        n.op = op;
        n.kids = {a, b};
        n.begin = tree_.nodes[a].begin;
        n.end = tree_.nodes[b].end;
        return add(std::move(n));
    }
    struct Depth {
        Parser& p;
        explicit Depth(Parser& q) : p(q) {
            if (++p.depth_ > kMaxDepth)
                p.fail(p.peek(), "nested more than " + std::to_string(kMaxDepth) +
                                     " deep (parentheses, signs, powers and sums)");
        }
        ~Depth() { --p.depth_; }
    };

    int expr() {
        int a = term();
        while (sym('+') || sym('-')) {
            const Op op = sym('+') ? Op::Add : Op::Sub;
            ++pos_;
            a = binary(op, a, term());
        }
        return a;
    }

    // Can the next token start an operand (for implicit multiplication)?
    bool starts_primary() const {
        const Token& t = peek();
        if (t.t == T::Number) return true;
        if (t.t == T::Ident) return !word("dot") && !word("cross");
        return sym('(') || sym('S');
    }

    int term() {
        int a = unary();
        for (;;) {
            Op op;
            if (sym('*'))
                op = Op::Mul;
            else if (sym('/'))
                op = Op::Div;
            else if (sym('.') || word("dot"))
                op = Op::Dot;
            else if (sym('x') || word("cross"))
                op = Op::Cross;
            else if (starts_primary()) {
                a = binary(Op::Mul, a, unary());
                continue;
            } else
                break;
            ++pos_;
            a = binary(op, a, unary());
        }
        return a;
    }

    int unary() {
        Depth d(*this);
        if (sym('-')) {
            const int begin = peek().begin;
            ++pos_;
            const int a = unary();
            Node n;
            n.op = Op::Neg;
            n.kids = {a};
            n.begin = begin;
            n.end = tree_.nodes[a].end;
            return add(std::move(n));
        }
        if (sym('+')) fail(peek(), "expected a number, a name or '('");
        const int a = primary();
        if (sym('^')) {
            ++pos_;
            return binary(Op::Pow, a, unary());
        }
        return a;
    }

    long long integer_literal(const char* what) {
        bool negative = false;
        if (sym('-')) {
            negative = true;
            ++pos_;
        }
        const Token& t = peek();
        if (t.t != T::Number || t.text.find_first_of(".eE") != std::string::npos ||
            t.text.size() > 6)
            fail(t, std::string("expected a whole number for ") + what);
        ++pos_;
        const long long v = std::stoll(t.text);
        return negative ? -v : v;
    }

    int primary() {
        const Token t = peek();
        if (t.t == T::Number) {
            ++pos_;
            Node n;
            n.op = Op::Number;
            n.number = t.number;
            n.begin = t.begin;
            n.end = t.end;
            return add(std::move(n));
        }
        if (sym('(')) {
            ++pos_;
            const int a = expr();
            if (!sym(')')) fail(peek(), "expected ')'");
            tree_.nodes[a].begin = t.begin;  // the parentheses belong to the sub-expression's text
            tree_.nodes[a].end = peek().end;
            ++pos_;
            return a;
        }
        if (sym('S') || (word("sum") && sym('_', 1))) return sum();
        if (t.t != T::Ident) fail(t, "expected a number, a name or '('");
        if ((word("sin") || word("cos")) && sym('(', 1)) {
            const Op op = t.text == "sin" ? Op::Sin : Op::Cos;
            pos_ += 2;
            const int a = expr();
            if (!sym(')')) fail(peek(), "expected ')' after the argument of " + t.text);
            Node n;
            n.op = op;
            n.kids = {a};
            n.begin = t.begin;
            n.end = peek().end;
            ++pos_;
            return add(std::move(n));
        }
        if ((word("dot") || word("cross")) && sym('(', 1)) {
            const Op op = t.text == "dot" ? Op::Dot : Op::Cross;
            pos_ += 2;
            const int a = expr();
            expect(',', "',' between the two vectors");
            const int b = expr();
            if (!sym(')')) fail(peek(), "expected ')'");
            Node n;
            n.op = op;
            n.kids = {a, b};
            n.begin = t.begin;
            n.end = peek().end;
            ++pos_;
            return add(std::move(n));
        }
        if (word("sin") || word("cos") || word("dot") || word("cross") || word("sum"))
            fail(t, "'" + t.text +
                        "' is a reserved word here (declare it as a point or vector to use it as a "
                        "name)");
        // B(n, i, t) is the Bernstein polynomial even where B is a declared point: a point cannot
        // take a list of arguments. A declared B before a single parenthesis is a product.
        const bool b_declared = names_.is_point("B") || names_.is_vector("B");
        if (ident("B") && sym('(', 1)) {
            const std::size_t saved_pos = pos_;
            const std::size_t saved_nodes = tree_.nodes.size();
            pos_ += 2;
            const int nn = expr();
            if (b_declared && !sym(',')) {
                pos_ = saved_pos;  // B (…): read B alone; the parenthesis multiplies it
                tree_.nodes.resize(saved_nodes);
                ++pos_;
                Node b;
                b.op = Op::Name;
                b.name = "B";
                b.begin = t.begin;
                b.end = t.end;
                return add(std::move(b));
            }
            expect(',', "',' in B(n, i, t)");
            const int ii = expr();
            expect(',', "',' in B(n, i, t)");
            const int tt = expr();
            if (!sym(')')) fail(peek(), "expected ')' to close B(n, i, t)");
            Node n;
            n.op = Op::Bernstein;
            n.kids = {nn, ii, tt};
            n.begin = t.begin;
            n.end = peek().end;
            ++pos_;
            return add(std::move(n));
        }
        ++pos_;
        Node n;
        n.op = Op::Name;
        n.name = t.text;
        n.begin = t.begin;
        n.end = t.end;
        if (sym('_')) {
            ++pos_;
            n.kids = {subscript()};
            n.end = toks_[pos_ - 1].end;  // past a closing '}' too
            // The course's B_i^n(t): the Bernstein polynomial, when B is no declared name.
            if (t.text == "B" && sym('^') && peek(1).t == T::Number && sym('(', 2)) {
                ++pos_;
                const Token deg = peek();
                ++pos_;
                Node degree;
                degree.op = Op::Number;
                degree.number = deg.number;
                degree.begin = deg.begin;
                degree.end = deg.end;
                const int dn = add(std::move(degree));
                ++pos_;  // '('
                const int tt = expr();
                if (!sym(')')) fail(peek(), "expected ')' to close B_i^n(t)");
                Node b;
                b.op = Op::Bernstein;
                b.kids = {dn, n.kids[0], tt};
                b.begin = t.begin;
                b.end = peek().end;
                ++pos_;
                return add(std::move(b));
            }
        }
        return add(std::move(n));
    }

    // After '_': digits, a name, or {expr}.
    int subscript() {
        const Token t = peek();
        if (t.t == T::Number && t.text.find_first_of(".eE") == std::string::npos) {
            ++pos_;
            Node n;
            n.op = Op::Number;
            n.number = t.number;
            n.begin = t.begin;
            n.end = t.end;
            return add(std::move(n));
        }
        if (t.t == T::Ident) {
            ++pos_;
            Node n;
            n.op = Op::Name;
            n.name = t.text;
            n.begin = t.begin;
            n.end = t.end;
            return add(std::move(n));
        }
        if (sym('{')) {
            ++pos_;
            const int a = expr();
            if (!sym('}')) fail(peek(), "expected '}' to close the subscript");
            ++pos_;
            return a;
        }
        fail(t, "expected a subscript after '_': a whole number, a name or {…}");
    }

    // sum_{i=a}^{b} term
    int sum() {
        const Token start = peek();
        ++pos_;
        expect('_', "'_{' after sum");
        expect('{', "'{' after sum_");
        if (peek().t != T::Ident) fail(peek(), "expected the index name in sum_{i=…}");
        const std::string index = peek().text;
        ++pos_;
        expect('=', "'=' in sum_{i=…}");
        const long long lo = integer_literal("the sum's lower bound");
        expect('}', "'}' after the lower bound");
        expect('^', "'^' and the upper bound");
        long long hi = 0;
        if (sym('{')) {
            ++pos_;
            hi = integer_literal("the sum's upper bound");
            expect('}', "'}' after the upper bound");
        } else {
            hi = integer_literal("the sum's upper bound");
        }
        if (hi < lo)
            fail(toks_[pos_ - 1], "the upper bound is below the lower bound: the sum has no terms");
        const long long count = hi - lo + 1;
        if (count > kMaxTerms / terms_)
            fail(toks_[pos_ - 1],
                 "the sums expand to more than " + std::to_string(kMaxTerms) + " terms");
        terms_ *= count;
        if (!starts_primary() && !sym('-'))
            fail(peek(), "expected the summed term after the bounds");
        const int body = term();
        terms_ /= count;
        Node n;
        n.op = Op::Sum;
        n.name = index;
        n.lo = lo;
        n.hi = hi;
        n.kids = {body};
        n.begin = start.begin;
        n.end = tree_.nodes[body].end;
        return add(std::move(n));
    }

    std::vector<Token> toks_;
    const Names& names_;
    Tree& tree_;
    ParseError& err_;
    std::size_t pos_ = 0;
    int depth_ = 0;
    long long terms_ = 1;
};

}  // namespace

std::string Tree::span(const Node& n) const {
    const auto cs = decode(source);
    if (n.begin >= static_cast<int>(cs.size())) return "";
    const int b = cs[n.begin].byte;
    const int e =
        n.end < static_cast<int>(cs.size()) ? cs[n.end].byte : static_cast<int>(source.size());
    return source.substr(b, e - b);
}

// The course writes products without a space: tQ is t times the point Q. An undeclared name
// made of one letter and a declared point or vector reads as that letter, a scalar, times it
// (tQ, sB, kv, tP_i); when the letter is itself a declared point or vector (PQ) the name is
// refused, naming the product it would be, never taken silently as a scalar. Longer scalar
// names are written apart: "alpha P".
bool split_products(std::vector<Token>& toks, const Names& names, ParseError& err) {
    auto declared = [&](const std::string& n) { return names.is_point(n) || names.is_vector(n); };
    std::vector<Token> out;
    for (const Token& t : toks) {
        if (t.t != T::Ident || t.text.size() < 2 || declared(t.text) || t.text == "dot" ||
            !declared(t.text.substr(1)) || !is_letter(static_cast<unsigned char>(t.text[1]))) {
            out.push_back(t);
            continue;
        }
        const std::string letter = t.text.substr(0, 1), thing = t.text.substr(1);
        if (declared(letter)) {
            err = {t.begin + 1, "\"" + t.text + "\" is not declared: it reads as " + letter +
                                    "·" + thing + ", a product of two declared names (write " +
                                    "the product with · or a space, or declare " + t.text + ")"};
            return false;
        }
        out.push_back({T::Ident, 0, letter, t.begin, t.begin + 1});
        out.push_back({T::Ident, 0, thing, t.begin + 1, t.end});
    }
    toks = std::move(out);
    return true;
}

bool parse(const std::string& text, const Names& names, Tree& tree, ParseError& error) {
    tree = Tree{};
    tree.source = text;
    const auto cs = decode(text);
    if (cs.size() > static_cast<std::size_t>(kMaxLength)) {
        error = {kMaxLength + 1, "longer than " + std::to_string(kMaxLength) + " characters"};
        return false;
    }
    std::vector<Token> toks;
    if (!lex(cs, toks, error) || !split_products(toks, names, error)) return false;
    if (toks.size() == 1) {
        error = {1, "the expression is empty"};
        return false;
    }
    try {
        Parser(std::move(toks), names, tree, error).run();
    } catch (const Fail&) {
        return false;
    }
    return true;
}

// ---- [scalars] ------------------------------------------------------------------------------
// Each named scalar takes kSamples fixed values in (0.1, 0.9), from a hash of its name, so a
// formula's samples never depend on the order names appear in.

namespace {

constexpr double kTol = 1e-12;

double sample_value(const std::string& name, int m) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a
    for (unsigned char c : name) h = (h ^ c) * 1099511628211ull;
    Rng r(h + static_cast<std::uint64_t>(m) * 0x9e3779b97f4a7c15ull);
    return r.uniform(0.1, 0.9);
}

// A constant as a student writes it: a small fraction when it is one, else a decimal.
std::string number_text(double x) {
    for (int d = 2; d <= 12; ++d) {
        const double top = x * d;
        const double n = std::round(top);
        if (std::fabs(top - n) < 1e-12 && std::fabs(n) < 1e6 && std::fmod(n, d) != 0)
            return (n < 0 ? "−" : "") + num(std::fabs(n)) + "/" + std::to_string(d);
    }
    return x < 0 ? "−" + num(-x) : num(x);
}

Scalar constant(double x) {
    Scalar s;
    s.v.fill(x);
    s.text = number_text(x);
    s.prec = x < 0 ? 3 : (s.text.find('/') != std::string::npos ? 2 : 9);
    s.constant = true;
    return s;
}

Scalar symbol(const std::string& name) {
    Scalar s;
    for (int m = 0; m < kSamples; ++m) s.v[m] = sample_value(name, m);
    s.text = name;
    s.prec = 9;
    s.constant = false;
    return s;
}

bool is_const(const Scalar& s, double x) {
    return s.constant && s.v[0] == x;
}

std::string wrap(const Scalar& s, bool paren) {
    return paren ? "(" + s.text + ")" : s.text;
}

template <class F>
Scalar combine(const Scalar& a, const Scalar& b, F f) {
    Scalar s;
    for (int m = 0; m < kSamples; ++m) s.v[m] = f(a.v[m], b.v[m]);
    s.constant = a.constant && b.constant;
    return s;
}

Scalar neg(const Scalar& a) {
    if (a.constant) return constant(-a.v[0]);
    Scalar s = a;
    for (double& x : s.v) x = -x;
    s.text = "−" + wrap(a, a.prec < 4);
    s.prec = 3;
    return s;
}

Scalar add(const Scalar& a, const Scalar& b) {
    if (a.constant && b.constant) return constant(a.v[0] + b.v[0]);
    if (is_const(a, 0)) return b;
    if (is_const(b, 0)) return a;
    Scalar s = combine(a, b, [](double x, double y) { return x + y; });
    if (b.constant && b.v[0] < 0)
        s.text = a.text + " − " + constant(-b.v[0]).text;
    else if (b.prec == 3 && b.text.rfind("−", 0) == 0)
        s.text = a.text + " − " + b.text.substr(std::string("−").size());
    else
        s.text = a.text + " + " + b.text;
    s.prec = 1;
    return s;
}

Scalar sub(const Scalar& a, const Scalar& b) {
    if (a.constant && b.constant) return constant(a.v[0] - b.v[0]);
    if (is_const(b, 0)) return a;
    if (is_const(a, 0)) return neg(b);
    Scalar s = combine(a, b, [](double x, double y) { return x - y; });
    s.text = a.text + " − " + wrap(b, b.prec <= 1 || (b.prec == 3));
    s.prec = 1;
    return s;
}

Scalar mul(const Scalar& a, const Scalar& b) {
    if (a.constant && b.constant) return constant(a.v[0] * b.v[0]);
    if (is_const(a, 0) || is_const(b, 0)) return constant(0);
    if (is_const(a, 1)) return b;
    if (is_const(b, 1)) return a;
    if (is_const(a, -1)) return neg(b);
    if (is_const(b, -1)) return neg(a);
    Scalar s = combine(a, b, [](double x, double y) { return x * y; });
    const Scalar& l = b.constant ? b : a;  // the number first: "2 t", not "t 2"
    const Scalar& r = b.constant ? a : b;
    s.text = wrap(l, l.prec < 2 || (l.prec == 3 && &l != &a)) + " " + wrap(r, r.prec <= 3);
    s.prec = 2;
    return s;
}

Scalar divide(const Scalar& a, const Scalar& b) {
    if (a.constant && b.constant) return constant(a.v[0] / b.v[0]);
    if (is_const(b, 1)) return a;
    if (is_const(a, 0)) return constant(0);
    Scalar s = combine(a, b, [](double x, double y) { return x / y; });
    s.text =
        wrap(a, a.prec < 2) + "/" + wrap(b, b.prec <= 3 || b.text.find('/') != std::string::npos);
    s.prec = 2;
    return s;
}

Scalar power(const Scalar& a, const Scalar& b) {
    if (a.constant && b.constant) return constant(std::pow(a.v[0], b.v[0]));
    if (is_const(b, 1)) return a;
    if (is_const(b, 0)) return constant(1);
    Scalar s = combine(a, b, [](double x, double y) { return std::pow(x, y); });
    s.text = wrap(a, a.prec < 9) + "^" + wrap(b, b.prec < 9);
    s.prec = 4;
    return s;
}

Scalar function(const char* name, const Scalar& a, double (*f)(double)) {
    if (a.constant) return constant(f(a.v[0]));
    Scalar s = a;
    for (double& x : s.v) x = f(x);
    s.text = std::string(name) + "(" + a.text + ")";
    s.prec = 9;
    return s;
}

double binomial(long long n, long long k) {
    double c = 1;
    for (long long j = 1; j <= k; ++j) c = c * double(n - k + j) / double(j);
    return c;
}

Scalar bernstein(long long n, long long i, const Scalar& t) {
    const double c = binomial(n, i);
    auto f = [&](double x) { return c * std::pow(x, double(i)) * std::pow(1 - x, double(n - i)); };
    Scalar s = t;
    for (double& x : s.v) x = f(x);
    if (t.constant) return constant(s.v[0]);
    s.text = "B(" + std::to_string(n) + "," + std::to_string(i) + "," + t.text + ")";
    s.prec = 9;
    return s;
}

// What a scalar formula is over all the samples: 1, 0, another constant, or a function of the
// scalars (or undefined everywhere: a division by zero).
enum class Verdict : std::uint8_t { One, Zero, Constant, Depends, Undefined };

// `scale` is Σ|a_i| per sample, the size of what was added: a sum is 0 when it is small beside
// that (rounding, 0.1 + 0.2 − 0.3), not when it is merely small (1e-300 P is no vector).
Verdict decide(const Scalar& s, const std::array<double, kSamples>& scale) {
    bool any = false, one = true, zero = true, same = true;
    double first = 0;
    for (int m = 0; m < kSamples; ++m) {
        const double x = s.v[m];
        if (!std::isfinite(x)) continue;
        if (!any) first = x;
        any = true;
        one = one && std::fabs(x - 1) <= kTol;
        zero = zero && std::fabs(x) <= kTol * std::min(1.0, scale[m]);
        same = same && std::fabs(x - first) < kTol * std::max(1.0, std::fabs(first));
    }
    if (!any) return Verdict::Undefined;
    if (one) return Verdict::One;
    if (zero) return Verdict::Zero;
    if (same) return Verdict::Constant;
    return Verdict::Depends;
}

bool undefined_somewhere(const Scalar& s) {
    return std::any_of(s.v.begin(), s.v.end(), [](double x) { return !std::isfinite(x); });
}

// ---- [analysis] -----------------------------------------------------------------------------

struct Val {
    enum class T : std::uint8_t { Scalar, Linear, Bad } t = T::Scalar;
    Scalar s;                        // T::Scalar
    std::vector<Coefficient> terms;  // T::Linear
    std::string why;                 // T::Bad
};

Val bad(std::string why) {
    Val v;
    v.t = Val::T::Bad;
    v.why = std::move(why);
    return v;
}

Val scalar_val(Scalar s) {
    Val v;
    v.s = std::move(s);
    return v;
}

Scalar point_sum(const std::vector<Coefficient>& terms) {
    Scalar s = constant(0);
    for (const auto& c : terms)
        if (c.point) s = add(s, c.value);
    return s;
}

std::array<double, kSamples> point_scale(const std::vector<Coefficient>& terms) {
    std::array<double, kSamples> scale{};
    for (const auto& c : terms)
        if (c.point)
            for (int m = 0; m < kSamples; ++m) scale[m] += std::fabs(c.value.v[m]);
    return scale;
}

// What a combination is: its point-coefficient sum judged beside the coefficients' size.
Verdict verdict_of(const std::vector<Coefficient>& terms) {
    return decide(point_sum(terms), point_scale(terms));
}

bool has_points(const std::vector<Coefficient>& terms) {
    return std::any_of(terms.begin(), terms.end(), [](const Coefficient& c) { return c.point; });
}

// "a point", "a vector", "a scalar", "P + Q (coefficients summing to 2)"
std::string describe(const Val& v, const std::string& text) {
    if (v.t == Val::T::Scalar) return text + " is a scalar";
    const Scalar sum = point_sum(v.terms);
    switch (verdict_of(v.terms)) {
        case Verdict::One:
            return text + " is a point";
        case Verdict::Zero:
            return text + " is a vector";
        default:
            break;
    }
    return text + " is a combination of points whose coefficients sum to " + sum.text;
}

class Analyser {
  public:
    Analyser(const Tree& tree, const Names& names)
        : tree_(tree), names_(names), types_(tree.nodes.size()) {}

    Val run() { return eval(static_cast<int>(tree_.nodes.size()) - 1); }

    std::vector<NodeType> types() const {
        std::vector<NodeType> out;
        for (const auto& t : types_)
            if (t) out.push_back(*t);
        return out;
    }

  private:
    std::string text(int k) const { return tree_.span(tree_.nodes[k]); }

    Val eval(int k) {
        Val v = overflow_check(eval_node(k));
        if (!types_[k]) types_[k] = NodeType{text(k), type_of(v), k};
        return v;
    }

    // A number that left the doubles (1e308 * 10) is refused where it appears, so no infinity
    // reaches a coefficient, a narration or a result.
    static Val overflow_check(Val v) {
        if (v.t == Val::T::Scalar && v.s.constant && !std::isfinite(v.s.v[0]))
            return bad("a number overflows (beyond ±1.8e308) or is undefined");
        if (v.t == Val::T::Linear)
            for (const auto& c : v.terms)
                if (c.value.constant && !std::isfinite(c.value.v[0]))
                    return bad("the coefficient of " + c.name +
                               " overflows (beyond ±1.8e308) or is undefined");
        return v;
    }

    static std::string type_of(const Val& v) {
        if (v.t == Val::T::Bad) return "invalid: " + v.why;
        if (v.t == Val::T::Scalar) return "scalar";
        const Scalar sum = point_sum(v.terms);
        switch (verdict_of(v.terms)) {
            case Verdict::One:
                return "point (Σ = 1)";
            case Verdict::Zero:
                return "vector (Σ = 0)";
            case Verdict::Constant:
                return "Σ = " + sum.text + ": not yet a point or vector";
            case Verdict::Depends:
                return "Σ = " + sum.text + ": depends on the scalars";
            case Verdict::Undefined:
                break;
        }
        return "Σ undefined";
    }

    // An index expression (a subscript) as a whole number, when it is one.
    std::optional<long long> index(int k) const {
        const Node& n = tree_.nodes[k];
        auto kid = [&](int j) { return index(n.kids[j]); };
        switch (n.op) {
            case Op::Number:
                if (n.number == std::floor(n.number) && std::fabs(n.number) < 1e9)
                    return static_cast<long long>(n.number);
                return std::nullopt;
            case Op::Name: {
                if (!n.kids.empty()) return std::nullopt;
                const auto it = env_.find(n.name);
                if (it == env_.end()) return std::nullopt;
                return it->second;
            }
            case Op::Neg: {
                auto a = kid(0);
                if (a) return -*a;
                return std::nullopt;
            }
            case Op::Add:
            case Op::Sub:
            case Op::Mul: {
                auto a = kid(0), b = kid(1);
                if (!a || !b) return std::nullopt;
                if (n.op == Op::Add) return *a + *b;
                if (n.op == Op::Sub) return *a - *b;
                return *a * *b;
            }
            default:
                return std::nullopt;
        }
    }

    Val name(const Node& n) {
        if (n.kids.empty()) {
            const auto it = env_.find(n.name);
            if (it != env_.end()) return scalar_val(constant(double(it->second)));
            return basis(n.name, names_.is_point(n.name), names_.is_vector(n.name));
        }
        const std::string literal = n.name + "_" + tree_.span(tree_.nodes[n.kids[0]]);
        if (names_.is_point(literal) || names_.is_vector(literal))
            return basis(literal, names_.is_point(literal), names_.is_vector(literal));
        const auto k = index(n.kids[0]);
        const bool family_point = names_.is_point(n.name), family_vector = names_.is_vector(n.name);
        if (!k) {
            if (family_point || family_vector)
                return bad("the subscript of " + literal +
                           " is not a whole number or a sum's index");
            return basis(literal, false, false);
        }
        const std::string member = n.name + "_" + std::to_string(*k);
        const bool p = family_point || names_.is_point(member);
        const bool v = family_vector || names_.is_vector(member);
        return basis(member, p, v);
    }

    static Val basis(const std::string& nm, bool point, bool vector) {
        if (!point && !vector) return scalar_val(symbol(nm));
        Val v;
        v.t = Val::T::Linear;
        v.terms.push_back({nm, point, constant(1)});
        return v;
    }

    static Val scale(Val v, const Scalar& c) {
        for (auto& t : v.terms) t.value = mul(c, t.value);
        return v;
    }

    static Val combine_terms(Val a, const Val& b, bool subtract) {
        for (const auto& t : b.terms) {
            auto it = std::find_if(a.terms.begin(), a.terms.end(),
                                   [&](const Coefficient& c) { return c.name == t.name; });
            if (it == a.terms.end())
                a.terms.push_back({t.name, t.point, subtract ? neg(t.value) : t.value});
            else
                it->value = subtract ? sub(it->value, t.value) : add(it->value, t.value);
        }
        return a;
    }

    // Are these a vector (a combination with point coefficients summing to 0)?
    static bool is_vector(const Val& v) {
        return v.t == Val::T::Linear && verdict_of(v.terms) == Verdict::Zero;
    }

    Val eval_node(int k) {
        const Node& n = tree_.nodes[k];
        switch (n.op) {
            case Op::Number:
                return scalar_val(constant(n.number));
            case Op::Name:
                return name(n);
            case Op::Neg: {
                Val a = eval(n.kids[0]);
                if (a.t == Val::T::Bad) return a;
                if (a.t == Val::T::Scalar) return scalar_val(neg(a.s));
                return scale(std::move(a), constant(-1));
            }
            case Op::Add:
            case Op::Sub: {
                Val a = eval(n.kids[0]);
                Val b = eval(n.kids[1]);
                if (a.t == Val::T::Bad) return a;
                if (b.t == Val::T::Bad) return b;
                const bool subtract = n.op == Op::Sub;
                if (a.t == Val::T::Scalar && b.t == Val::T::Scalar)
                    return scalar_val(subtract ? sub(a.s, b.s) : add(a.s, b.s));
                if (a.t == Val::T::Linear && b.t == Val::T::Linear)
                    return combine_terms(std::move(a), b, subtract);
                const Val& s = a.t == Val::T::Scalar ? a : b;
                const Val& l = a.t == Val::T::Scalar ? b : a;
                const int sk = a.t == Val::T::Scalar ? n.kids[0] : n.kids[1];
                const int lk = a.t == Val::T::Scalar ? n.kids[1] : n.kids[0];
                (void)s;
                return bad(std::string("a scalar and a point or vector cannot be ") +
                           (subtract ? "subtracted" : "added") + " (" + text(sk) +
                           " is a scalar; " + describe(l, text(lk)) + ")");
            }
            case Op::Mul: {
                Val a = eval(n.kids[0]);
                Val b = eval(n.kids[1]);
                if (a.t == Val::T::Bad) return a;
                if (b.t == Val::T::Bad) return b;
                if (a.t == Val::T::Scalar && b.t == Val::T::Scalar)
                    return scalar_val(mul(a.s, b.s));
                if (a.t == Val::T::Scalar) return scale(std::move(b), a.s);
                if (b.t == Val::T::Scalar) return scale(std::move(a), b.s);
                return bad("points and vectors cannot be multiplied together (" +
                           describe(a, text(n.kids[0])) + "; " + describe(b, text(n.kids[1])) +
                           "); vectors have · and × instead");
            }
            case Op::Div: {
                Val a = eval(n.kids[0]);
                Val b = eval(n.kids[1]);
                if (a.t == Val::T::Bad) return a;
                if (b.t == Val::T::Bad) return b;
                if (b.t != Val::T::Scalar)
                    return bad("nothing can be divided by a point or vector (" +
                               describe(b, text(n.kids[1])) + ")");
                if (std::all_of(b.s.v.begin(), b.s.v.end(), [](double x) { return x == 0; }))
                    return bad("division by zero (" + text(n.kids[1]) + " = 0)");
                if (a.t == Val::T::Scalar) return scalar_val(divide(a.s, b.s));
                return scale(std::move(a), divide(constant(1), b.s));
            }
            case Op::Pow: {
                Val a = eval(n.kids[0]);
                Val b = eval(n.kids[1]);
                if (a.t == Val::T::Bad) return a;
                if (b.t == Val::T::Bad) return b;
                if (a.t != Val::T::Scalar || b.t != Val::T::Scalar)
                    return bad("only scalars have powers (" +
                               describe(a.t != Val::T::Scalar ? a : b,
                                        text(n.kids[a.t != Val::T::Scalar ? 0 : 1])) +
                               ")");
                return scalar_val(power(a.s, b.s));
            }
            case Op::Dot:
            case Op::Cross: {
                Val a = eval(n.kids[0]);
                Val b = eval(n.kids[1]);
                if (a.t == Val::T::Bad) return a;
                if (b.t == Val::T::Bad) return b;
                const char* op = n.op == Op::Dot ? "·" : "×";
                for (int j = 0; j < 2; ++j) {
                    const Val& x = j == 0 ? a : b;
                    if (!is_vector(x))
                        return bad(std::string(op) + " takes two vectors, but " +
                                   describe(x, text(n.kids[j])) +
                                   (x.t == Val::T::Scalar ? ""
                                    : has_points(x.terms) && verdict_of(x.terms) == Verdict::One
                                        ? " (points cannot be dotted or crossed)"
                                        : ""));
                }
                auto operand = [&](int kid) {
                    const std::string t = text(kid);
                    const bool simple = t.find_first_of(" +−-*/·×") == std::string::npos;
                    return simple || (t.front() == '(' && t.back() == ')') ? t : "(" + t + ")";
                };
                const std::string product =
                    operand(n.kids[0]) + " " + op + " " + operand(n.kids[1]);
                if (n.op == Op::Dot) {
                    // A number that depends on coordinates the question does not give: a fresh
                    // scalar.
                    return scalar_val(symbol(product));
                }
                return basis(product, false, true);
            }
            case Op::Sin:
            case Op::Cos: {
                Val a = eval(n.kids[0]);
                if (a.t == Val::T::Bad) return a;
                const char* f = n.op == Op::Sin ? "sin" : "cos";
                if (a.t != Val::T::Scalar)
                    return bad(std::string(f) + " takes a scalar, but " +
                               describe(a, text(n.kids[0])));
                return scalar_val(function(f, a.s,
                                           n.op == Op::Sin
                                               ? static_cast<double (*)(double)>(std::sin)
                                               : static_cast<double (*)(double)>(std::cos)));
            }
            case Op::Bernstein: {
                Val nn = eval(n.kids[0]);
                Val ii = eval(n.kids[1]);
                Val tt = eval(n.kids[2]);
                for (const Val* x : {&nn, &ii, &tt})
                    if (x->t == Val::T::Bad) return *x;
                auto whole = [](const Val& x) {
                    return x.t == Val::T::Scalar && x.s.constant &&
                           x.s.v[0] == std::floor(x.s.v[0]) && std::fabs(x.s.v[0]) <= 1000;
                };
                if (!whole(nn) || !whole(ii)) return bad("B(n, i, t) needs whole numbers n and i");
                const auto nv = static_cast<long long>(nn.s.v[0]),
                           iv = static_cast<long long>(ii.s.v[0]);
                if (nv < 0 || iv < 0 || iv > nv)
                    return bad("B(n, i, t) needs 0 ≤ i ≤ n, got n = " + std::to_string(nv) +
                               ", i = " + std::to_string(iv));
                if (tt.t != Val::T::Scalar)
                    return bad("B(n, i, t) takes a scalar t, but " + describe(tt, text(n.kids[2])));
                return scalar_val(bernstein(nv, iv, tt.s));
            }
            case Op::Sum: {
                const auto saved = env_.find(n.name) != env_.end()
                                       ? std::optional<long long>(env_[n.name])
                                       : std::nullopt;
                Val total;
                bool first = true;
                for (long long i = n.lo; i <= n.hi; ++i) {
                    env_[n.name] = i;
                    Val term = eval(n.kids[0]);
                    if (term.t == Val::T::Bad) {
                        total = term;
                        break;
                    }
                    if (first) {
                        total = std::move(term);
                        first = false;
                        continue;
                    }
                    if (total.t != term.t) {
                        total = bad("the sum mixes scalars with points or vectors");
                        break;
                    }
                    total = total.t == Val::T::Scalar
                                ? scalar_val(add(total.s, term.s))
                                : combine_terms(std::move(total), term, false);
                }
                if (saved)
                    env_[n.name] = *saved;
                else
                    env_.erase(n.name);
                return total;
            }
        }
        return bad("unknown operation");
    }

    const Tree& tree_;
    const Names& names_;
    std::vector<std::optional<NodeType>> types_;
    std::map<std::string, long long> env_;
};

// Which identity makes a non-constant sum 0 or 1, for the reason line.
std::string identity_of(const Scalar& sum) {
    if (sum.text.find("B(") != std::string::npos)
        return "the Bernstein polynomials of one degree sum to 1 for every t";
    if (sum.text.find("sin") != std::string::npos || sum.text.find("cos") != std::string::npos)
        return "sin² + cos² = 1 for every angle";
    return "the terms in the scalars cancel for every value";
}

void collect_scalars(const Tree& tree, const Names& names, int k, std::vector<std::string>& bound,
                     std::vector<std::pair<std::string, int>>& out) {
    const Node& n = tree.nodes[k];
    if (n.op == Op::Name) {
        const bool is_bound = std::find(bound.begin(), bound.end(), n.name) != bound.end();
        if (n.kids.empty()) {
            if (!is_bound && !names.is_point(n.name) && !names.is_vector(n.name))
                out.emplace_back(n.name, n.begin + 1);
            return;
        }
        const std::string literal = n.name + "_" + tree.span(tree.nodes[n.kids[0]]);
        if (!names.is_point(literal) && !names.is_vector(literal) && !names.is_point(n.name) &&
            !names.is_vector(n.name))
            out.emplace_back(n.name, n.begin + 1);
        collect_scalars(tree, names, n.kids[0], bound, out);
        return;
    }
    if (n.op == Op::Sum) {
        bound.push_back(n.name);
        collect_scalars(tree, names, n.kids[0], bound, out);
        bound.pop_back();
        return;
    }
    for (int kid : n.kids) collect_scalars(tree, names, kid, bound, out);
}

}  // namespace

std::vector<std::pair<std::string, int>> scalar_names(const Tree& tree, const Names& names) {
    std::vector<std::pair<std::string, int>> out;
    std::vector<std::string> bound;
    if (!tree.nodes.empty())
        collect_scalars(tree, names, static_cast<int>(tree.nodes.size()) - 1, bound, out);
    return out;
}

Analysis analyse(const Tree& tree, const Names& names) {
    Analysis a;
    Analyser an(tree, names);
    Val v = an.run();
    a.nodes = an.types();
    switch (v.t) {
        case Val::T::Bad:
            a.kind = Kind::Invalid;
            a.reason = v.why;
            return a;
        case Val::T::Scalar:
            a.kind = Kind::Scalar;
            a.reason = undefined_somewhere(v.s)
                           ? "a scalar (undefined for some values of its names)"
                           : "no points or vectors remain: a number";
            return a;
        case Val::T::Linear:
            break;
    }
    a.coefficients = v.terms;
    a.has_sum = true;
    a.sum = point_sum(v.terms);
    // The addition as a student writes it: "3 − 2", "(1 − t) + t", "B(3,0,t) + … + B(3,3,t)".
    for (const auto& c : v.terms) {
        if (!c.point) continue;
        const std::string& t = c.value.text;
        const std::string minus = "−";
        if (a.sum_terms.empty())
            a.sum_terms = c.value.prec == 1 ? "(" + t + ")" : t;
        else if (t.rfind(minus, 0) == 0 && c.value.prec != 1)
            a.sum_terms += " − " + t.substr(minus.size());
        else
            a.sum_terms += " + " + (c.value.prec == 1 ? "(" + t + ")" : t);
    }
    if (a.sum_terms.empty()) a.sum_terms = "0";
    const std::string shown =
        a.sum_terms == a.sum.text ? a.sum.text : a.sum_terms + " = " + a.sum.text;
    const bool points = has_points(v.terms);
    const Verdict verdict = verdict_of(v.terms);
    if ((verdict == Verdict::One || verdict == Verdict::Zero) && !a.sum.constant)
        a.identity = identity_of(a.sum);
    const std::string because = a.identity.empty() ? "" : " (" + a.identity + ")";
    switch (verdict) {
        case Verdict::One:
            a.kind = Kind::Point;
            a.reason = "the point coefficients sum to " +
                       (a.sum.constant ? shown : a.sum_terms + " = 1") + because +
                       ": an affine combination, a point";
            break;
        case Verdict::Zero:
            a.kind = Kind::Vector;
            a.reason = points ? "the point coefficients sum to " +
                                    (a.sum.constant ? shown : a.sum_terms + " = 0") + because +
                                    ": a vector"
                              : "only vectors appear: a vector";
            break;
        case Verdict::Constant:
            a.kind = Kind::Invalid;
            a.reason =
                "the point coefficients sum to " + shown +
                ", neither 1 (a point) nor 0 (a vector): the result would move with the origin";
            break;
        case Verdict::Depends:
            a.kind = Kind::Invalid;
            a.depends = true;
            a.reason = "the point coefficients sum to " + shown +
                       ", which is not 1 or 0 for every value of its scalars: a point or vector "
                       "only for some values";
            break;
        case Verdict::Undefined:
            a.kind = Kind::Invalid;
            a.reason = "the point coefficients sum to " + a.sum_terms +
                       ", which overflows (beyond ±1.8e308)";
            break;
    }
    return a;
}

}  // namespace cg::affine
