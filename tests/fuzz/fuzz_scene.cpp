// Scene files, through `cgsandbox render-scene`'s path: parse, read the scene (validation),
// then render it with the plain tracer on one thread and check every pixel was written and
// the ray counts add up (samples_per_pixel primary rays per pixel). Only InputError may escape;
// scenes too costly for a fuzz iteration (fuzz_support.hpp) are validated but not rendered.
#include "fuzz_support.hpp"
#include "json_mutator.hpp"
#include "rays/rt_scene.hpp"

// The whole input is one JSON document: mutate it within its shape (json_mutator.hpp).
CG_FUZZ_JSON_MUTATOR(0, nullptr)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    cg::rt::Scene scene;
    cg::json input;
    try {
        input = cg::parse_json(text);
        scene = cg::rt::scene_from_json(input, {"stepping"});
        cg::rt::validate(scene);
        (void)cg::rt::scene_to_json(scene).dump();
    } catch (const cg::InputError&) {
        return 0;
    }
    if (cg::fuzz::too_costly(*cg::fuzz::registry().find("ray-tracer"), input)) return 0;
    const cg::rt::Image img = cg::rt::render(scene, 1);
    if (img.rgba.size() != static_cast<std::size_t>(scene.camera.width) * scene.camera.height)
        cg::fuzz::fail("the image has the wrong size");
    for (std::uint32_t v : img.rgba)
        if ((v & 0xff) != 0xff) cg::fuzz::fail("a pixel was not written");
    // One primary ray per pixel sample (Poisson dart throwing may place fewer).
    const std::uint64_t spp = static_cast<std::uint64_t>(scene.settings.samples_per_pixel);
    if (img.rays.primary < img.rgba.size() || img.rays.primary > img.rgba.size() * spp ||
        (scene.settings.pattern != cg::sampling::Pattern::Poisson &&
         img.rays.primary != img.rgba.size() * spp))
        cg::fuzz::fail("one primary ray per pixel sample");
    // The scene written back reads the same.
    const cg::json written = cg::rt::scene_to_json(scene);
    const cg::rt::Scene again = cg::rt::scene_from_json(written);
    cg::rt::validate(again);
    if (cg::rt::scene_to_json(again) != written)
        cg::fuzz::fail("a scene does not survive writing and reading back");
    return 0;
}
