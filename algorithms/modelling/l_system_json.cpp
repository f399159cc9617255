// L-system, JSON:
//   input  {"axiom": "F" (ω, a string of symbols; spaces are dropped, the Unicode minus − reads
//                     as -),
//           "rules": {"F": "F+F-F-F+F", …} (one production per symbol; a symbol without one
//                    copies itself; "" erases it),
//           "generations": n (0 to 40),
//           "angle": δ (degrees, the turn of + and −),
//           "step": the length of one F (optional, 1),
//           "heading": the start heading in degrees, counter-clockwise from +x (optional, 90: up),
//           "draw": the symbols that draw a line (optional, "F"; e.g. "FG" or "AB")}
//   result {"lengths": the string's length after 0, 1, …, n generations,
//           "string": the string after n generations,
//           "segments": lines drawn, "moves": f moves, "turns", "branches": [ read,
//           "max_depth": the deepest stack, "ignored": symbols the turtle skipped,
//           "end": the turtle's end position, "end_heading": degrees in [0, 360),
//           "path_length": segments · step, "bounds": {"min", "max"} of the positions visited}
#include "io/registry.hpp"
#include "modelling/l_system.hpp"

namespace cg {

// A named namespace: the JSON adapters are compiled in unity batches.
namespace l_system_json {

// The symbols as the turtle reads them: spaces dropped, the Unicode minus (U+2212) as '-'.
std::string symbols(const std::string& text) {
    static const std::string minus = "\xe2\x88\x92";
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, minus.size(), minus) == 0) {
            out += '-';
            i += minus.size() - 1;
        } else if (text[i] != ' ' && text[i] != '\t' && text[i] != '\n') {
            out += text[i];
        }
    }
    return out;
}

}  // namespace l_system_json

template <>
struct JsonIo<LSystem> {
    static LSystem::Input input(const json& j) {
        Reader r(j);
        r.only({"axiom", "rules", "generations", "angle", "step", "heading", "draw"});
        LSystem::Input in;
        in.axiom = l_system_json::symbols(r.string("axiom"));
        if (r.has("rules")) {
            const json& rules = r.get("rules");
            if (!rules.is_object())
                throw InputError(r.field("rules"),
                                 "must be an object mapping a symbol to its replacement, such "
                                 "as {\"F\": \"F+F-F-F+F\"}, got " +
                                     describe(rules));
            for (auto it = rules.begin(); it != rules.end(); ++it) {
                const std::string key = l_system_json::symbols(it.key());
                const std::string f = r.field("rules") + "." + it.key();
                if (key.size() != 1)
                    throw InputError(f, "a production rewrites one symbol; \"" + it.key() +
                                            "\" is " + std::to_string(key.size()) + " symbols");
                if (!it.value().is_string())
                    throw InputError(
                        f, "must be a string (the replacement), got " + describe(it.value()));
                in.rules.push_back({key[0], l_system_json::symbols(it.value().get<std::string>())});
            }
        }
        in.generations = int(r.integer("generations", 0, LSystem::kMaxGenerations,
                                       "0 to " + std::to_string(LSystem::kMaxGenerations)));
        in.angle = r.number("angle");
        if (r.has("step")) in.step = r.number("step");
        if (r.has("heading")) in.heading = r.number("heading");
        if (r.has("draw")) in.draw = l_system_json::symbols(r.string("draw"));
        return in;
    }

    static json input_json(const LSystem::Input& in) {
        json j;
        j["axiom"] = in.axiom;
        json rules = json::object();
        for (const auto& rule : in.rules) rules[std::string(1, rule.symbol)] = rule.replacement;
        j["rules"] = rules;
        j["generations"] = in.generations;
        j["angle"] = nice_number(in.angle);
        j["step"] = nice_number(in.step);
        j["heading"] = nice_number(in.heading);
        if (in.draw != "F") j["draw"] = in.draw;
        return j;
    }

    static json result(const LSystem::Result& r) {
        json j;
        j["lengths"] = r.lengths;
        j["string"] = r.word;
        j["segments"] = r.tally.segments;
        j["moves"] = r.tally.moves;
        j["turns"] = r.tally.turns;
        j["branches"] = r.tally.pushes;
        j["max_depth"] = r.tally.max_depth;
        j["ignored"] = r.tally.ignored;
        j["end"] = to_json(r.end);
        j["end_heading"] = r.end_heading;
        j["path_length"] = r.path_length;
        j["bounds"] = {{"min", to_json(r.tally.lo)}, {"max", to_json(r.tally.hi)}};
        return j;
    }

    static json example() {
        // The Koch curve, two generations: F → F+F−−F+F with 60° turns.
        return parse_json(R"({"axiom": "F", "rules": {"F": "F+F--F+F"}, "generations": 2,
                              "angle": 60, "step": 1, "heading": 0})");
    }
};

Algorithm l_system_algorithm() {
    return make_algorithm<LSystem>([](const LSystem::Input& in) { return LSystem::compute(in); });
}

}  // namespace cg
