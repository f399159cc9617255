// The viewer's picture, as pixels: `cgsandbox render` under Xvfb (started here with
// xvfb-run -a), then the PNG read back and searched for the colours of the roles.
#include <catch2/catch.hpp>

#include <stb_image.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/json.hpp"
#include "support/process.hpp"
#include "viewer/palette.hpp"

namespace {

struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgba;
    // Pixels within `tolerance` (per channel) of the role's colour.
    std::vector<std::pair<int, int>> find(std::uint32_t rgba_colour, int tolerance = 24) const {
        return find_in(rgba_colour, 0, 0, width, height, tolerance);
    }
    // The same, within the rectangle [x0, x1) × [y0, y1).
    std::vector<std::pair<int, int>> find_in(std::uint32_t rgba_colour, int x0, int y0, int x1,
                                             int y1, int tolerance = 24) const {
        const int r = rgba_colour >> 24 & 255, g = rgba_colour >> 16 & 255, b = rgba_colour >> 8 & 255;
        std::vector<std::pair<int, int>> hits;
        for (int y = std::max(y0, 0); y < std::min(y1, height); ++y)
            for (int x = std::max(x0, 0); x < std::min(x1, width); ++x) {
                const unsigned char* p = &rgba[4 * (y * width + x)];
                if (std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
                    std::abs(p[2] - b) <= tolerance)
                    hits.push_back({x, y});
            }
        return hits;
    }
};

// `cgsandbox render <args> --out <name>.png` under Xvfb; `env` entries ("NAME=value") are set
// for the renderer.
Image render_args(const std::vector<std::string>& args, const std::string& name,
                  const std::vector<std::string>& env = {}) {
    const std::string out = cg::test::output_path(name + ".png");
    std::vector<std::string> argv = {"env"};
    argv.insert(argv.end(), env.begin(), env.end());
    for (const char* a : {"xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", CG_BINARY, "render"})
        argv.push_back(a);
    argv.insert(argv.end(), args.begin(), args.end());
    argv.push_back("--out");
    argv.push_back(out);
    auto r = cg::test::run_process(argv);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    Image img;
    int channels = 0;
    unsigned char* data = stbi_load(out.c_str(), &img.width, &img.height, &channels, 4);
    REQUIRE(data);
    img.rgba.assign(data, data + 4 * img.width * img.height);
    stbi_image_free(data);
    return img;
}

Image render(const std::string& input, int step, const std::string& name) {
    const std::string in = cg::test::write_temp(name + ".json", input);
    return render_args({"liang-barsky", "--input", in, "--step", std::to_string(step), "--size",
                        "400x300"},
                       name);
}

struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    explicit Box(const std::vector<std::pair<int, int>>& pts) {
        for (auto [x, y] : pts) x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
};

const char* kCrossing =
    R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 2], "p1": [4, 6]})";
const char* kMissing =
    R"({"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4}, "p0": [0, 5], "p1": [6, 5]})";

}  // namespace

TEST_CASE("gui: render shows the window, and the kept part inside it", "[gui]") {
    Image img = render(kCrossing, 6, "crossing-end");
    REQUIRE(img.width == 400);
    REQUIRE(img.height == 300);
    auto window = img.find(cg::viewer::role_rgba(cg::Role::Window));
    auto kept = img.find(cg::viewer::role_rgba(cg::Role::Kept));
    CHECK(window.size() > 300);  // the window's outline, at least
    REQUIRE(kept.size() > 30);   // the clipped segment, drawn thick
    // The kept segment lies inside the window's outline, and runs up and to the right.
    Box w(window), k(kept);
    CHECK(k.x0 >= w.x0 - 8);
    CHECK(k.x1 <= w.x1 + 8);
    CHECK(k.y0 >= w.y0 - 8);
    CHECK(k.y1 <= w.y1 + 8);
    CHECK(k.x1 - k.x0 > 10);
    CHECK(k.y1 - k.y0 > 10);
    CHECK(img.find(cg::viewer::role_rgba(cg::Role::Discarded)).size() < 5);
}

TEST_CASE("gui: before any step nothing is kept, and a rejected segment turns red", "[gui]") {
    Image start = render(kCrossing, 0, "crossing-start");
    CHECK(start.find(cg::viewer::role_rgba(cg::Role::Kept)).size() < 5);
    CHECK(start.find(cg::viewer::role_rgba(cg::Role::Window)).size() > 300);

    Image rejected = render(kMissing, 10, "missing-end");
    CHECK(rejected.find(cg::viewer::role_rgba(cg::Role::Discarded)).size() > 30);
    CHECK(rejected.find(cg::viewer::role_rgba(cg::Role::Kept)).size() < 5);
}

TEST_CASE("gui: the edge under test is drawn in the active colour", "[gui]") {
    Image edge = render(kCrossing, 2, "crossing-edge");  // step 2 tests the left edge
    CHECK(edge.find(cg::viewer::role_rgba(cg::Role::Active)).size() > 100);
}

TEST_CASE("gui: render refuses bad input before opening a window", "[gui][errors]") {
    const std::string in = cg::test::write_temp("bad-render.json", R"({"window": 3})");
    auto r = cg::test::cgsandbox({"render", "liang-barsky", "--input", in, "--out",
                                  cg::test::output_path("never.png")});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("window: must be a JSON object"));
}

// --- lessons and exam practice, in the full UI ------------------------------------------------
//
// At 1400x900 with a lesson or an exam open, the left panel is the leftmost 27 % (378 px) and
// the top two thirds; the canvas runs from there to the right column (the rightmost 27 %).
namespace {

constexpr int kW = 1400;  // × 900
constexpr int kLeft = 378, kRight = kW - 378, kTop = 600;

// Near-black: the panels' text (antialiased glyphs have some pixels at full ink).
std::size_t text_pixels(const Image& img, int x0, int x1) {
    return img.find_in(0x000000ff, x0, 0, x1, kTop, 40).size();
}

}  // namespace

TEST_CASE("gui: the lesson view shows the lesson's text beside the canvas", "[gui][lessons]") {
    Image img = render_args({"--lesson", "liang-barsky", "--preset", "a segment crossing two edges",
                             "--step", "6", "--full", "--size", "1400x900"},
                            "lesson-full");
    REQUIRE(img.width == kW);
    // Section headings in their colour, and plenty of text, in the lesson panel.
    CHECK(img.find_in(cg::viewer::kSectionTitle, 0, 0, kLeft, kTop, 30).size() > 200);
    CHECK(text_pixels(img, 0, kLeft) > 1500);
    // The canvas still shows the run: the window, and the kept part at the end.
    CHECK(img.find_in(cg::viewer::role_rgba(cg::Role::Window), kLeft, 0, kRight, kTop).size() > 300);
    CHECK(img.find_in(cg::viewer::role_rgba(cg::Role::Kept), kLeft, 0, kRight, kTop).size() > 30);

    // Without --lesson the left panel is the algorithm's, with no lesson headings.
    Image plain = render_args({"liang-barsky", "--full", "--size", "1400x900"}, "plain-full");
    CHECK(plain.find_in(cg::viewer::kSectionTitle, 0, 0, kLeft, kTop, 30).size() < 20);
}

TEST_CASE("gui: a checkpoint reopens its lesson", "[gui][lessons][checkpoint]") {
    const std::string c = cg::test::write_temp(
        "lesson-checkpoint.json",
        R"({"algorithm": "liang-barsky", "step": 2, "lesson": "liang-barsky",
            "preset": "a segment crossing two edges",
            "input": {"window": {"xmin": 1, "ymin": 1, "xmax": 5, "ymax": 4},
                      "p0": [0, 2], "p1": [4, 6]}})");
    Image img = render_args({"--checkpoint", c, "--full", "--size", "1400x900"}, "lesson-ckpt");
    CHECK(img.find_in(cg::viewer::kSectionTitle, 0, 0, kLeft, kTop, 30).size() > 200);
}

TEST_CASE("gui: exam practice shows the question and hides the solution", "[gui][exam]") {
    Image img = render_args({"liang-barsky", "--exam", "3", "--full", "--size", "1400x900"},
                            "exam-full");
    // The question's yellow card in the left panel.
    CHECK(img.find_in(cg::viewer::kExamQuestion, 0, 0, kLeft, kTop, 8).size() > 20000);
    // The canvas shows the problem's input at step 0: a window, nothing kept yet.
    CHECK(img.find_in(cg::viewer::role_rgba(cg::Role::Window), kLeft, 0, kRight, kTop).size() > 300);
    CHECK(img.find_in(cg::viewer::role_rgba(cg::Role::Kept), kLeft, 0, kRight, kTop).size() < 5);
}

TEST_CASE("gui: broken lesson files do not stop the viewer, and the good ones open",
          "[gui][lessons][errors]") {
    const std::filesystem::path dir = cg::test::output_path("render-lessons");
    std::filesystem::create_directories(dir);
    std::filesystem::copy_file(CG_SOURCE_DIR "/lessons/040-liang-barsky.json", dir / "good.json",
                               std::filesystem::copy_options::overwrite_existing);
    std::ofstream(dir / "broken.json") << R"({"id": "broken", "title": })";
    const std::string env = "CGSANDBOX_LESSONS=" + dir.string();

    Image img = render_args({"--lesson", "liang-barsky", "--full", "--size", "1400x900"},
                            "lesson-broken-dir", {env});
    CHECK(img.find_in(cg::viewer::kSectionTitle, 0, 0, kLeft, kTop, 30).size() > 200);
    // Opening the broken one is refused clearly, without a crash.
    auto r = cg::test::run_process({"env", env, "xvfb-run", "-a", CG_BINARY, "render", "--lesson",
                                    "broken", "--out", cg::test::output_path("never.png")});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains("no lesson \"broken\""));
}

namespace {

// A role's colour at `alpha` over the white canvas, as the 3D canvas fills faces.
std::uint32_t over_white(std::uint32_t rgba, double alpha) {
    auto ch = [&](int shift) {
        const double c = (rgba >> shift & 255) * alpha + 255 * (1 - alpha);
        return static_cast<std::uint32_t>(std::lround(c)) << shift;
    };
    return ch(24) | ch(16) | ch(8) | 0xffu;
}

}  // namespace

TEST_CASE("gui: a 3D scene opens the 3D canvas, faces filled by their verdict", "[gui][3d]") {
    // Back-face culling's cube seen from its eye: at the end the kept faces are green, the
    // culled ones faint grey; the world axes are drawn in red, green and blue.
    Image end = render_args({"backface-cull", "--size", "600x450"}, "backface-3d-end");
    const auto kept = end.find(over_white(cg::viewer::role_rgba(cg::Role::Kept), 0.45), 12);
    CHECK(kept.size() > 800);
    CHECK(end.find(0xd62728ff, 40).size() > 10);  // the x axis's arrowhead
    CHECK(end.find(cg::viewer::role_rgba(cg::Role::Window), 30).size() > 20);  // the eye
    // Step 1 decides F0: the face being decided is orange, nothing is green yet (but the world's
    // y axis, a thin line of about the kept faces' colour).
    Image first = render_args({"backface-cull", "--step", "1", "--size", "600x450"},
                              "backface-3d-first");
    CHECK(first.find(over_white(cg::viewer::role_rgba(cg::Role::Active), 0.6), 34).size() > 150);
    const auto green = first.find(over_white(cg::viewer::role_rgba(cg::Role::Kept), 0.45), 12);
    CHECK(green.size() * 10 < kept.size());
}

TEST_CASE("gui: an algorithm's slider is drawn over the canvas", "[gui][slider]") {
    // De Casteljau declares t as a slider: its light-blue bar sits along the canvas's bottom.
    Image img = render_args({"de-casteljau", "--size", "600x400"}, "de-casteljau-slider");
    const int bar = static_cast<int>(
        img.find_in(cg::viewer::kNoteBackground, 0, img.height - 45, img.width, img.height, 6).size());
    CHECK(bar > 3000);
    // Liang-Barsky declares none.
    Image none = render_args({"liang-barsky", "--size", "600x400"}, "liang-barsky-no-slider");
    CHECK(none.find_in(cg::viewer::kNoteBackground, 0, none.height - 45, none.width, none.height, 6)
              .size() < 200);
}

TEST_CASE("gui: the ray tracer's image fills in pixel by pixel, and a ray tree is drawn in 3D",
          "[gui][3d][ray-tracer]") {
    // The lesson's 48 × 36 image: the red ball's lit side is about (221, 42, 28). After the
    // first step no pixel is known; at the end the ball is in the image panel (counted inside
    // the panel's content box, from the render's own layout record: the 3D canvas shows the
    // ball's mesh in a similar red, framed differently at each step).
    const std::vector<std::string> lesson = {"--lesson", "ray-tracer", "--preset",
                                             "the whole image, pixel by pixel", "--size", "900x500"};
    auto image_panel_red = [&](const char* step, const std::string& name) {
        std::vector<std::string> a = lesson;
        if (step) a.insert(a.end(), {"--step", step});
        const std::string layout = cg::test::output_path(name + ".json");
        a.insert(a.end(), {"--layout", layout});
        const Image img = render_args(a, name);
        std::ifstream f(layout);
        std::stringstream text;
        text << f.rdbuf();
        const cg::json record = cg::parse_json(text.str());
        std::vector<double> c;
        for (const cg::json& p : record["panels"])
            if (p["kind"] == "image") c = p["content"].get<std::vector<double>>();
        REQUIRE(c.size() == 4);
        return img.find_in(0xdd2a1cff, int(c[0]), int(c[1]), int(c[2]), int(c[3]), 40).size();
    };
    CHECK(image_panel_red("1", "ray-tracer-first") < 10);
    CHECK(image_panel_red(nullptr, "ray-tracer-end") > 300);
    // One pixel's ray tree (the first preset): its two shadow rays, one reaching its light
    // (green) and one blocked (red), and the mirror ray (teal) on the 3D canvas.
    Image tree = render_args({"--lesson", "ray-tracer", "--size", "900x500"}, "ray-tracer-tree");
    CHECK(tree.find(cg::viewer::role_rgba(cg::Role::Kept), 40).size() > 15);
    CHECK(tree.find(cg::viewer::role_rgba(cg::Role::Discarded), 40).size() > 15);
    CHECK(tree.find(cg::viewer::role_rgba(cg::Role::Entering), 40).size() > 15);
}

TEST_CASE("gui: silhouette edges are drawn over the faces they bound, all round the outline",
          "[gui][3d][silhouette-edges]") {
    // A silhouette edge lies on a front face's border; sorted by depth alone it was hidden under
    // that face about half the time, so the loop came out broken. The sphere's loop at the end
    // must show in magenta (the Leaving role), at its full 5 px width (half hidden, the sphere
    // shows about 980 such pixels, the cube about 510), in every quarter around its centre.
    Image cube = render_args({"--lesson", "silhouette-edges", "--size", "600x450"},
                             "silhouette-cube-end");
    CHECK(cube.find(cg::viewer::role_rgba(cg::Role::Leaving), 40).size() > 1200);  // 1,647 drawn
    Image img = render_args({"--lesson", "silhouette-edges", "--preset",
                             "a sphere: the silhouette is a closed loop", "--size", "600x450"},
                            "silhouette-sphere-end");
    const auto magenta = img.find(cg::viewer::role_rgba(cg::Role::Leaving), 40);
    REQUIRE(magenta.size() > 1350);  // 1,672 drawn
    const Box box(magenta);
    const int cx = (box.x0 + box.x1) / 2, cy = (box.y0 + box.y1) / 2;
    int quarter[4] = {0, 0, 0, 0};
    for (auto [x, y] : magenta) ++quarter[(x < cx ? 0 : 1) + (y < cy ? 0 : 2)];
    for (int q : quarter) CHECK(q > 60);
    // The box is roughly square: a loop, not a few stray segments.
    const double aspect = double(box.x1 - box.x0) / std::max(1, box.y1 - box.y0);
    CHECK(aspect > 0.8);
    CHECK(aspect < 1.25);
}
