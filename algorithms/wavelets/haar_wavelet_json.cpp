// Haar wavelet, JSON:
//   input  {"signal": [x_0, …, x_n−1]                       (1D: n a power of two, 1 to 1024)
//           | "image": [[row 0], [row 1], …]                 (n × n, n a power of two, ≤ 256;
//                                                            row 0 is the top row)
//           | "pattern": {"name": "gradient" | "disc" | "checker" | "rings" | "blocks" | "noise",
//                         "size": n, "seed": s (noise only, optional)}   (a generated grey image),
//           "mode": "1d" (a signal's default) | "standard" (an image's default) | "nonstandard",
//           "normalised": false (averages (a + b)/2, details (a − b)/2) | true (both / √2),
//           "threshold": t (≥ 0: zero the details with |c| < t)  or  "keep": f (in (0, 1]: keep
//           the largest fraction f of the coefficients); both optional, not together}
//   result {"levels": the vector after each level (1D only: the worked answer),
//           "coefficients": the transform (a list, or rows), "compressed": after zeroing,
//           "reconstruction": x̃, "zeroed", "kept": non-zero coefficients dropped and left,
//           "predicted_error": √Σ w c² of the dropped, "l2_error": ‖x − x̃‖₂, "max_error",
//           "relative_error": l2_error / ‖x‖₂, "signal_norm": ‖x‖₂, "coefficient_norm": ‖c‖₂}
#include <algorithm>
#include <climits>

#include "io/registry.hpp"
#include "wavelets/haar_wavelet.hpp"

namespace cg {

// A named namespace: the JSON adapters are compiled in unity batches, where anonymous helpers of
// different adapters would meet.
namespace haar_json {

using Mode = HaarWavelet::Mode;

std::vector<double> numbers(const json& v, const std::string& field, const char* what) {
    if (!v.is_array())
        throw InputError(field, std::string("must be a list of ") + what + ", got " + describe(v));
    std::vector<double> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(as_number(v[i], element(field, i)));
    return out;
}

json rows_of(const std::vector<double>& v, int n, Mode mode) {
    if (mode == Mode::OneD) return json(v);
    json rows = json::array();
    for (int r = 0; r < n; ++r)
        rows.push_back(std::vector<double>(v.begin() + std::ptrdiff_t(r) * n,
                                           v.begin() + std::ptrdiff_t(r + 1) * n));
    return rows;
}

const char* mode_name(Mode m) {
    return m == Mode::OneD ? "1d" : m == Mode::Standard ? "standard" : "nonstandard";
}

}  // namespace haar_json

template <>
struct JsonIo<HaarWavelet> {
    using Mode = HaarWavelet::Mode;
    static HaarWavelet::Input input(const json& j) {
        Reader r(j);
        r.only({"signal", "image", "pattern", "mode", "normalised", "threshold", "keep"});
        HaarWavelet::Input in;
        const int given = int(r.has("signal")) + int(r.has("image")) + int(r.has("pattern"));
        if (given == 0)
            throw InputError("signal",
                             "is missing: give a \"signal\" (a list of numbers), an "
                             "\"image\" (a list of rows) or a \"pattern\"");
        if (given > 1)
            throw InputError(r.has("signal") ? "signal" : "image",
                             "give one of \"signal\", \"image\" and \"pattern\", not several");
        bool two_d = true;
        if (r.has("signal")) {
            two_d = false;
            in.data = haar_json::numbers(r.get("signal"), r.field("signal"), "numbers");
            in.n = int(std::min<std::size_t>(in.data.size(), INT_MAX));
        } else if (r.has("image")) {
            const json& rows = r.get("image");
            const std::string f = r.field("image");
            if (!rows.is_array())
                throw InputError(
                    f, "must be a list of rows (lists of numbers), got " + describe(rows));
            in.n = int(std::min<std::size_t>(rows.size(), INT_MAX));
            for (std::size_t k = 0; k < rows.size(); ++k) {
                std::vector<double> row =
                    haar_json::numbers(rows[k], element(f, k), "numbers (a row)");
                if (row.size() != rows.size())
                    throw InputError(element(f, k),
                                     "has " + std::to_string(row.size()) +
                                         " values, but the "
                                         "image has " +
                                         std::to_string(rows.size()) +
                                         " rows: the 2D transform needs a square image");
                in.data.insert(in.data.end(), row.begin(), row.end());
            }
        } else {
            const Reader p = r.object("pattern");
            p.only({"name", "size", "seed"});
            in.pattern = p.string("name");
            const auto& names = HaarWavelet::pattern_names();
            if (std::find(names.begin(), names.end(), in.pattern) == names.end()) {
                std::string known;
                for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
                throw InputError(p.field("name"),
                                 "must be one of " + known + " (got \"" + in.pattern + "\")");
            }
            in.n = int(p.integer("size", 1, HaarWavelet::kMaxImage,
                                 "1 to " + std::to_string(HaarWavelet::kMaxImage) + " pixels"));
            if (p.has("seed")) {
                if (in.pattern != "noise")
                    throw InputError(p.field("seed"), "only the \"noise\" pattern is seeded");
                in.seed = std::uint64_t(p.integer("seed", 0, 1LL << 53, "0 to 2^53"));
            }
            if ((in.n & (in.n - 1)) != 0)
                throw InputError(p.field("size"), "must be a power of two (1, 2, 4, 8, …), got " +
                                                      std::to_string(in.n));
            in.data = HaarWavelet::pattern_image(in.pattern, in.n, in.seed);
        }
        in.mode = two_d ? Mode::Standard : Mode::OneD;
        if (r.has("mode")) {
            const std::string m = r.string("mode");
            if (m == "1d")
                in.mode = Mode::OneD;
            else if (m == "standard")
                in.mode = Mode::Standard;
            else if (m == "nonstandard")
                in.mode = Mode::NonStandard;
            else
                throw InputError(
                    r.field("mode"),
                    "must be \"1d\", \"standard\" or \"nonstandard\", got \"" + m + "\"");
            if (two_d && in.mode == Mode::OneD)
                throw InputError(r.field("mode"),
                                 "\"1d\" transforms a signal; an image is decomposed "
                                 "\"standard\" or \"nonstandard\"");
            if (!two_d && in.mode != Mode::OneD)
                throw InputError(r.field("mode"),
                                 "\"" + m +
                                     "\" is a 2D decomposition: give an \"image\" (a list "
                                     "of rows), or use \"1d\" for a signal");
        }
        if (r.has("normalised")) in.normalised = r.boolean("normalised");
        if (r.has("threshold") && r.has("keep"))
            throw InputError(r.field("keep"), "give either threshold or keep, not both");
        if (r.has("threshold")) {
            in.compress = HaarWavelet::Compress::Threshold;
            in.threshold = r.number("threshold");
        } else if (r.has("keep")) {
            in.compress = HaarWavelet::Compress::Keep;
            in.keep = r.number("keep");
        }
        return in;
    }

    static json input_json(const HaarWavelet::Input& in) {
        json j;
        if (in.mode == Mode::OneD) {
            json v = json::array();
            for (double x : in.data) v.push_back(nice_number(x));
            j["signal"] = v;
        } else if (!in.pattern.empty()) {
            j["pattern"] = {{"name", in.pattern}, {"size", in.n}};
            if (in.pattern == "noise") j["pattern"]["seed"] = in.seed;
        } else {
            json rows = json::array();
            for (int r = 0; r < in.n; ++r) {
                json row = json::array();
                for (int c = 0; c < in.n; ++c)
                    row.push_back(nice_number(in.data[std::size_t(r) * in.n + c]));
                rows.push_back(row);
            }
            j["image"] = rows;
        }
        j["mode"] = haar_json::mode_name(in.mode);
        j["normalised"] = in.normalised;
        if (in.compress == HaarWavelet::Compress::Threshold)
            j["threshold"] = nice_number(in.threshold);
        else if (in.compress == HaarWavelet::Compress::Keep)
            j["keep"] = nice_number(in.keep);
        return j;
    }

    static json result(const HaarWavelet::Result& r) {
        json j;
        if (r.mode == Mode::OneD) j["levels"] = r.levels;
        j["coefficients"] = haar_json::rows_of(r.coefficients, r.n, r.mode);
        j["compressed"] = haar_json::rows_of(r.compressed, r.n, r.mode);
        j["reconstruction"] = haar_json::rows_of(r.reconstruction, r.n, r.mode);
        j["zeroed"] = r.zeroed;
        j["kept"] = r.kept;
        j["predicted_error"] = r.predicted_error;
        j["l2_error"] = r.l2_error;
        j["max_error"] = r.max_error;
        j["relative_error"] = r.relative_error;
        j["signal_norm"] = r.signal_norm;
        j["coefficient_norm"] = r.coefficient_norm;
        return j;
    }

    static json example() {
        // A 4 × 4 image with a bright corner, decomposed the standard way, small details dropped.
        return parse_json(R"({
            "image": [[9, 7, 3, 5], [7, 9, 5, 3], [2, 2, 2, 2], [4, 0, 2, 2]],
            "mode": "standard", "normalised": false, "threshold": 1})");
    }
};

Algorithm haar_wavelet_algorithm() {
    return make_algorithm<HaarWavelet>(
        [](const HaarWavelet::Input& in) { return HaarWavelet::compute(in); });
}

}  // namespace cg
