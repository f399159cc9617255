// Sampling, JSON. Either a 1D signal or a 2D image:
//   input  {"signal": [{"frequency": f ≥ 0, "amplitude": A (optional, 1), "phase": degrees
//           (optional, 0)}, …], "rate": f_s > 0, "duration": > 0,
//           "reconstruction": "nearest" | "linear" | "sinc" (optional, linear)}
//   result {"samples": [[t, x], …], "aliases": [{"frequency", "alias", "alias_phase", "k",
//           "aliased"}, …], "nyquist_rate": 2 f_max, "error_rms"}
// or
//   input  {"image": {"type": "edge", "angle": degrees, "point": [x, y] (optional, the centre)}
//                  | {"type": "checkerboard", "horizon": y (optional, 0.9 height),
//                     "square": side on the ground (optional, 0.25), "focal": pixels (optional,
//                     the height)}
//                  | {"type": "zone-plate", "nyquist_radius": ρ (optional, min(w, h)/4)},
//           "width", "height": pixels, "supersampling": {"pattern", "samples", "filter",
//           "seed"} (optional, each optional: jittered, 16, box, 1)}
//   result {"width", "height", "point_sampled": [[row 0 (bottom)…], …], "supersampled": […],
//           "rms_difference"}
#include "io/registry.hpp"
#include "sampling/pattern_json.hpp"
#include "sampling/sampling.hpp"

namespace cg {

namespace {

Sampling::Component component(const Reader& r) {
    r.only({"frequency", "amplitude", "phase"});
    Sampling::Component c;
    c.frequency = r.number("frequency");
    if (r.has("amplitude")) c.amplitude = r.number("amplitude");
    if (r.has("phase")) c.phase = r.number("phase");
    return c;
}

int side(const Reader& r, const char* key) {
    const long long n = r.integer(key);
    if (n < 1 || n > Sampling::kMaxSide)
        throw InputError(r.field(key), "must be between 1 and " +
                                           std::to_string(Sampling::kMaxSide) + " (got " +
                                           std::to_string(n) + ")");
    return static_cast<int>(n);
}

json rows(const std::vector<double>& v, int w, int h) {
    json out = json::array();
    for (int j = 0; j < h; ++j) {
        json row = json::array();
        for (int i = 0; i < w; ++i) row.push_back(v[std::size_t(j) * w + i]);
        out.push_back(std::move(row));
    }
    return out;
}

}  // namespace

template <>
struct JsonIo<Sampling> {
    static Sampling::Input input(const json& j) {
        Reader r(j);
        Sampling::Input in;
        if (r.has("signal") == r.has("image"))
            throw InputError(r.has("signal") ? "image" : "signal",
                             r.has("signal") ? "is not allowed with a signal: give either a 1D "
                                               "\"signal\" or a 2D \"image\""
                                             : "is missing: give either a 1D \"signal\" or a 2D "
                                               "\"image\"");
        if (r.has("signal")) {
            r.only({"signal", "rate", "duration", "reconstruction"});
            in.mode = Sampling::Mode::Signal;
            const json& list = r.get("signal");
            if (!list.is_array())
                throw InputError(r.field("signal"),
                                 "must be a list of sines, got " + describe(list));
            for (std::size_t k = 0; k < list.size(); ++k)
                in.signal.push_back(
                    component(Reader(list[k], r.field("signal") + "[" + std::to_string(k) + "]")));
            in.rate = r.number("rate");
            in.duration = r.number("duration");
            if (r.has("reconstruction")) {
                const std::string s = r.string("reconstruction");
                if (s == "nearest")
                    in.reconstruction = Sampling::Reconstruction::Nearest;
                else if (s == "linear")
                    in.reconstruction = Sampling::Reconstruction::Linear;
                else if (s == "sinc")
                    in.reconstruction = Sampling::Reconstruction::Sinc;
                else
                    throw InputError(
                        r.field("reconstruction"),
                        "must be \"nearest\", \"linear\" or \"sinc\", got \"" + s + "\"");
            }
            return in;
        }
        r.only({"image", "width", "height", "supersampling"});
        in.mode = Sampling::Mode::Image;
        in.width = side(r, "width");
        in.height = side(r, "height");
        const Reader im = r.object("image");
        const std::string type = im.string("type");
        Sampling::Image& g = in.image;
        if (type == "edge") {
            im.only({"type", "angle", "point"});
            g.kind = Sampling::ImageKind::Edge;
            g.angle = im.number("angle");
            g.point =
                im.has("point") ? im.point2("point") : glm::dvec2(in.width / 2.0, in.height / 2.0);
        } else if (type == "checkerboard") {
            im.only({"type", "horizon", "square", "focal"});
            g.kind = Sampling::ImageKind::Checkerboard;
            g.horizon = im.has("horizon") ? im.number("horizon") : 0.9 * in.height;
            g.square = im.has("square") ? im.number("square") : 0.25;
            g.focal = im.has("focal") ? im.number("focal") : double(in.height);
        } else if (type == "zone-plate") {
            im.only({"type", "nyquist_radius"});
            g.kind = Sampling::ImageKind::ZonePlate;
            g.nyquist_radius = im.has("nyquist_radius") ? im.number("nyquist_radius")
                                                        : std::min(in.width, in.height) / 4.0;
        } else {
            throw InputError(
                im.field("type"),
                "must be \"edge\", \"checkerboard\" or \"zone-plate\", got \"" + type + "\"");
        }
        if (r.has("supersampling")) {
            const Reader ss = r.object("supersampling");
            ss.only({"pattern", "samples", "filter", "seed"});
            if (ss.has("pattern")) in.pattern = sampling_json::pattern(ss, "pattern");
            if (ss.has("samples"))
                in.samples = sampling_json::count(ss, "samples", Sampling::kMaxSupersamples);
            if (ss.has("filter")) in.filter = sampling_json::filter(ss, "filter");
            if (ss.has("seed")) in.seed = sampling_json::seed(ss, "seed");
        }
        return in;
    }

    static json input_json(const Sampling::Input& in) {
        if (in.mode == Sampling::Mode::Signal) {
            json sig = json::array();
            for (const auto& c : in.signal)
                sig.push_back(json{{"frequency", nice_number(c.frequency)},
                                   {"amplitude", nice_number(c.amplitude)},
                                   {"phase", nice_number(c.phase)}});
            const char* rec = in.reconstruction == Sampling::Reconstruction::Nearest  ? "nearest"
                              : in.reconstruction == Sampling::Reconstruction::Linear ? "linear"
                                                                                      : "sinc";
            return json{{"signal", std::move(sig)},
                        {"rate", nice_number(in.rate)},
                        {"duration", nice_number(in.duration)},
                        {"reconstruction", rec}};
        }
        json im;
        switch (in.image.kind) {
            case Sampling::ImageKind::Edge:
                im = json{{"type", "edge"},
                          {"angle", nice_number(in.image.angle)},
                          {"point", nice_point(in.image.point)}};
                break;
            case Sampling::ImageKind::Checkerboard:
                im = json{{"type", "checkerboard"},
                          {"horizon", nice_number(in.image.horizon)},
                          {"square", nice_number(in.image.square)},
                          {"focal", nice_number(in.image.focal)}};
                break;
            case Sampling::ImageKind::ZonePlate:
                im = json{{"type", "zone-plate"},
                          {"nyquist_radius", nice_number(in.image.nyquist_radius)}};
                break;
        }
        return json{{"image", std::move(im)},
                    {"width", in.width},
                    {"height", in.height},
                    {"supersampling",
                     {{"pattern", sampling::pattern_id(in.pattern)},
                      {"samples", in.samples},
                      {"filter", sampling::filter_id(in.filter)},
                      {"seed", in.seed}}}};
    }

    static json result(const Sampling::Result& r) {
        if (r.mode == Sampling::Mode::Signal) {
            json samples = json::array();
            for (const auto& s : r.samples) samples.push_back(json::array({s.x, s.y}));
            json aliases = json::array();
            for (const auto& a : r.aliases)
                aliases.push_back(json{{"frequency", a.frequency},
                                       {"alias", a.alias},
                                       {"alias_phase", a.alias_phase},
                                       {"k", a.k},
                                       {"aliased", a.aliased}});
            return json{{"samples", std::move(samples)},
                        {"aliases", std::move(aliases)},
                        {"nyquist_rate", r.nyquist_rate},
                        {"error_rms", r.error_rms}};
        }
        return json{{"width", r.width},
                    {"height", r.height},
                    {"point_sampled", rows(r.point_sampled, r.width, r.height)},
                    {"supersampled", rows(r.supersampled, r.width, r.height)},
                    {"rms_difference", r.rms_difference}};
    }

    static json example() {
        // 7 kHz sampled at 10 kHz for a millisecond (frequencies in kHz, time in ms): alias 3.
        return json{
            {"signal", json::array({json{{"frequency", 7}, {"amplitude", 1}, {"phase", 0}}})},
            {"rate", 10},
            {"duration", 1},
            {"reconstruction", "linear"}};
    }
};

Algorithm sampling_algorithm() {
    return make_algorithm<Sampling>([](const Sampling::Input& in) { return Sampling::run(in); });
}

}  // namespace cg
