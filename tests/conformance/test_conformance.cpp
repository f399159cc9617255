// What every registered algorithm promises, checked on its example, its lesson presets and a
// spread of exam problems: the state machine is deterministic and resumable, every step says
// what happened in terms the algorithm declared, and its picture is well formed.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/timeline.hpp"
#include "io/exam.hpp"
#include "io/lesson.hpp"
#include "support/sweep.hpp"

namespace {

const cg::Registry& registry() {
    static const cg::Registry r = cg::builtin_registry();
    return r;
}

struct NamedInput {
    std::string name;
    cg::json input;
};

std::vector<NamedInput> inputs_of(const cg::Algorithm& a) {
    std::vector<NamedInput> inputs{{"example", a.example()}};
    static const cg::LessonLibrary lessons = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    if (const cg::Lesson* l = lessons.for_algorithm(a.spec->id))
        for (const auto& p : l->presets) inputs.push_back({"preset " + p.name, p.input});
    if (cg::has_exam(a))
        for (std::uint64_t seed = 0; seed < cg::test::sweep(40); ++seed)
            inputs.push_back({"exam seed " + std::to_string(seed), a.exam_input(seed)});
    return inputs;
}

std::string trace(const cg::Algorithm& a, const cg::json& input) {
    std::string out;
    auto run = a.create(input);
    for (std::size_t i = 1; !run->done(); ++i) {
        cg::StepInfo info;
        run->step(&info);
        out += cg::step_to_json(i, info).dump() + "\n";
    }
    return out + a.result(*run).dump();
}

bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

void check_scene(const cg::Scene& scene) {
    for (const auto& p : scene.points) CHECK(finite(p.p));
    for (const auto& s : scene.segments) CHECK((finite(s.a) && finite(s.b)));
    for (const auto& poly : scene.polygons)
        for (const auto& p : poly.points) CHECK(finite(p));
    for (const auto& h : scene.half_planes) CHECK((finite(h.point) && finite(h.inward)));
    for (const auto& l : scene.labels) CHECK(finite(l.p));
    for (const auto& h : scene.handles) {
        CHECK(finite(h.p));
        CHECK(h.x_field.rfind('/', 0) == 0);  // JSON pointers into the input
        CHECK(h.y_field.rfind('/', 0) == 0);
    }
}

}  // namespace

TEST_CASE("conformance: every algorithm is deterministic, resumable and self-describing", "[conformance]") {
    for (const cg::Algorithm& a : registry().all()) {
        const cg::Spec& spec = *a.spec;
        for (const NamedInput& in : inputs_of(a)) {
            CAPTURE(spec.id, in.name, in.input.dump());
            // The same input gives the same trace, byte for byte.
            const std::string first = trace(a, in.input);
            REQUIRE(trace(a, in.input) == first);

            // Step through, keeping every state; check each step's report and picture.
            std::vector<std::unique_ptr<cg::Run>> states;
            std::vector<cg::StepInfo> infos;
            auto run = a.create(in.input);
            states.push_back(run->clone());
            std::size_t guard = 0;
            double clock = 0;  // an animation's simulated time (Spec::clock), never going back
            while (!run->done()) {
                REQUIRE(++guard < 1'000'000);
                cg::StepInfo info;
                run->step(&info);
                bool declared = false;
                for (const auto& e : spec.events) declared = declared || e.id == info.event;
                CAPTURE(info.event);
                CHECK(declared);
                CHECK(info.line >= 1);
                CHECK(info.line <= int(spec.pseudocode.size()));
                CHECK_FALSE(info.narration.empty());
                CHECK(info.narration.find("nan") == std::string::npos);
                CHECK(info.narration.find("NaN") == std::string::npos);
                if (!spec.clock.empty()) {
                    // Every step of an animation says its time, so that Play can keep real time.
                    const cg::Var* t = nullptr;
                    for (const cg::Var& v : info.vars) t = v.name == spec.clock ? &v : t;
                    REQUIRE(t != nullptr);
                    REQUIRE(std::holds_alternative<double>(t->value));
                    const double now = std::get<double>(t->value);
                    CHECK(std::isfinite(now));
                    CHECK(now >= clock);
                    clock = now;
                }
                cg::Scene scene;
                run->draw(scene);
                check_scene(scene);
                states.push_back(run->clone());
                infos.push_back(std::move(info));
            }
            // A finished machine stays finished.
            auto finished = run->clone();
            run->step(nullptr);
            CHECK(run->same_state(*finished));

            // A copy taken at any step finishes in the same state as the quiet path.
            for (std::size_t i = 0; i < states.size(); i += std::max<std::size_t>(1, states.size() / 7)) {
                auto copy = states[i]->clone();
                while (!copy->done()) copy->step(nullptr);
                CHECK(copy->same_state(*states.back()));
                CHECK(a.result(*copy) == a.result(*states.back()));
            }

            // The timeline: to the end, back to the start, forward again: same states, same steps.
            cg::Timeline t(a.create(in.input));
            t.to_end();
            REQUIRE(t.index() == infos.size());
            while (t.back()) REQUIRE(t.current().same_state(*states[t.index()]));
            while (t.forward()) {
                REQUIRE(t.current().same_state(*states[t.index()]));
                REQUIRE(*t.last_step() == infos[t.index() - 1]);
            }
        }
    }
}

TEST_CASE("conformance: every algorithm's spec is complete", "[conformance]") {
    for (const cg::Algorithm& a : registry().all()) {
        const cg::Spec& spec = *a.spec;
        CAPTURE(spec.id);
        CHECK_FALSE(spec.title.empty());
        CHECK_FALSE(spec.topic.empty());
        CHECK(spec.pseudocode.size() >= 3);
        CHECK(spec.events.size() >= 2);
        for (const auto& e : spec.events) CHECK_FALSE(e.meaning.empty());
        CHECK(registry().find(spec.id) == &a);
    }
}
