// The viewer's picture, as pixels: `cgsandbox render` under Xvfb (started here with
// xvfb-run -a), then the PNG read back and searched for the colours of the roles.
#include <catch2/catch.hpp>

#include <stb_image.h>

#include "io/json.hpp"
#include "support/process.hpp"
#include "viewer/palette.hpp"

namespace {

struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgba;
    // Pixels within `tolerance` (per channel) of the role's colour.
    std::vector<std::pair<int, int>> find(std::uint32_t rgba_colour, int tolerance = 24) const {
        const int r = rgba_colour >> 24 & 255, g = rgba_colour >> 16 & 255, b = rgba_colour >> 8 & 255;
        std::vector<std::pair<int, int>> hits;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const unsigned char* p = &rgba[4 * (y * width + x)];
                if (std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
                    std::abs(p[2] - b) <= tolerance)
                    hits.push_back({x, y});
            }
        return hits;
    }
};

Image render(const std::string& input, int step, const std::string& name) {
    const std::string in = cg::test::write_temp(name + ".json", input);
    const std::string out = cg::test::output_path(name + ".png");
    auto r = cg::test::run_process({"xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", CG_BINARY,
                                    "render", "liang-barsky", "--input", in, "--step",
                                    std::to_string(step), "--out", out, "--size", "400x300"});
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

TEST_CASE("gui: before any step nothing is kept; a rejected segment turns red", "[gui]") {
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
