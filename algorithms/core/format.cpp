#include "core/format.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace cg {

namespace {

// The number as %g writes it (ASCII, "2.5e-05"), with the zero snap applied (`snap`).
std::string g_text(double x, int digits, bool snap = true) {
    if (x == 0 || (snap && std::fabs(x) < kZeroSnap)) return "0";  // also folds -0
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    return buf;
}

// Splits %g's "2.5e-05" into mantissa "2.5" and exponent -5; no 'e': the exponent is 0.
struct Sci {
    std::string mantissa;
    int exponent = 0;
    bool has = false;
};
Sci split(const std::string& s) {
    const auto e = s.find('e');
    if (e == std::string::npos) return {s, 0, false};
    return {s.substr(0, e), std::stoi(s.substr(e + 1)), true};
}

std::string superscript(int n) {
    static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string out = n < 0 ? "⁻" : "";
    const std::string d = std::to_string(n < 0 ? -n : n);
    for (char c : d) out += digits[c - '0'];
    return out;
}

// A leading '-' as the text minus.
std::string with_minus(const std::string& s) {
    return !s.empty() && s[0] == '-' ? kMinus + s.substr(1) : s;
}

}  // namespace

namespace {

// The number as shown, in ASCII: "-2.5", "1310", or a mantissa with a power of ten.
Sci shown(double x, int digits, bool snap = true) {
    Sci s = split(g_text(x, digits, snap));
    if (s.has && s.exponent >= 0 && std::fabs(x) < 1e15) {
        // A big number as a person writes it: whole, 1234567; else rounded to `digits`
        // figures but not in powers of ten, 1310 rather than 1.31 × 10³.
        char buf[64];
        const double v =
            std::nearbyint(x) == x ? x : std::strtod(g_text(x, digits).c_str(), nullptr);
        std::snprintf(buf, sizeof buf, "%.0f", v);
        return {buf, 0, false};
    }
    return s;
}

}  // namespace

namespace {

std::string text_number(double x, int digits, bool snap) {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    const Sci s = shown(x, digits, snap);
    if (!s.has) return with_minus(s.mantissa);
    // "1e+15" → "10¹⁵", "2.5e-05" → "2.5 × 10⁻⁵", "-1e-05" → "−10⁻⁵".
    const std::string power = "10" + superscript(s.exponent);
    if (s.mantissa == "1") return power;
    if (s.mantissa == "-1") return kMinus + power;
    return with_minus(s.mantissa) + " × " + power;
}

}  // namespace

std::string num(double x, int digits) {
    return text_number(x, digits, true);
}

std::string given(double x, int digits) {
    return text_number(x, digits, false);
}

std::string given(glm::dvec2 p, int digits) {
    return "(" + given(p.x, digits) + ", " + given(p.y, digits) + ")";
}

std::string given(glm::dvec3 p, int digits) {
    return "(" + given(p.x, digits) + ", " + given(p.y, digits) + ", " + given(p.z, digits) + ")";
}

std::string num(glm::dvec2 p, int digits) {
    return "(" + num(p.x, digits) + ", " + num(p.y, digits) + ")";
}

std::string num(glm::dvec3 p, int digits) {
    return "(" + num(p.x, digits) + ", " + num(p.y, digits) + ", " + num(p.z, digits) + ")";
}

std::string tex(double x, int digits) {
    if (std::isnan(x)) return "\\text{NaN}";
    if (std::isinf(x)) return x > 0 ? "\\infty" : "-\\infty";
    const Sci s = shown(x, digits);
    if (!s.has) return s.mantissa;
    // "2.5e-12" -> "2.5 \times 10^{-12}".
    const std::string power = "10^{" + std::to_string(s.exponent) + "}";
    if (s.mantissa == "1") return power;
    if (s.mantissa == "-1") return "-" + power;
    return s.mantissa + " \\times " + power;
}

std::string tex(glm::dvec2 p, int digits) {
    return "(" + tex(p.x, digits) + ", " + tex(p.y, digits) + ")";
}

std::string tex(glm::dvec3 p, int digits) {
    return "(" + tex(p.x, digits) + ", " + tex(p.y, digits) + ", " + tex(p.z, digits) + ")";
}

namespace {
std::string list(const std::vector<double>& v, int digits) {
    std::string s = "(";
    for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + num(v[i], digits);
    return s + ")";
}
}  // namespace

std::string to_text(const Value& v, int digits) {
    struct Visitor {
        int digits;
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(long long i) const { return with_minus(std::to_string(i)); }
        std::string operator()(double d) const { return num(d, digits); }
        std::string operator()(const std::string& s) const { return text_minus(s); }
        std::string operator()(const std::vector<double>& v) const { return list(v, digits); }
        std::string operator()(const std::vector<std::vector<double>>& m) const {
            std::string s = "[";
            for (size_t i = 0; i < m.size(); ++i) s += (i ? "; " : "") + list(m[i], digits);
            return s + "]";
        }
    };
    return std::visit(Visitor{digits}, v);
}

std::string text_minus(std::string_view t) {
    std::string out;
    out.reserve(t.size() + 8);
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (std::size_t i = 0; i < t.size(); ++i) {
        const char c = t[i];
        if (c != '-') {
            out += c;
            continue;
        }
        const char before = i > 0 ? t[i - 1] : ' ';
        const char after = i + 1 < t.size() ? t[i + 1] : ' ';
        const bool number_follows = std::isdigit(static_cast<unsigned char>(after)) ||
                                    (after == '.' && i + 2 < t.size() &&
                                     std::isdigit(static_cast<unsigned char>(t[i + 2]))) ||
                                    t.substr(i + 1, 3) == "inf" || t.substr(i + 1, 3) == "∞";
        const bool spaced = before == ' ' && after == ' ';
        // "-2" after a space, "(", "[", "=", ",": a negative number; "a - b": a subtraction.
        // "x-2" (a hyphen after a word character) and "--" stay as they are.
        if ((number_follows && !word(before) && before != '-' && before != '.') || spaced)
            out += kMinus;
        else
            out += c;
    }
    return out;
}

}  // namespace cg
