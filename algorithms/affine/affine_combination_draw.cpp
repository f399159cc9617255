// Affine combinations, the picture. The current expression's parse tree, root at the top, each
// node labelled with its operator and its type and coloured by it (point green, vector teal,
// scalar grey, meaningless red, a partial sum Σ not yet 1 or 0 orange); under it, the verdicts so
// far, the current expression orange; drawn in the world without its grid (the coordinates are only
// the layout's). Expressions are written as a person writes them, not as
// they are typed: "sum_{i=0}^{3} B(3,i,t) P_i" is shown as "Σᵢ₌₀³ Bᵢ³(t) Pᵢ" (display()).
#include <algorithm>
#include <cmath>

#include "affine/affine_combination.hpp"
#include "core/format.hpp"

namespace cg {

// ---- the typed syntax as a person writes it ---------------------------------------------------

namespace {

std::u32string utf32(const std::string& s) {
    std::u32string out;
    for (std::size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        const int len = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : 4;
        char32_t c = len == 1 ? b : len == 2 ? b & 0x1F : len == 3 ? b & 0x0F : b & 0x07;
        for (int k = 1; k < len && i + k < s.size(); ++k)
            c = (c << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
        out.push_back(c);
        i += len;
    }
    return out;
}

std::string utf8(const std::u32string& s) {
    std::string out;
    for (char32_t c : s) {
        if (c < 0x80) {
            out.push_back(static_cast<char>(c));
        } else if (c < 0x800) {
            out.push_back(static_cast<char>(0xC0 | (c >> 6)));
            out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
        } else if (c < 0x10000) {
            out.push_back(static_cast<char>(0xE0 | (c >> 12)));
            out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
            out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
        } else {
            out.push_back(static_cast<char>(0xF0 | (c >> 18)));
            out.push_back(static_cast<char>(0x80 | ((c >> 12) & 0x3F)));
            out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
            out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
        }
    }
    return out;
}

bool letter(char32_t c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}
bool digit(char32_t c) {
    return c >= '0' && c <= '9';
}

// One character raised or lowered, or 0 when Unicode has no such character.
char32_t script(char32_t c, bool up) {
    if (digit(c)) {
        static const char32_t sup[] = U"⁰¹²³⁴⁵⁶⁷⁸⁹";
        return up ? sup[c - '0'] : char32_t(0x2080 + (c - '0'));
    }
    switch (c) {
        case '+':
            return up ? U'⁺' : U'₊';
        case '-':
        case U'−':
            return up ? U'⁻' : U'₋';
        case '=':
            return up ? U'⁼' : U'₌';
        case '(':
            return up ? U'⁽' : U'₍';
        case ')':
            return up ? U'⁾' : U'₎';
        default:
            break;
    }
    if (c < 'a' || c > 'z') return 0;
    static const char32_t sup[] = U"ᵃᵇᶜᵈᵉᶠᵍʰⁱʲᵏˡᵐⁿᵒᵖ\0ʳˢᵗᵘᵛʷˣʸᶻ";
    static const char32_t sub[] = U"ₐ\0\0\0ₑ\0\0ₕᵢⱼₖₗₘₙₒₚ\0ᵣₛₜᵤᵥ\0ₓ\0\0";
    return (up ? sup : sub)[c - 'a'];
}

// `s` raised or lowered whole (spaces dropped), or false when a character cannot be.
bool scripted(const std::u32string& s, bool up, std::u32string& out) {
    std::u32string r;
    for (char32_t c : s) {
        if (c == ' ') continue;
        const char32_t x = script(c, up);
        if (!x) return false;
        r.push_back(x);
    }
    if (r.empty()) return false;
    out += r;
    return true;
}

// The index of the bracket closing the one at `open`, or npos.
std::size_t closing(const std::u32string& s, std::size_t open) {
    const char32_t a = s[open], b = a == '(' ? ')' : a == '{' ? '}' : 0;
    int depth = 0;
    for (std::size_t i = open; i < s.size(); ++i) {
        if (s[i] == a) ++depth;
        if (s[i] == b && --depth == 0) return i;
    }
    return std::u32string::npos;
}

// What follows a ^ or a _ at `at`: a braced or parenthesised group (`inner` without the braces;
// parentheses are kept), a number, or a name. Returns the index after it (at when nothing).
std::size_t script_operand(const std::u32string& s, std::size_t at, std::u32string& inner) {
    inner.clear();
    if (at >= s.size()) return at;
    if (s[at] == '{' || s[at] == '(') {
        const std::size_t end = closing(s, at);
        if (end == std::u32string::npos) return at;
        inner = s[at] == '{' ? s.substr(at + 1, end - at - 1) : s.substr(at, end - at + 1);
        return end + 1;
    }
    std::size_t i = at;
    if (s[i] == '-' || s[i] == U'−') ++i;
    if (i < s.size() && digit(s[i]))
        while (i < s.size() && digit(s[i])) ++i;
    else if (i < s.size() && letter(s[i]))
        while (i < s.size() && (letter(s[i]) || digit(s[i]))) ++i;
    else
        return at;
    inner = s.substr(at, i - at);
    return i;
}

std::u32string display32(const std::u32string& s);

// The arguments of a call whose '(' is at `open`, split at its top-level commas.
std::vector<std::u32string> arguments(const std::u32string& s, std::size_t open,
                                      std::size_t close) {
    std::vector<std::u32string> out(1);
    int depth = 0;
    for (std::size_t i = open + 1; i < close; ++i) {
        if (s[i] == '(' || s[i] == '{') ++depth;
        if (s[i] == ')' || s[i] == '}') --depth;
        if (s[i] == ',' && depth == 0)
            out.emplace_back();
        else
            out.back().push_back(s[i]);
    }
    return out;
}

std::u32string trimmed(const std::u32string& s) {
    const std::size_t a = s.find_first_not_of(U' '), b = s.find_last_not_of(U' ');
    return a == std::u32string::npos ? std::u32string() : s.substr(a, b - a + 1);
}

std::u32string display32(const std::u32string& s) {
    std::u32string out;
    std::size_t i = 0;
    while (i < s.size()) {
        const char32_t c = s[i];
        if (letter(c) && (i == 0 || !(letter(s[i - 1]) || digit(s[i - 1])))) {
            std::size_t j = i;
            while (j < s.size() && (letter(s[j]) || digit(s[j]))) ++j;
            const std::u32string word = s.substr(i, j - i);
            const bool call = j < s.size() && s[j] == '(';
            const std::size_t close = call ? closing(s, j) : std::u32string::npos;
            if (word == U"sum") {
                out += U'Σ';
            } else if (word == U"dot") {
                out += U'·';
            } else if (word == U"cross") {
                out += U'×';
            } else if (word == U"B" && close != std::u32string::npos) {
                // B(n, i, t), the Bernstein polynomial, as the course writes it: Bᵢⁿ(t).
                const auto args = arguments(s, j, close);
                std::u32string b = U"B";
                if (args.size() == 3 && scripted(trimmed(args[1]), false, b) &&
                    scripted(trimmed(args[0]), true, b)) {
                    out += b + U"(" + display32(trimmed(args[2])) + U")";
                    i = close + 1;
                    continue;
                }
                out += word;
            } else if ((word == U"sin" || word == U"cos") && close != std::u32string::npos &&
                       close + 1 < s.size() && s[close + 1] == '^') {
                // sin(t)^2 as sin²(t).
                std::u32string power, raised;
                const std::size_t after = script_operand(s, close + 2, power);
                if (after > close + 2 && scripted(display32(power), true, raised)) {
                    out += word + raised + display32(s.substr(j, close - j + 1));
                    i = after;
                    continue;
                }
                out += word;
            } else {
                out += word;
            }
            i = j;
            continue;
        }
        if (c == '^' || c == '_') {
            std::u32string operand;
            const std::size_t after = script_operand(s, i + 1, operand);
            if (after > i + 1 && scripted(display32(operand), c == '^', out)) {
                i = after;
                continue;
            }
            out += c;
            ++i;
            continue;
        }
        out += c == '-' ? U'−' : c;
        ++i;
    }
    return out;
}

}  // namespace

std::string AffineCombination::display(const std::string& expression) {
    return utf8(display32(utf32(expression)));
}

// ---- the parse tree -----------------------------------------------------------------------------

namespace {

using affine::Kind;

Role role_of(const std::string& type) {
    if (type.rfind("point", 0) == 0) return Role::Kept;
    if (type.rfind("vector", 0) == 0) return Role::Entering;
    if (type.rfind("scalar", 0) == 0) return Role::Neutral;
    if (type.rfind("invalid", 0) == 0) return Role::Discarded;
    return Role::Active;  // a partial sum, not yet a point or vector
}

std::string short_type(const std::string& type) {
    if (type.rfind("point", 0) == 0) return "point";
    if (type.rfind("vector", 0) == 0) return "vector";
    if (type.rfind("scalar", 0) == 0) return "scalar";
    if (type.rfind("invalid", 0) == 0) return "invalid";
    const auto colon = type.find(':');
    return AffineCombination::display(colon == std::string::npos ? type : type.substr(0, colon));
}

std::string op_text(const affine::Tree& t, const affine::Node& n) {
    using affine::Op;
    switch (n.op) {
        case Op::Number:
            return num(n.number);
        case Op::Name:
            return AffineCombination::display(t.span(n));
        case Op::Neg:
            return "−x";
        case Op::Add:
            return "+";
        case Op::Sub:
            return "−";
        case Op::Mul:
            return "*";
        case Op::Div:
            return "/";
        case Op::Pow:
            return "xⁿ";
        case Op::Dot:
            return "·";
        case Op::Cross:
            return "×";
        case Op::Sin:
            return "sin";
        case Op::Cos:
            return "cos";
        case Op::Bernstein:
            return "B";
        case Op::Sum:
            return AffineCombination::display("sum_{" + n.name + "=" + std::to_string(n.lo) +
                                              "}^{" + std::to_string(n.hi) + "}");
    }
    return "?";
}

struct Layout {
    std::vector<glm::dvec2> at;
    double next_leaf = 0;
    int depth = 0;
};

// A sub-expression drawn as one leaf: a name, a number, or (once typed) a whole scalar — the
// analysis only cares that a coefficient is a number, not how it is built.
bool is_leaf(const affine::Node& n, const std::string& type, bool root) {
    return n.op == affine::Op::Name || n.op == affine::Op::Number || n.kids.empty() ||
           (!root && type == "scalar");
}

// In-order leaves, parents centred over their children.
void place(const affine::Tree& t, const std::vector<std::string>& type, int k, int depth,
           Layout& l) {
    const affine::Node& n = t.nodes[k];
    constexpr double kDx = 1.6, kDy = 1.4;
    l.depth = std::max(l.depth, depth);
    if (is_leaf(n, type[k], depth == 0)) {
        l.at[k] = {l.next_leaf * kDx, -depth * kDy};
        l.next_leaf += 1;
        return;
    }
    double x = 0;
    for (int kid : n.kids) {
        place(t, type, kid, depth + 1, l);
        x += l.at[kid].x;
    }
    l.at[k] = {x / double(n.kids.size()), -depth * kDy};
}

}  // namespace

void AffineCombination::draw(const State& s, Scene& scene) {
    const Parsed& p = *s.in;
    const int shown = std::max(0, s.k);
    const affine::Tree& tree = p.trees[shown];
    scene.world_grid = false;  // a parse tree: its coordinates mean nothing to the student
    const int root = static_cast<int>(tree.nodes.size()) - 1;
    std::vector<std::string> type(tree.nodes.size());
    if (s.k >= 0)
        for (const auto& nt : s.analysis.nodes) type[nt.node] = nt.type;
    Layout l;
    l.at.assign(tree.nodes.size(), glm::dvec2(0));
    place(tree, type, root, 0, l);

    auto visit = [&](auto&& self, int k) -> void {
        const affine::Node& n = tree.nodes[k];
        const bool leaf = is_leaf(n, type[k], k == root);
        if (!leaf)
            for (int kid : n.kids) {
                scene.segments.push_back(
                    {l.at[k], l.at[kid], "", {Role::Construction, 1.5f}, false});
                self(self, kid);
            }
        const Role role = type[k].empty() ? Role::Subject : role_of(type[k]);
        const std::string op = leaf && n.op != affine::Op::Name && n.op != affine::Op::Number
                                   ? display(tree.span(n))
                                   : op_text(tree, n);
        const std::string label = op + (type[k].empty() ? "" : "  " + short_type(type[k]));
        // The root's verdict is the step's answer: placed first.
        scene.points.push_back(
            {l.at[k], label, {role, 2.0f}, k == root ? 7.0f : 5.0f, k == root ? 20 : 0});
    };
    visit(visit, root);

    // The verdicts so far, one line each, under the tree.
    const double x = (l.next_leaf - 1) * 1.6 / 2;
    const double top = -(l.depth + 1.5) * 1.4;
    scene.labels.push_back({{x, top}, "expressions", {Role::Neutral}});
    for (int j = 0; j < static_cast<int>(p.expressions.size()); ++j) {
        std::string line = std::to_string(j + 1) + ". " + display(p.expressions[j]);
        Role role = Role::Subject;
        if (j < static_cast<int>(s.rows.size())) {
            const Row& r = s.rows[j];
            line += "  →  " + std::string(r.kind == Kind::Invalid ? "meaningless"
                                                                  : affine::kind_name(r.kind));
            role = r.kind == Kind::Point    ? Role::Kept
                   : r.kind == Kind::Vector ? Role::Entering
                   : r.kind == Kind::Scalar ? Role::Neutral
                                            : Role::Discarded;
        }
        if (j == s.k) role = Role::Active;
        scene.labels.push_back({{x, top - 0.9 * (j + 1)}, line, {role}});
    }
}

}  // namespace cg
