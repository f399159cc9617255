#include "core/format.hpp"

#include <cmath>
#include <cstdio>

namespace cg {

std::string num(double x, int digits) {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    if (x == 0) return "0";  // also folds -0
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    std::string s = buf;
    // Round-off like 1e-17 next to numbers of size 1 reads as noise; %g keeps it, which is
    // what we want: the narration must show the number the algorithm really used.
    return s == "-0" ? "0" : s;
}

std::string num(glm::dvec2 p, int digits) {
    return "(" + num(p.x, digits) + ", " + num(p.y, digits) + ")";
}

std::string num(glm::dvec3 p, int digits) {
    return "(" + num(p.x, digits) + ", " + num(p.y, digits) + ", " + num(p.z, digits) + ")";
}

std::string tex(double x, int digits) {
    std::string s = num(x, digits);
    auto e = s.find('e');
    if (e == std::string::npos) return s;
    // "2.5e-12" -> "2.5 \times 10^{-12}"; printf writes at least two exponent digits.
    std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
    bool negative = exponent[0] == '-';
    exponent = exponent.substr(exponent[0] == '-' || exponent[0] == '+' ? 1 : 0);
    while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
    return mantissa + " \\times 10^{" + (negative ? "-" : "") + exponent + "}";
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
        std::string operator()(long long i) const { return std::to_string(i); }
        std::string operator()(double d) const { return num(d, digits); }
        std::string operator()(const std::string& s) const { return s; }
        std::string operator()(const std::vector<double>& v) const { return list(v, digits); }
        std::string operator()(const std::vector<std::vector<double>>& m) const {
            std::string s = "[";
            for (size_t i = 0; i < m.size(); ++i) s += (i ? "; " : "") + list(m[i], digits);
            return s + "]";
        }
    };
    return std::visit(Visitor{digits}, v);
}

}  // namespace cg
