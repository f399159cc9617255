// Sections: [tables] [scripts and fractions] [environments] [the converter] [text].
#include "viewer/math_text.hpp"

#include <cctype>
#include <initializer_list>
#include <map>
#include <vector>

namespace cg::viewer {

namespace {

// --- [tables] --------------------------------------------------------------------------------

// Commands that stand for one symbol. Function names (\max, \cos, …) are not listed: an
// unknown command is shown by its name anyway.
// The tables read best as tables.
// clang-format off
const std::map<std::string_view, std::string_view>& symbols() {
    static const std::map<std::string_view, std::string_view> table = {
        // relations and operators
        {"le", "≤"}, {"leq", "≤"}, {"ge", "≥"}, {"geq", "≥"}, {"ne", "≠"}, {"neq", "≠"},
        {"lt", "<"}, {"gt", ">"}, {"approx", "≈"}, {"sim", "∼"}, {"simeq", "≃"}, {"equiv", "≡"},
        {"propto", "∝"}, {"cdot", "·"}, {"times", "×"}, {"div", "÷"}, {"pm", "±"}, {"mp", "∓"},
        {"ast", "∗"}, {"star", "⋆"}, {"circ", "∘"}, {"bullet", "•"}, {"oplus", "⊕"},
        {"otimes", "⊗"}, {"in", "∈"}, {"notin", "∉"}, {"ni", "∋"}, {"subset", "⊂"},
        {"subseteq", "⊆"}, {"supset", "⊃"}, {"supseteq", "⊇"}, {"cup", "∪"}, {"cap", "∩"},
        {"setminus", "∖"}, {"emptyset", "∅"}, {"varnothing", "∅"}, {"forall", "∀"},
        {"exists", "∃"}, {"nexists", "∄"}, {"neg", "¬"}, {"lnot", "¬"}, {"land", "∧"}, {"wedge", "∧"}, {"lor", "∨"},
        {"vee", "∨"}, {"perp", "⊥"}, {"parallel", "∥"}, {"angle", "∠"}, {"mid", "|"},
        // arrows
        {"to", "→"}, {"rightarrow", "→"}, {"leftarrow", "←"}, {"gets", "←"},
        {"leftrightarrow", "↔"}, {"mapsto", "↦"}, {"Rightarrow", "⇒"}, {"implies", "⇒"},
        {"Leftarrow", "⇐"}, {"Leftrightarrow", "⇔"}, {"iff", "⇔"}, {"uparrow", "↑"},
        {"downarrow", "↓"},
        // big operators and calculus
        {"sum", "∑"}, {"prod", "∏"}, {"int", "∫"}, {"iint", "∬"}, {"iiint", "∭"}, {"oint", "∮"},
        {"partial", "∂"}, {"nabla", "∇"}, {"infty", "∞"},
        {"ll", "≪"}, {"gg", "≫"}, {"leqslant", "≤"}, {"geqslant", "≥"}, {"lesssim", "≲"},
        {"gtrsim", "≳"}, {"bmod", " mod "}, {"mod", " mod "}, {"triangle", "△"},
        {"square", "□"}, {"checkmark", "✓"}, {"cross", "✗"}, {"top", "⊤"}, {"intercal", "ᵀ"},
        // delimiters
        {"lvert", "|"}, {"rvert", "|"}, {"vert", "|"}, {"lVert", "‖"}, {"rVert", "‖"},
        {"Vert", "‖"}, {"langle", "⟨"}, {"rangle", "⟩"}, {"lceil", "⌈"}, {"rceil", "⌉"},
        {"lfloor", "⌊"}, {"rfloor", "⌋"}, {"lbrace", "{"}, {"rbrace", "}"}, {"lbrack", "["},
        {"rbrack", "]"},
        // dots, spaces and the rest
        {"dots", "…"}, {"ldots", "…"}, {"cdots", "⋯"}, {"vdots", "⋮"}, {"ddots", "⋱"},
        {"quad", "\u2003"}, {"qquad", "\u2003\u2003"}, {"prime", "′"}, {"degree", "°"},
        {"ell", "ℓ"}, {"hbar", "ℏ"},
        // Greek
        {"alpha", "α"}, {"beta", "β"}, {"gamma", "γ"}, {"delta", "δ"}, {"epsilon", "ε"},
        {"varepsilon", "ε"}, {"zeta", "ζ"}, {"eta", "η"}, {"theta", "θ"}, {"vartheta", "ϑ"},
        {"iota", "ι"}, {"kappa", "κ"}, {"lambda", "λ"}, {"mu", "μ"}, {"nu", "ν"}, {"xi", "ξ"},
        {"omicron", "ο"}, {"pi", "π"}, {"varpi", "ϖ"}, {"rho", "ρ"}, {"varrho", "ϱ"},
        {"sigma", "σ"}, {"varsigma", "ς"}, {"tau", "τ"}, {"upsilon", "υ"}, {"phi", "φ"},
        {"varphi", "φ"}, {"chi", "χ"}, {"psi", "ψ"}, {"omega", "ω"}, {"Gamma", "Γ"},
        {"Delta", "Δ"}, {"Theta", "Θ"}, {"Lambda", "Λ"}, {"Xi", "Ξ"}, {"Pi", "Π"}, {"Sigma", "Σ"},
        {"Upsilon", "Υ"}, {"Phi", "Φ"}, {"Psi", "Ψ"}, {"Omega", "Ω"},
    };
    return table;
}
// clang-format on

// Escapes of one non-letter character: spacing, and characters LaTeX reserves.
std::string_view escaped(char c) {
    switch (c) {
        case ',':
            return "\u2009";  // thin space
        case ';':
        case ':':
        case ' ':
            return " ";
        case '!':
            return "";  // negative thin space: none
        case '|':
            return "‖";
        case '\\':
            return "; ";  // a line break outside a matrix
        default:
            return {};
    }
}

bool one_of(std::string_view name, std::initializer_list<std::string_view> names) {
    for (std::string_view n : names)
        if (n == name) return true;
    return false;
}

// clang-format off
// Commands whose argument is shown as it is (converted), dropping the styling.
bool is_style(std::string_view name) {
    return one_of(name, {"mathrm", "mathbf", "mathit", "mathsf", "mathtt", "mathcal",
                         "operatorname", "boldsymbol", "bm", "vec", "hat", "bar", "overline",
                         "underline", "tilde", "widehat", "widetilde", "dot", "ddot",
                         "mathring", "displaystyle", "textstyle", "scriptstyle", "overrightarrow", "overleftarrow",
                         "underbrace", "overbrace"});
}

// \text{…} and friends hold words, not math: no '-' → '−' there.
bool is_text(std::string_view name) {
    return one_of(name, {"text", "textrm", "textbf", "textit", "textsf", "texttt", "mbox"});
}

// Sizing commands before a delimiter: the delimiter alone is kept.
bool is_sizing(std::string_view name) {
    return one_of(name, {"left", "right", "middle", "big", "Big", "bigg", "Bigg", "bigl", "bigr",
                         "Bigl", "Bigr", "biggl", "biggr"});
}

// Function names get a space before a following letter, as LaTeX sets "cos θ".
bool is_function(std::string_view name) {
    return one_of(name, {"sin", "cos", "tan", "cot", "sec", "csc", "arcsin", "arccos", "arctan",
                         "sinh", "cosh", "tanh", "log", "ln", "exp", "max", "min", "det", "lim",
                         "sup", "inf", "arg", "gcd", "deg", "dim", "ker"});
}
// clang-format on

// --- [scripts and fractions] -----------------------------------------------------------------

// One UTF-8 code point at s[i]; advances i.
std::string_view next_char(std::string_view s, std::size_t& i) {
    std::size_t n = 1;
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0xf0)
        n = 4;
    else if (c >= 0xe0)
        n = 3;
    else if (c >= 0xc0)
        n = 2;
    n = std::min(n, s.size() - i);
    const std::string_view out = s.substr(i, n);
    i += n;
    return out;
}

std::vector<std::string_view> chars(std::string_view s) {
    std::vector<std::string_view> out;
    for (std::size_t i = 0; i < s.size();) out.push_back(next_char(s, i));
    return out;
}

// clang-format off
const std::map<std::string_view, std::string_view>& subscripts() {
    static const std::map<std::string_view, std::string_view> table = {
        {"0", "₀"}, {"1", "₁"}, {"2", "₂"}, {"3", "₃"}, {"4", "₄"}, {"5", "₅"}, {"6", "₆"},
        {"7", "₇"}, {"8", "₈"}, {"9", "₉"}, {"+", "₊"}, {"−", "₋"}, {"-", "₋"}, {"=", "₌"},
        {"(", "₍"}, {")", "₎"}, {"i", "ᵢ"}, {"j", "ⱼ"}, {"k", "ₖ"}, {"l", "ₗ"}, {"m", "ₘ"},
        {"n", "ₙ"}};
    return table;
}

const std::map<std::string_view, std::string_view>& superscripts() {
    static const std::map<std::string_view, std::string_view> table = {
        {"0", "⁰"}, {"1", "¹"}, {"2", "²"}, {"3", "³"}, {"4", "⁴"}, {"5", "⁵"}, {"6", "⁶"},
        {"7", "⁷"}, {"8", "⁸"}, {"9", "⁹"}, {"+", "⁺"}, {"−", "⁻"}, {"-", "⁻"}, {"=", "⁼"},
        {"(", "⁽"}, {")", "⁾"}, {"a", "ᵃ"}, {"b", "ᵇ"}, {"c", "ᶜ"}, {"d", "ᵈ"}, {"e", "ᵉ"},
        {"f", "ᶠ"}, {"g", "ᵍ"}, {"h", "ʰ"}, {"i", "ⁱ"}, {"j", "ʲ"}, {"k", "ᵏ"}, {"l", "ˡ"},
        {"m", "ᵐ"}, {"n", "ⁿ"}, {"o", "ᵒ"}, {"p", "ᵖ"}, {"r", "ʳ"}, {"s", "ˢ"}, {"t", "ᵗ"},
        {"u", "ᵘ"}, {"v", "ᵛ"}, {"w", "ʷ"}, {"x", "ˣ"}, {"y", "ʸ"}, {"z", "ᶻ"}, {"T", "ᵀ"},
        {"*", "*"}, {"′", "′"}, {"'", "′"}, {"∘", "°"}, {"°", "°"}};
    return table;
}
// clang-format on

bool has_letter_run(std::string_view s) {
    for (std::size_t i = 0; i + 1 < s.size(); ++i)
        if (std::isalpha(static_cast<unsigned char>(s[i])) &&
            std::isalpha(static_cast<unsigned char>(s[i + 1])))
            return true;
    return false;
}

// x_{…} or x^{…} with an already converted argument: Unicode scripts where every character
// has one and no word is spelled out ("min" reads better as _min than as ₘᵢₙ).
std::string script(const std::string& arg, bool super) {
    const auto& table = super ? superscripts() : subscripts();
    std::string mapped;
    bool ok = !arg.empty() && !has_letter_run(arg);
    for (std::string_view c : chars(arg)) {
        if (!ok) break;
        const auto it = table.find(c);
        if (it == table.end())
            ok = false;
        else
            mapped += it->second;
    }
    if (ok) return mapped;
    const bool one = chars(arg).size() == 1;
    const bool spaced = arg.find(' ') != std::string::npos;
    if (super) return one ? "^" + arg : "^(" + arg + ")";
    return spaced ? "_(" + arg + ")" : "_" + arg;
}

// True when `s` can stand beside "/" without parentheses: one term, such as "q₁", "-4",
// "x_min" or "side(S)"; false for sums, products and anything spaced.
bool is_simple(const std::string& s) {
    static const std::vector<std::string_view> operators = {"−", "·", "×", "÷", "±",      "∓",
                                                            "≤", "≥", "≠", "≈", "→",      "←",
                                                            "∈", "∪", "∩", "∘", "\u2003", "\u2009"};
    int depth = 0;
    bool first = true;
    for (std::string_view c : chars(s)) {
        const bool leading_minus = first && (c == "−" || c == "-");
        first = false;
        if (c == "(" || c == "[" || c == "{")
            ++depth;
        else if (c == ")" || c == "]" || c == "}")
            --depth;
        else if (depth > 0 || leading_minus)
            continue;
        else if (c.size() == 1) {
            const auto b = static_cast<unsigned char>(c[0]);
            if (!std::isalnum(b) && c != "." && c != "_" && c != "'" && c != "!") return false;
        } else {
            for (std::string_view op : operators)
                if (c == op) return false;
        }
    }
    return true;
}

std::string parenthesised(const std::string& s) {
    return is_simple(s) ? s : "(" + s + ")";
}

// Runs of spaces (ASCII, thin, em) become the widest of them; the ends are trimmed.
std::string tidy_spaces(const std::string& s) {
    auto rank = [](std::string_view c) {
        if (c == "\u2003") return 3;
        if (c == " " || c == "\n" || c == "\t") return 2;
        if (c == "\u2009") return 1;
        return 0;
    };
    std::string out;
    std::string_view pending;
    for (std::string_view c : chars(s)) {
        if (rank(c)) {
            if (rank(c) > rank(pending)) pending = c == "\n" || c == "\t" ? " " : c;
            continue;
        }
        if (!pending.empty() && !out.empty()) out += pending;
        pending = {};
        out += c;
    }
    return out;
}

// --- [environments] --------------------------------------------------------------------------

std::string convert(std::string_view s);

// The cells of a matrix-like body: rows split at \\ and cells at &, outside braces and
// nested environments.
std::vector<std::vector<std::string_view>> split_cells(std::string_view body) {
    std::vector<std::vector<std::string_view>> rows(1);
    int depth = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < body.size(); ++i) {
        const char c = body[i];
        if (c == '{')
            ++depth;
        else if (c == '}')
            --depth;
        else if (c == '\\' && (body.substr(i, 7) == "\\begin{" || body.substr(i, 5) == "\\end{")) {
            depth += body[i + 1] == 'b' ? 1 : -1;
            i = std::min(body.find('}', i), body.size());  // past the environment's name
        } else if (c == '\\' && depth == 0 && i + 1 < body.size() && body[i + 1] == '\\') {
            rows.back().push_back(body.substr(start, i - start));
            rows.emplace_back();
            start = i + 2;
            ++i;
        } else if (c == '\\')
            ++i;  // \& is an ampersand, not a cell
        else if (c == '&' && depth == 0) {
            rows.back().push_back(body.substr(start, i - start));
            start = i + 1;
        }
    }
    rows.back().push_back(body.substr(start));
    // A trailing \\ leaves an empty last row.
    if (rows.size() > 1 && rows.back().size() == 1 && tidy_spaces(convert(rows.back()[0])).empty())
        rows.pop_back();
    return rows;
}

std::string environment(std::string_view name, std::string_view body) {
    std::string open, close, cell_gap = " ";
    if (name == "bmatrix")
        open = "[", close = "]";
    else if (name == "pmatrix")
        open = "(", close = ")";
    else if (name == "vmatrix")
        open = close = "|";
    else if (name == "Vmatrix")
        open = close = "‖";
    else if (name == "Bmatrix")
        open = "{", close = "}";
    else if (name == "cases")
        open = "{ ";
    else if (name == "aligned" || name == "align" || name == "align*" || name == "gathered" ||
             name == "gather" || name == "split" || name == "eqnarray")
        cell_gap = "";
    else if (name != "matrix" && name != "smallmatrix" && name != "array")
        return convert(body);
    std::string out = open;
    const auto rows = split_cells(body);
    for (std::size_t r = 0; r < rows.size(); ++r) {
        if (r) out += "; ";
        for (std::size_t c = 0; c < rows[r].size(); ++c)
            out += (c ? cell_gap : "") + tidy_spaces(convert(rows[r][c]));
    }
    return out + close;
}

// --- [the converter] -------------------------------------------------------------------------

class Converter {
  public:
    explicit Converter(std::string_view s) : s_(s) {}

    std::string run() {
        while (i_ < s_.size()) token();
        return out_;
    }

  private:
    void skip_spaces() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }

    // The raw text of the next argument: a {group}'s inside, a command, or one character.
    std::string_view argument() {
        skip_spaces();
        if (i_ >= s_.size()) return {};
        if (s_[i_] == '{') {
            const std::size_t start = ++i_;
            for (int depth = 1; i_ < s_.size(); ++i_) {
                if (s_[i_] == '\\')
                    ++i_;  // \{ and \} do not nest
                else if (s_[i_] == '{')
                    ++depth;
                else if (s_[i_] == '}' && --depth == 0)
                    break;
            }
            const std::string_view inside = s_.substr(start, std::min(i_, s_.size()) - start);
            if (i_ < s_.size()) ++i_;  // the closing brace
            return inside;
        }
        const std::size_t start = i_;
        if (s_[i_] == '\\') {
            ++i_;
            if (i_ < s_.size() && !std::isalpha(static_cast<unsigned char>(s_[i_]))) ++i_;
            while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) ++i_;
            return s_.substr(start, i_ - start);
        }
        next_char(s_, i_);
        return s_.substr(start, i_ - start);
    }

    // [n] after \sqrt: the root's index, if any.
    std::string_view optional_argument() {
        skip_spaces();
        if (i_ >= s_.size() || s_[i_] != '[') return {};
        const std::size_t close = s_.find(']', i_);
        if (close == std::string_view::npos) return {};
        const std::string_view inside = s_.substr(i_ + 1, close - i_ - 1);
        i_ = close + 1;
        return inside;
    }

    void token() {
        const char c = s_[i_];
        switch (c) {
            case '\\':
                command();
                return;
            case '{':
                out_ += convert(argument());
                return;
            case '}':  // unbalanced: nothing to show
                ++i_;
                return;
            case '^':
            case '_':
                ++i_;
                out_ += script(tidy_spaces(convert(argument())), c == '^');
                return;
            case '-':
                ++i_;
                out_ += "−";
                return;
            case '~':
            case '&':
                ++i_;
                out_ += " ";
                return;
            case '\'':
                ++i_;
                out_ += "′";
                return;
            default:
                out_ += next_char(s_, i_);
        }
    }

    void command() {
        ++i_;  // the backslash
        if (i_ >= s_.size()) return;
        if (!std::isalpha(static_cast<unsigned char>(s_[i_]))) {
            const char c = s_[i_++];
            const std::string_view e = escaped(c);
            if (!e.empty() || c == '!')
                out_ += e;
            else
                out_ += c;  // \{ \} \$ \% \& \_ \#
            return;
        }
        const std::size_t start = i_;
        while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) ++i_;
        const std::string_view name = s_.substr(start, i_ - start);
        if (i_ < s_.size() && s_[i_] == '*') ++i_;  // \operatorname* and the like

        if (name == "frac" || name == "tfrac" || name == "dfrac" || name == "cfrac") {
            const std::string a = tidy_spaces(convert(argument()));
            const std::string b = tidy_spaces(convert(argument()));
            out_ += parenthesised(a) + "/" + parenthesised(b);
        } else if (name == "sqrt") {
            const std::string_view index = optional_argument();
            if (!index.empty()) out_ += script(tidy_spaces(convert(index)), true);
            out_ += "√(" + tidy_spaces(convert(argument())) + ")";
        } else if (name == "binom" || name == "tbinom" || name == "dbinom") {
            const std::string n = tidy_spaces(convert(argument()));
            const std::string k = tidy_spaces(convert(argument()));
            out_ += "C(" + n + ", " + k + ")";
        } else if (is_text(name)) {
            out_ += argument();
        } else if (is_style(name)) {
            out_ += convert(argument());
        } else if (name == "mathbb") {
            const std::string_view a = argument();
            static const std::map<std::string_view, std::string_view> sets = {
                {"R", "ℝ"}, {"N", "ℕ"}, {"Z", "ℤ"}, {"Q", "ℚ"}, {"C", "ℂ"}};
            const auto it = sets.find(a);
            out_ += it != sets.end() ? std::string(it->second) : convert(a);
        } else if (is_sizing(name)) {
            skip_spaces();
            if (i_ < s_.size() && s_[i_] == '.') ++i_;  // \left. is an invisible delimiter
        } else if (name == "begin") {
            begin_environment();
        } else if (name == "end") {
            argument();  // an \end without its \begin
        } else if (const auto it = symbols().find(name); it != symbols().end()) {
            out_ += it->second;
        } else if (!is_function(name) && i_ < s_.size() && s_[i_] == '{') {
            // A command we do not know, with an argument: shown like a function, \norm{v}
            // as norm(v), so the argument does not run into its name.
            out_ += std::string(name) + "(" + tidy_spaces(convert(argument())) + ")";
        } else {
            out_ += name;  // \max, \cos, and any command we do not know
            if (is_function(name) && i_ < s_.size() &&
                (std::isalpha(static_cast<unsigned char>(s_[i_])) || s_[i_] == '\\'))
                out_ += " ";
        }
    }

    void begin_environment() {
        const std::string name(argument());
        if (name == "array") argument();  // the column specification
        const std::string begin = "\\begin{" + name + "}", end = "\\end{" + name + "}";
        const std::size_t start = i_;
        std::size_t at = i_;
        for (int depth = 1; depth > 0;) {
            const std::size_t b = s_.find(begin, at), e = s_.find(end, at);
            if (e == std::string_view::npos) {  // unterminated: take the rest
                at = s_.size();
                break;
            }
            if (b < e) {
                ++depth;
                at = b + begin.size();
            } else {
                --depth;
                at = e + (depth == 0 ? 0 : end.size());
            }
        }
        out_ += environment(name, s_.substr(start, at - start));
        i_ = std::min(s_.size(), at + end.size());
    }

    std::string_view s_;
    std::size_t i_ = 0;
    std::string out_;
};

std::string convert(std::string_view s) {
    return Converter(s).run();
}

}  // namespace

bool known_command(std::string_view name) {
    static const std::initializer_list<std::string_view> structural = {
        "frac", "tfrac", "dfrac", "cfrac", "sqrt", "binom", "tbinom", "dbinom", "mathbb", "begin",
        "end"};
    if (name.size() == 1 && escaped(name[0]).data() != nullptr) return true;
    if (name.size() == 1 && !std::isalpha(static_cast<unsigned char>(name[0]))) return true;
    return symbols().count(name) || is_style(name) || is_text(name) || is_sizing(name) ||
           is_function(name) || one_of(name, structural);
}

std::string math_to_unicode(std::string_view latex) {
    return tidy_spaces(convert(latex));
}

// --- [text] ----------------------------------------------------------------------------------

std::string text_to_unicode(std::string_view text) {
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '$') {
            out += '$';
            i += 2;
            continue;
        }
        if (text[i] != '$') {
            out += text[i++];
            continue;
        }
        const bool display = text.substr(i, 2) == "$$";
        const std::string_view delimiter = display ? "$$" : "$";
        std::size_t close = i + delimiter.size();
        while ((close = text.find(delimiter, close)) != std::string_view::npos &&
               text[close - 1] == '\\')
            ++close;                            // an escaped \$ inside the math
        if (close == std::string_view::npos) {  // unmatched: keep it as written
            out += text.substr(i);
            break;
        }
        const std::size_t start = i + delimiter.size();
        out += math_to_unicode(text.substr(start, close - start));
        i = close + delimiter.size();
    }
    return out;
}

}  // namespace cg::viewer
