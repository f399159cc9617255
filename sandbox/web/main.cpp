// The browser's main (the emscripten build, sandbox/web/): the viewer as `cgsandbox` opens it without
// arguments — the lesson list, the first algorithm beside it — or, when the address's fragment
// holds a checkpoint (a shared link), exactly that step. The browser owns the loop: each
// animation frame runs one turn of the viewer's own loop (Viewer::turn, never sleeping), and
// main returns while the page lives on.
#include <emscripten.h>

#include <SDL.h>

#include <memory>
#include <optional>
#include <string>

#include "browser.hpp"
#include "io/registry.hpp"
#include "viewer/app.hpp"
#include "viewer/host.hpp"
#include "viewer/session.hpp"

namespace {

// What the page keeps for the tab's lifetime (made in main, never freed: the tab's end frees it),
// handed to each animation frame by emscripten_set_main_loop_arg.
struct Page {
    const cg::Registry registry = cg::builtin_registry();
    std::unique_ptr<cg::viewer::Viewer> viewer;
};

// A checkpoint's JSON read against the registry; the error, as the viewer would say it, if not.
std::optional<cg::Checkpoint> read_checkpoint(const cg::Registry& registry, const std::string& text,
                                              std::string& error) {
    try {
        return cg::checkpoint_from_json(cg::parse_json(text), registry);
    } catch (const std::exception& e) {
        error = e.what();
        return std::nullopt;
    }
}

// A redraw on the next turn: the viewer draws when events come (Viewer::turn), and a
// checkpoint opened from the page is not one.
void wake() {
    SDL_Event e{};
    e.type = SDL_USEREVENT;
    SDL_PushEvent(&e);
}

void frame(void* arg) {
    Page* page = static_cast<Page*>(arg);
    cg::viewer::Viewer& v = *page->viewer;
    if (std::optional<std::string> text = cg::web::take_pending_checkpoint()) {
        std::string error;
        if (std::optional<cg::Checkpoint> c = read_checkpoint(page->registry, *text, error)) {
            v.session().set_status("Opened the checkpoint", false);
            v.session().load(*c);
        } else {
            v.session().set_status("checkpoint: " + error, true);
        }
        wake();
    }
    const int before = v.frames();
    v.turn(0);
    if (v.frames() != before) cg::web::publish(v.session(), v.frames());
}

}  // namespace

int main() {
    Page* page = new Page;
    std::optional<cg::Checkpoint> initial;
    std::string error;
    if (std::optional<std::string> text = cg::web::fragment_json())
        initial = read_checkpoint(page->registry, *text, error);
    try {
        page->viewer = std::make_unique<cg::viewer::Viewer>(page->registry, initial);
    } catch (const std::exception& e) {
        // Most likely no WebGL 2 in this browser: say so on the page, not only in the console.
        EM_ASM({ document.getElementById('status').textContent = 'Cannot start: ' + UTF8ToString($0); },
               e.what());
        return 1;
    }
    cg::viewer::Session& s = page->viewer->session();
    if (!error.empty()) s.set_status("the link's checkpoint: " + error, true);
    s.record_widgets = true;  // published to the page (window.cgsandbox.widgets) for the test
    EM_ASM({
        document.getElementById("status").textContent = "";
        window.addEventListener('hashchange', () => {
            try { Module.cgPending = decodeURIComponent(location.hash.slice(1)); } catch (e) {}
        });
    });
    emscripten_set_main_loop_arg(frame, page, 0, false);
    return 0;
}
