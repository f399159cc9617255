// Haar wavelet exam problems, unnormalised as the course writes them: two times in three a
// signal of 4 or 8 digits ("the Haar transform of [8 4 1 3]", level by level; one time in ten a
// constant one, whose details are all 0), a quarter of them followed by zeroing the details
// below 1 or 2 in size and the error that costs; one time in three a 2 × 2 or 4 × 4 image of
// digits, decomposed the standard or the non-standard way.
#include "core/format.hpp"
#include "wavelets/haar_wavelet.hpp"

namespace cg {

HaarWavelet::Input HaarWavelet::exam_input(Rng& rng) {
    Input in;
    in.normalised = false;
    if (rng.chance(2.0 / 3)) {
        in.mode = Mode::OneD;
        in.n = rng.chance(0.6) ? 4 : 8;
        const bool constant = rng.chance(0.1);
        const double c = double(rng.integer(0, 9));
        for (int i = 0; i < in.n; ++i) in.data.push_back(constant ? c : double(rng.integer(0, 9)));
        if (rng.chance(0.25)) {
            in.compress = Compress::Threshold;
            in.threshold = double(rng.integer(1, 2));
        }
    } else {
        in.mode = rng.chance(0.5) ? Mode::Standard : Mode::NonStandard;
        in.n = rng.chance(0.5) ? 2 : 4;
        for (int i = 0; i < in.n * in.n; ++i) in.data.push_back(double(rng.integer(0, 9)));
    }
    return in;
}

namespace {
std::string digits(const std::vector<double>& v, int from, int count) {
    std::string t = "[";
    for (int i = 0; i < count; ++i) t += (i ? " " : "") + num(v[std::size_t(from + i)]);
    return t + "]";
}
}  // namespace

std::string HaarWavelet::question(const Input& in) {
    const std::string rule =
        "average (a + b)/2 stored first and the detail a − (a + b)/2 = (a − b)/2 stored after "
        "the averages";
    if (in.mode == Mode::OneD) {
        std::string q = "Compute the (unnormalised) Haar transform of " + digits(in.data, 0, in.n) +
                        " as in the course: replace each pair of "
                        "neighbours (a, b) by its " +
                        rule +
                        ", then repeat on the averages until one is left. Give the vector after "
                        "each level (levels) and the final coefficients (coefficients).";
        if (in.compress == Compress::Threshold)
            q += " Then set every detail with |d| < " + num(in.threshold) +
                 " to 0, reconstruct, and give how many non-zero coefficients you zeroed (zeroed) "
                 "and the L2 error ‖x − x′‖₂ of the reconstruction (l2_error).";
        return q;
    }
    std::string rows;
    for (int r = 0; r < in.n; ++r) rows += (r ? ", " : "") + digits(in.data, r * in.n, in.n);
    const std::string how =
        in.mode == Mode::Standard
            ? "the standard way: transform every row fully with 1-D Haar (all levels), then "
              "every column"
            : "the non-standard way: one level on every row, then one level on every column, then "
              "the same on the top-left block of averages, until one average is left";
    return "Decompose the " + std::to_string(in.n) + " × " + std::to_string(in.n) +
           " image with rows " + rows + " by the 2-D Haar transform, " + how +
           ". Each 1-D level stores the " + rule +
           ". Give the coefficients as rows (coefficients).";
}

std::vector<std::string> HaarWavelet::answer_fields(const Input& in) {
    if (in.mode != Mode::OneD) return {"coefficients"};
    if (in.compress == Compress::Threshold) return {"levels", "coefficients", "zeroed", "l2_error"};
    return {"levels", "coefficients"};
}

}  // namespace cg
