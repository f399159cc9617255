// The JSON reader names the offending field; numbers print the same everywhere.
#include <catch2/catch.hpp>

#include "core/format.hpp"
#include "io/json.hpp"

using cg::json;

TEST_CASE("json reader: errors name the field and the reason", "[json]") {
    json j = json::parse(R"({"a": {"b": "x"}, "p": [1, "2"], "n": 3, "q": [1, 2, 3]})");
    cg::Reader r(j);
    auto message = [&](auto&& f) {
        try {
            f();
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(message([&] { r.object("a").number("b"); }) == "a.b: must be a number, got a string (\"x\")");
    CHECK(message([&] { r.point2("p"); }) == "p[1]: must be a number, got a string (\"2\")");
    CHECK(message([&] { r.point2("q"); }) == "q: must be a point [x, y], got an array ([1,2,3])");
    CHECK(message([&] { r.number("missing"); }) == "missing: is missing");
    CHECK(message([&] { r.only({"a", "p"}); }) == "n: is not a known field (expected: a, p)");
    CHECK(message([&] { (void)cg::Reader(json::array()); }) == "the input must be a JSON object, got an array ([])");
    CHECK(r.integer("n") == 3);
    CHECK_THROWS_WITH(cg::Reader(json::parse(R"({"w": 18446744073709551615})")).integer("w"),
                      "w: is too large, got 18446744073709551615");
}

TEST_CASE("json reader: non-finite numbers are refused", "[json]") {
    json j;
    j["x"] = std::numeric_limits<double>::infinity();
    j["y"] = std::numeric_limits<double>::quiet_NaN();
    cg::Reader r(j);
    CHECK_THROWS_WITH(r.number("x"), "x: must be a finite number, got inf");
    CHECK_THROWS_WITH(r.number("y"), "y: must be a finite number, got NaN");
    // JSON text has no NaN literal, and 1e999 overflows: both are refused with a position.
    CHECK_THROWS_WITH(cg::parse_json(R"({"x": NaN})"), Catch::Contains("not valid JSON") && Catch::Contains("line 1"));
    CHECK_THROWS_WITH(cg::parse_json(R"({"a": {"x": [1, 1e999]}})"), Catch::StartsWith("a.x[1]: not valid JSON: number overflow"));
    CHECK_THROWS_WITH(cg::parse_json(R"({"a": {"x": 1, "y": NaN}})"), Catch::StartsWith("a.y: not valid JSON: parse error at line 1"));
    CHECK_THROWS_WITH(cg::parse_json(R"({"w": [[0, 0], [1, 1e999], [2, 2]]})"), Catch::StartsWith("w[1][1]: not valid JSON: number overflow"));
    CHECK_THROWS_WITH(cg::parse_json(R"({"w": [{"a": 1}, {"a": [3, 1e999]}]})"), Catch::StartsWith("w[1].a[1]: not valid JSON: number overflow"));
}

TEST_CASE("format: short, deterministic numbers", "[format]") {
    CHECK(cg::num(0.25) == "0.25");
    CHECK(cg::num(-0.0) == "0");
    CHECK(cg::num(1.0 / 3.0) == "0.333333");
    CHECK(cg::num(2.5e-12) == "2.5 × 10⁻¹²");
    CHECK(cg::num(glm::dvec2(1, -2)) == "(1, −2)");
    CHECK(cg::to_text(cg::Value{std::vector<double>{1, 2.5}}) == "(1, 2.5)");
    CHECK(cg::to_text(cg::Value{true}) == "true");
}
