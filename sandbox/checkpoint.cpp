#include "checkpoint.hpp"

#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

namespace cg {

Checkpoint checkpoint_from_json(const json& j, const Registry& registry) {
    Reader r(j);
    r.only({"algorithm", "input", "step", "view", "lesson", "preset", "exam_seed"});
    Checkpoint c;
    c.algorithm = r.string("algorithm");
    if (!registry.find(c.algorithm))
        throw InputError("algorithm", "unknown algorithm \"" + c.algorithm +
                                          "\" (see `cgsandbox list`)");
    c.input = r.get("input");
    long long step = r.integer("step");
    if (step < 0) throw InputError("step", "must be 0 or more, got " + std::to_string(step));
    c.step = static_cast<std::size_t>(step);
    if (r.has("view")) {
        Reader v = r.object("view");
        v.only({"center", "zoom"});
        View2 view;
        view.center = v.point2("center");
        view.zoom = v.number("zoom");
        if (!(view.zoom > 0)) throw InputError("view.zoom", "must be positive");
        c.view = view;
    }
    // Whether the lesson exists is the viewer's business: it may have been renamed since.
    if (r.has("lesson")) c.lesson = r.string("lesson");
    if (r.has("preset")) c.preset = r.string("preset");
    if (r.has("exam_seed")) {
        const long long seed = r.integer("exam_seed");
        if (seed < 0) throw InputError("exam_seed", "must be 0 or more");
        c.exam_seed = static_cast<std::uint64_t>(seed);
    }
    return c;
}

json checkpoint_to_json(const Checkpoint& c) {
    json j{{"algorithm", c.algorithm}, {"input", c.input}, {"step", c.step}};
    if (c.view) j["view"] = json{{"center", to_json(c.view->center)}, {"zoom", c.view->zoom}};
    if (!c.lesson.empty()) j["lesson"] = c.lesson;
    if (!c.preset.empty()) j["preset"] = c.preset;
    if (c.exam_seed) j["exam_seed"] = *c.exam_seed;
    return j;
}

std::string read_text_file(const std::string& path) {
    std::ifstream file;
    if (path != "-") {
        file.open(path, std::ios::binary);
        if (!file) throw InputError("", "cannot open file");
    }
    std::istream& in = path == "-" ? std::cin : file;
    // Read in chunks up to the limit, so that a huge file (or an endless stream) is refused
    // without first filling the memory.
    std::string text;
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
        text.append(chunk, static_cast<std::size_t>(in.gcount()));
        if (text.size() > kMaxInputBytes)
            throw InputError("", "the file is larger than " + std::to_string(kMaxInputBytes >> 20) +
                                     " MiB (the limit for input files)");
    }
    return text;
}

}  // namespace cg
