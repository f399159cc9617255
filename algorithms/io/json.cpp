#include "io/json.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

// Parses into a DOM (by delegating to nlohmann's own DOM builder) while keeping the path of
// the value being read, so that a syntax error or an overflowing number ("1e999") can be
// reported against the field it sits in: "window.xmin: number overflow ...".
class PathTrackingSax {
public:
    explicit PathTrackingSax(json& result) : dom_(result, true) {}

    bool null() { return value(), dom_.null(); }
    bool boolean(bool b) { return value(), dom_.boolean(b); }
    bool number_integer(json::number_integer_t v) { return value(), dom_.number_integer(v); }
    bool number_unsigned(json::number_unsigned_t v) { return value(), dom_.number_unsigned(v); }
    bool number_float(json::number_float_t v, const std::string& s) {
        return value(), dom_.number_float(v, s);
    }
    bool string(std::string& s) { return value(), dom_.string(s); }
    bool binary(json::binary_t& b) { return value(), dom_.binary(b); }
    bool start_object(std::size_t n) {
        value();
        check_depth();
        frames_.push_back({false, 0, ""});
        return dom_.start_object(n);
    }
    bool key(std::string& k) {
        frames_.back().key = k;
        return dom_.key(k);
    }
    bool end_object() { return frames_.pop_back(), dom_.end_object(); }
    bool start_array(std::size_t n) {
        value();
        check_depth();
        frames_.push_back({true, 0, ""});
        return dom_.start_array(n);
    }
    bool end_array() { return frames_.pop_back(), dom_.end_array(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
        std::string what = e.what();
        // "[json.exception.parse_error.101] parse error at line 3, column 7: ..." -> from "parse"
        auto at = what.find("] ");
        what = at == std::string::npos ? what : what.substr(at + 2);
        throw InputError(path(), "not valid JSON: " + what);
    }

private:
    struct Frame {
        bool array;
        std::size_t next_index;
        std::string key;
    };
    // Limits that keep a hostile file from exhausting the machine: code that walks a value
    // recursively (printing it, say) stays shallow, and the parsed document stays small.
    static constexpr std::size_t kMaxDepth = 256;
    static constexpr std::size_t kMaxValues = 10'000'000;
    void check_depth() const {
        if (frames_.size() >= kMaxDepth)
            throw InputError(path(), "nested more than " + std::to_string(kMaxDepth) +
                                         " lists or objects deep (the limit)");
    }

    // Called before each value that parsed: inside an array it takes the next index, so at an
    // error next_index is the element that failed.
    void value() {
        if (++values_ > kMaxValues)
            throw InputError(path(), "more than " + std::to_string(kMaxValues) +
                                         " values in one file (the limit)");
        if (!frames_.empty() && frames_.back().array) frames_.back().key = std::to_string(frames_.back().next_index++);
    }
    std::string path() const {
        // The innermost list is still reading its failing element (next_index); every outer
        // list has already counted the element that contains it (next_index - 1).
        std::string p;
        for (std::size_t i = 0; i < frames_.size(); ++i) {
            const Frame& f = frames_[i];
            const bool innermost = i + 1 == frames_.size();
            if (f.array) p += "[" + std::to_string(innermost ? f.next_index : f.next_index - 1) + "]";
            else if (!f.key.empty()) p += (p.empty() ? "" : ".") + f.key;
        }
        return p;
    }

    nlohmann::detail::json_sax_dom_parser<json> dom_;
    std::vector<Frame> frames_;
    std::size_t values_ = 0;
};

}  // namespace

json parse_json(const std::string& text) {
    json result;
    PathTrackingSax sax(result);
    json::sax_parse(text, &sax);
    return result;
}

std::string describe(const json& v) {
    std::string text = v.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    switch (v.type()) {
        case json::value_t::null: return "null";
        case json::value_t::boolean: return "a boolean (" + text + ")";
        case json::value_t::string: return "a string (" + text + ")";
        case json::value_t::array: return "an array (" + text + ")";
        case json::value_t::object: return "an object (" + text + ")";
        default: return text;
    }
}

double as_number(const json& v, const std::string& field) {
    if (!v.is_number()) throw InputError(field, "must be a number, got " + describe(v));
    double d = v.get<double>();
    if (!std::isfinite(d)) throw InputError(field, "must be a finite number, got " + given(d));
    return d;
}

glm::dvec2 as_point2(const json& v, const std::string& field) {
    if (!v.is_array() || v.size() != 2)
        throw InputError(field, "must be a point [x, y], got " + describe(v));
    return {as_number(v[0], field + "[0]"), as_number(v[1], field + "[1]")};
}

glm::dvec3 as_point3(const json& v, const std::string& field) {
    if (!v.is_array() || v.size() != 3)
        throw InputError(field, "must be a point [x, y, z], got " + describe(v));
    return {as_number(v[0], field + "[0]"), as_number(v[1], field + "[1]"),
            as_number(v[2], field + "[2]")};
}

Reader::Reader(const json& j, std::string path) : j_(j), path_(std::move(path)) {
    if (!j_.is_object())
        throw InputError(path_, (path_.empty() ? "the input " : "") +
                                    std::string("must be a JSON object, got ") + describe(j_));
}

std::string element(const std::string& base, std::size_t i) {
    return base + "[" + std::to_string(i) + "]";
}

std::string Reader::field(const char* key) const {
    return path_.empty() ? std::string(key) : path_ + "." + key;
}

const json& Reader::get(const char* key) const {
    auto it = j_.find(key);
    if (it == j_.end()) throw InputError(field(key), "is missing");
    return *it;
}

double Reader::number(const char* key) const { return as_number(get(key), field(key)); }

std::optional<double> Reader::optional_number(const char* key) const {
    if (!has(key)) return std::nullopt;
    return number(key);
}

long long Reader::integer(const char* key) const {
    const json& v = get(key);
    if (v.is_number_unsigned() && v.get<std::uint64_t>() > std::uint64_t(std::numeric_limits<long long>::max()))
        throw InputError(field(key), "is too large, got " + describe(v));
    if (v.is_number_integer()) return v.get<long long>();
    if (v.is_number_float()) {
        double d = v.get<double>();
        if (std::isfinite(d) && d == std::floor(d) && std::fabs(d) < 9e15)
            return static_cast<long long>(d);
    }
    throw InputError(field(key), "must be an integer, got " + describe(v));
}

long long Reader::integer(const char* key, long long lo, long long hi, const std::string& why) const {
    const long long v = integer(key);
    if (v < lo || v > hi)
        throw InputError(field(key), "must be " + why + " (got " + std::to_string(v) + ")");
    return v;
}

bool Reader::boolean(const char* key) const {
    const json& v = get(key);
    if (!v.is_boolean()) throw InputError(field(key), "must be true or false, got " + describe(v));
    return v.get<bool>();
}

std::string Reader::string(const char* key) const {
    const json& v = get(key);
    if (!v.is_string()) throw InputError(field(key), "must be a string, got " + describe(v));
    return v.get<std::string>();
}

glm::dvec2 Reader::point2(const char* key) const { return as_point2(get(key), field(key)); }
glm::dvec3 Reader::point3(const char* key) const { return as_point3(get(key), field(key)); }

glm::dquat Reader::quat(const char* key) const {
    const json& v = get(key);
    const std::string f = field(key);
    if (!v.is_array() || v.size() != 4)
        throw InputError(f, "must be a quaternion [w, x, y, z], got " + describe(v));
    double c[4];
    for (int i = 0; i < 4; ++i) c[i] = as_number(v[i], f + "[" + std::to_string(i) + "]");
    return {c[0], c[1], c[2], c[3]};  // glm's constructor takes (w, x, y, z)
}

std::vector<glm::dvec2> Reader::points2(const char* key) const {
    const json& v = get(key);
    if (!v.is_array()) throw InputError(field(key), "must be a list of points, got " + describe(v));
    std::vector<glm::dvec2> out;
    for (std::size_t i = 0; i < v.size(); ++i)
        out.push_back(as_point2(v[i], field(key) + "[" + std::to_string(i) + "]"));
    return out;
}

std::vector<glm::dvec3> Reader::points3(const char* key) const {
    const json& v = get(key);
    if (!v.is_array()) throw InputError(field(key), "must be a list of points, got " + describe(v));
    std::vector<glm::dvec3> out;
    for (std::size_t i = 0; i < v.size(); ++i)
        out.push_back(as_point3(v[i], field(key) + "[" + std::to_string(i) + "]"));
    return out;
}

Reader Reader::object(const char* key) const { return Reader(get(key), field(key)); }

void Reader::only(std::initializer_list<const char*> allowed) const {
    for (auto it = j_.begin(); it != j_.end(); ++it) {
        bool known = false;
        for (const char* a : allowed) known = known || it.key() == a;
        if (known) continue;
        std::string list;
        for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        throw InputError(field(it.key().c_str()), "is not a known field (expected: " + list + ")");
    }
}

namespace {
bool is_flat(const json& j) {
    if (!j.is_array()) return false;
    for (const json& e : j)
        if (e.is_structured() && !(e.is_array() && e.size() <= 4 && is_flat(e) && !e.empty())) return false;
    return true;
}

std::string inline_dump(const json& j) {
    if (!j.is_array()) return j.dump();
    std::string s = "[";
    for (std::size_t i = 0; i < j.size(); ++i) s += (i ? ", " : "") + inline_dump(j[i]);
    return s + "]";
}

void pretty_into(const json& j, int indent, int depth, std::string& out) {
    const std::string pad(static_cast<std::size_t>(indent * (depth + 1)), ' ');
    const std::string close_pad(static_cast<std::size_t>(indent * depth), ' ');
    if (j.is_object() && !j.empty()) {
        out += "{\n";
        std::size_t i = 0;
        for (auto it = j.begin(); it != j.end(); ++it, ++i) {
            out += pad + json(it.key()).dump() + ": ";
            pretty_into(it.value(), indent, depth + 1, out);
            out += i + 1 < j.size() ? ",\n" : "\n";
        }
        out += close_pad + "}";
    } else if (j.is_array() && !j.empty() && !is_flat(j)) {
        out += "[\n";
        for (std::size_t i = 0; i < j.size(); ++i) {
            out += pad;
            pretty_into(j[i], indent, depth + 1, out);
            out += i + 1 < j.size() ? ",\n" : "\n";
        }
        out += close_pad + "]";
    } else if (j.is_array()) {
        out += inline_dump(j);
    } else {
        out += j.dump();
    }
}
}  // namespace

std::string pretty(const json& j, int indent) {
    std::string out;
    pretty_into(j, indent, 0, out);
    return out;
}

json nice_number(double x) {
    if (std::isfinite(x) && x == std::floor(x) && std::fabs(x) < 1e15) return static_cast<long long>(x);
    return x;
}
json nice_point(glm::dvec2 p) { return json::array({nice_number(p.x), nice_number(p.y)}); }
json nice_point(glm::dvec3 p) { return json::array({nice_number(p.x), nice_number(p.y), nice_number(p.z)}); }
json nice_quat(const glm::dquat& q) {
    return json::array({nice_number(q.w), nice_number(q.x), nice_number(q.y), nice_number(q.z)});
}

namespace {
template <int N>
json matrix_rows_of(const glm::mat<N, N, double, glm::defaultp>& m, bool nice) {
    json j = json::array();
    for (int r = 0; r < N; ++r) {
        json row = json::array();
        for (int c = 0; c < N; ++c) row.push_back(nice ? nice_number(m[c][r]) : json(m[c][r]));
        j.push_back(std::move(row));
    }
    return j;
}
}  // namespace

json matrix_rows(const glm::dmat3& m, bool nice) { return matrix_rows_of(m, nice); }
json matrix_rows(const glm::dmat4& m, bool nice) { return matrix_rows_of(m, nice); }

json to_json(glm::dvec2 p) { return json::array({p.x, p.y}); }
json to_json(glm::dvec3 p) { return json::array({p.x, p.y, p.z}); }
json quat_json(const glm::dquat& q) { return json::array({q.w, q.x, q.y, q.z}); }

json to_json(const Value& v) {
    struct Visitor {
        json operator()(bool b) const { return b; }
        json operator()(long long i) const { return i; }
        json operator()(double d) const { return d; }
        json operator()(const std::string& s) const { return s; }
        json operator()(const std::vector<double>& v) const { return v; }
        json operator()(const std::vector<std::vector<double>>& m) const { return m; }
    };
    return std::visit(Visitor{}, v);
}

json step_to_json(std::size_t index, const StepInfo& info) {
    json vars = json::object();
    for (const Var& v : info.vars) vars[v.name] = to_json(v.value);
    return json{{"index", index},
                {"event", info.event},
                {"line", info.line},
                {"narration", info.narration},
                {"math", info.math},
                {"variables", std::move(vars)}};
}

}  // namespace cg
