// The lessons' "mistakes" sections: the common mistakes, each linked ([step N]) to the step of a
// preset where it bites — a step whose event is the one the algorithm's planted bug of that
// mistake strikes (Spec::study.mistakes, the find-the-bug mode). And the step links themselves.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include "io/lesson.hpp"
#include "io/registry.hpp"
#include "support/registry_run.hpp"

using cg::test::registry;

TEST_CASE("mistakes: [step N] links are read from the text", "[lessons][mistakes]") {
    const auto links = cg::step_links("- swapped them [step 3]; see [step 12] and [step x] [step 4");
    REQUIRE(links.size() == 2);
    CHECK(links[0].step == 3);
    CHECK(links[1].step == 12);
    CHECK(links[0].at == 15);
    CHECK(links[0].size == 8);
}

TEST_CASE("mistakes: each bullet links the step where its mistake bites", "[lessons][mistakes]") {
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    REQUIRE(lib.errors.empty());
    int sections = 0, links = 0;
    for (const cg::Lesson& l : lib.lessons) {
        const cg::Algorithm& a = cg::test::algorithm(l.algorithm);
        std::set<std::string> bug_events;
        for (const cg::Mistake& m : a.spec->study.mistakes) bug_events.insert(m.event);
        for (const cg::LessonSection& s : l.sections) {
            const bool is_mistakes = s.kind == "mistakes";
            const auto found = cg::step_links(s.text);
            if (!is_mistakes && found.empty()) continue;
            CAPTURE(l.id, s.title);
            ++sections;
            const cg::LessonPreset* preset = cg::linked_preset(l, s);
            REQUIRE(preset);
            // The events of the preset's run, step by step (trace numbering, from 1).
            std::vector<std::string> events{""};
            auto run = a.create(preset->input);
            while (!run->done()) {
                cg::StepInfo info;
                run->step(&info);
                events.push_back(info.event);
            }
            std::set<std::string> linked;
            for (const cg::StepLink& link : found) {
                CAPTURE(link.step);
                ++links;
                REQUIRE(link.step >= 1);
                REQUIRE(link.step < events.size());
                if (is_mistakes) {
                    CAPTURE(events[link.step], bug_events);
                    CHECK(bug_events.count(events[link.step]));
                    linked.insert(events[link.step]);
                }
            }
            if (!is_mistakes) continue;
            // Every bullet is a mistake with its step.
            std::size_t start = 0;
            int bullets = 0;
            while (start < s.text.size()) {
                std::size_t end = s.text.find('\n', start);
                if (end == std::string::npos) end = s.text.size();
                const std::string line = s.text.substr(start, end - start);
                if (line.rfind("- ", 0) == 0) {
                    CAPTURE(line);
                    CHECK_FALSE(cg::step_links(line).empty());
                    ++bullets;
                }
                start = end + 1;
            }
            CHECK(bullets >= 2);
            // Every planted bug whose event the preset reaches has its bullet.
            for (const std::string& e : bug_events) {
                if (std::find(events.begin(), events.end(), e) == events.end()) continue;
                CAPTURE(e);
                CHECK(linked.count(e));
            }
        }
    }
    INFO(sections << " sections, " << links << " links");
    CHECK(sections >= 1);
}

TEST_CASE("mistakes: every lesson lists its common mistakes", "[lessons][mistakes]") {
    const cg::LessonLibrary lib = cg::load_lessons(CG_SOURCE_DIR "/lessons", registry());
    std::set<std::string> missing;
    for (const cg::Lesson& l : lib.lessons)
        if (std::none_of(l.sections.begin(), l.sections.end(),
                         [](const cg::LessonSection& s) { return s.kind == "mistakes"; }))
            missing.insert(l.id);
    INFO("missing a mistakes section: " << Catch::Detail::stringify(missing));
    CHECK(missing.empty());
    CHECK(lib.lessons.size() >= 63);
}
