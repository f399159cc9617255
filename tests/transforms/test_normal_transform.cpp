// Transforming normals: cases worked by hand; 5,000 random maps against glm::inverseTranspose
// and cofactors in long double, the transformed normal perpendicular to the transformed
// tangents, and the naive L n right exactly for similarities; errors; determinism; the
// picture; exam problems.
#include <catch2/catch.hpp>

#include "support/replay.hpp"

#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>

#include "io/exam.hpp"
#include "io/registry.hpp"
#include "transforms/normal_transform.hpp"

using cg::NormalTransform;
using glm::dmat3;
using glm::dvec3;

namespace {

std::vector<std::string> events(const NormalTransform::Input& in) {
    std::vector<std::string> e;
    auto s = NormalTransform::start(in);
    while (!NormalTransform::done(s)) {
        cg::StepInfo info;
        NormalTransform::step(s, &info);
        e.push_back(info.event);
    }
    return e;
}

dmat3 from_rows(std::array<double, 9> v) {
    dmat3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m[c][r] = v[static_cast<std::size_t>(3 * r + c)];
    return m;
}

}  // namespace

TEST_CASE("normal-transform: cases worked by hand", "[transforms][normal-transform]") {
    SECTION("squash y by 2: the naive normal fails, the inverse transpose works") {
        // L = diag(1, 0.5, 1), n = (1, 1, 0): t1 = n × z = (1, −1, 0), L t1 = (1, −0.5, 0);
        // L n = (1, 0.5, 0) has dot 0.75 with it. N = diag(1, 2, 1), N n = (1, 2, 0): dot 0.
        const NormalTransform::Input in{from_rows({1, 0, 0, 0, 0.5, 0, 0, 0, 1}), {1, 1, 0}, false, {}};
        CHECK(events(in) == std::vector<std::string>{"linear-part", "tangents", "naive-fails",
                                                     "inverse-transpose", "normal-correct"});
        const auto r = cg::run_to_end<NormalTransform>(NormalTransform::start(in));
        CHECK(r.det == 0.5);
        CHECK(r.tangents[0] == dvec3(1, -1, 0));
        CHECK(r.tangents[1] == dvec3(0, 0, -2));
        CHECK(r.naive == dvec3(1, 0.5, 0));
        CHECK_FALSE(r.naive_ok);
        CHECK(r.inverse_transpose == from_rows({1, 0, 0, 0, 2, 0, 0, 0, 1}));
        CHECK(r.normal == dvec3(1, 2, 0));
        CHECK(r.cos[0] == 0);
        CHECK(r.cos[1] == 0);
    }
    SECTION("a shear") {
        // L = [1 1 0; 0 1 0; 0 0 1]: N = [1 0 0; −1 1 0; 0 0 1]; n = (0, 1, 0) → (0, 1, 0).
        // The plane y = 0 slides into itself, so its normal stays (0, 1, 0); L n = (1, 1, 0).
        const auto r = NormalTransform::transform({from_rows({1, 1, 0, 0, 1, 0, 0, 0, 1}), {0, 1, 0}, false, {}});
        CHECK(r.inverse_transpose == from_rows({1, 0, 0, -1, 1, 0, 0, 0, 1}));
        CHECK(r.normal == dvec3(0, 1, 0));
        CHECK(r.naive == dvec3(1, 1, 0));
        CHECK_FALSE(r.naive_ok);
    }
    SECTION("a rotation and a uniform scale: the naive normal is right") {
        CHECK(events({from_rows({0, -1, 0, 1, 0, 0, 0, 0, 1}), {1, 2, 0}, false, {}})[2] == "naive-works");
        const auto r = NormalTransform::transform({from_rows({2, 0, 0, 0, 2, 0, 0, 0, 2}), {1, 1, 1}, false, {}});
        CHECK(r.naive_ok);
        CHECK(r.normal == dvec3(0.5, 0.5, 0.5));  // parallel to L n = (2, 2, 2)
    }
    SECTION("given tangents") {
        const auto r = NormalTransform::transform(
            {from_rows({3, 0, 0, 0, 1, 0, 0, 0, 1}), {0, 0, 1}, true, {dvec3(1, 1, 0), dvec3(1, -1, 0)}});
        CHECK(r.tangents[0] == dvec3(1, 1, 0));
        CHECK(r.images[0] == dvec3(3, 1, 0));
        CHECK(r.naive_ok);  // z stays perpendicular to the xy plane under a scale of x
    }
}

TEST_CASE("normal-transform: 5,000 random maps agree with glm::inverseTranspose and long-double cofactors",
          "[transforms][normal-transform]") {
    int similarities = 0, general = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        cg::Rng rng(trial);
        NormalTransform::Input in;
        const bool similar = trial % 5 == 0;
        if (similar) {  // a uniform scale times a rotation
            const glm::dquat q = glm::normalize(glm::dquat(rng.uniform(-1, 1), rng.uniform(-1, 1),
                                                           rng.uniform(-1, 1), rng.uniform(-1, 1)));
            in.linear = rng.uniform(0.1, 10) * glm::mat3_cast(q);
        } else {
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r) in.linear[c][r] = rng.uniform(-3, 3);
        }
        in.normal = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
        CAPTURE(trial);
        try {
            NormalTransform::validate(in);
        } catch (const cg::InputError&) {
            continue;  // a (nearly) singular random matrix
        }
        const auto r = cg::run_to_end<NormalTransform>(NormalTransform::start(in));
        REQUIRE(NormalTransform::transform(in) == r);
        const dmat3 ref = glm::inverseTranspose(in.linear);
        // Cofactors in long double: N[c][r] = cofactor(r, c) of L / det, i.e. (L⁻¹)ᵀ.
        using ld = long double;
        auto at = [&](int row, int col) { return ld(in.linear[col][row]); };
        const ld det = at(0, 0) * (at(1, 1) * at(2, 2) - at(1, 2) * at(2, 1)) -
                       at(0, 1) * (at(1, 0) * at(2, 2) - at(1, 2) * at(2, 0)) +
                       at(0, 2) * (at(1, 0) * at(2, 1) - at(1, 1) * at(2, 0));
        REQUIRE(std::fabs(r.det - det) <= 1e-12L * std::max<ld>(1, std::fabs(det)) * 100);
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col) {
                const int r1 = (row + 1) % 3, r2 = (row + 2) % 3, c1 = (col + 1) % 3, c2 = (col + 2) % 3;
                const ld cof = at(r1, c1) * at(r2, c2) - at(r1, c2) * at(r2, c1);
                const ld expected = cof / det;  // (L⁻¹)ᵀ[row][col]
                const ld scale = 1 + std::fabs(expected);
                CAPTURE(row, col);
                REQUIRE(std::fabs(r.inverse_transpose[col][row] - expected) < 1e-9L * scale * (1 + 1 / std::fabs(det)));
                REQUIRE(std::fabs(r.inverse_transpose[col][row] - ref[col][row]) < 1e-9 * (1 + std::fabs(ref[col][row])));
            }
        // The transformed normal is perpendicular to the transformed tangents; the naive one is
        // for similarities only.
        REQUIRE(std::fabs(r.cos[0]) < 1e-9);
        REQUIRE(std::fabs(r.cos[1]) < 1e-9);
        REQUIRE(std::fabs(glm::dot(r.tangents[0], in.normal)) < 1e-12 * glm::length(r.tangents[0]) * glm::length(in.normal));
        REQUIRE(r.naive_ok == similar);
        if (similar) {
            REQUIRE(glm::length(glm::cross(glm::normalize(r.naive), r.unit_normal)) < 1e-9);
            ++similarities;
        } else {
            ++general;
        }
    }
    CHECK(similarities == 1000);
    CHECK(general > 3900);
}

TEST_CASE("normal-transform: bad input names the field", "[transforms][normal-transform]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const dmat3 id(1.0);
    CHECK_THROWS_WITH(NormalTransform::start({from_rows({1, 0, 0, 0, 1, 0, 0, 0, 0}), {0, 0, 1}, false, {}}),
                      Catch::StartsWith("matrix: is singular (det = 0)"));
    CHECK_THROWS_WITH(NormalTransform::start({from_rows({1, 2, 3, 2, 4, 6, 0, 0, 1}), {0, 0, 1}, false, {}}),
                      Catch::StartsWith("matrix: is singular"));
    CHECK_THROWS_WITH(NormalTransform::start({id, {0, 0, 0}, false, {}}), "normal: must not be the zero vector");
    CHECK_THROWS_WITH(NormalTransform::start({id, {0, nan, 1}, false, {}}), "normal[1]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(NormalTransform::start({from_rows({1, 0, 0, 0, nan, 0, 0, 0, 1}), {0, 0, 1}, false, {}}),
                      "matrix[1][1]: must be a finite number (got NaN)");
    CHECK_THROWS_WITH(NormalTransform::start({id, {0, 0, 1}, true, {dvec3(1, 0, 1), dvec3(0, 1, 0)}}),
                      "tangents[0]: must be perpendicular to the normal (t · n = 1)");
    CHECK_THROWS_WITH(NormalTransform::start({id, {0, 0, 1}, true, {dvec3(1, 0, 0), dvec3(2, 0, 0)}}),
                      Catch::StartsWith("tangents[1]: must not be parallel to tangents[0]"));
    CHECK_THROWS_WITH(NormalTransform::start({id, {0, 0, 1}, true, {dvec3(0, 0, 0), dvec3(1, 0, 0)}}),
                      "tangents[0]: must not be the zero vector");

    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("normal-transform");
    auto error = [&](const std::string& text) {
        try {
            a.create(cg::parse_json(text));
        } catch (const cg::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(error(R"({"matrix": [[1, 0, 0, 5], [0, 2, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]], "normal": [1, 1, 0]})") == "(accepted)");
    CHECK(error(R"({"matrix": [[1, 0, 0, 5], [0, 2, 0, 1], [0, 0, 1, 0], [0, 0, 1, 1]], "normal": [1, 1, 0]})") ==
          "matrix[3]: must be [0, 0, 0, 1]: the 4×4 matrix must be affine");
    CHECK_THAT(error(R"({"matrix": [[1, 0], [0, 1]], "normal": [1, 1, 0]})"), Catch::StartsWith("matrix: must be a 3×3 matrix"));
    CHECK_THAT(error(R"({"matrix": [[1, 0, 0], [0, 1], [0, 0, 1]], "normal": [1, 1, 0]})"),
               Catch::StartsWith("matrix[1]: must be a row of 3 numbers"));
    CHECK_THAT(error(R"({"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "normal": [1, 1, 0], "tangents": [[1, -1, 0]]})"),
               Catch::StartsWith("tangents: must be two vectors"));
    CHECK_THAT(error(R"({"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "normals": [1, 1, 0]})"),
               Catch::StartsWith("normals: is not a known field"));
}

TEST_CASE("normal-transform: traces are deterministic, the picture shows both normals",
          "[transforms][normal-transform]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm* a = registry.find("normal-transform");
    REQUIRE(a);
    cg::test::check_replay(*a, a->example(), cg::test::kEveryStep);
    auto run = a->create(a->example());
    while (!run->done()) run->step(nullptr);
    CHECK(a->result(*run)["normal"] == cg::json::parse("[1, 2, 0]"));
    cg::Scene scene;
    run->draw(scene);
    CHECK(scene.faces3.size() == 2);
    bool naive = false, correct = false;
    for (const auto& s : scene.segments3) {
        naive = naive || (s.label == "L n" && s.style.role == cg::Role::Discarded);
        correct = correct || (s.label == "N n" && s.style.role == cg::Role::Kept);
    }
    CHECK(naive);
    CHECK(correct);
}

TEST_CASE("normal-transform: exam problems grade their own answers", "[transforms][normal-transform]") {
    const cg::Registry registry = cg::builtin_registry();
    const cg::Algorithm& a = *registry.find("normal-transform");
    int fails = 0, works = 0;
    for (std::uint64_t seed = 0; seed < 300; ++seed) {
        const cg::ExamProblem p = cg::make_exam(a, seed);
        for (const auto& g : cg::grade(p, p.expected)) CHECK(g.correct);
        (p.expected["naive_ok"].get<bool>() ? works : fails) += 1;
        for (const auto& row : p.expected["inverse_transpose"])
            for (const auto& v : row) CHECK(std::fabs(v.get<double>() * 4 - std::round(v.get<double>() * 4)) < 1e-12);
    }
    CHECK(works > 30);
    CHECK(fails > 100);
}
