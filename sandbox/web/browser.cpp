// The browser side of the viewer (see browser.hpp): a few lines of JavaScript each, through
// emscripten's EM_JS, and nothing kept in C++ but what the page hands back.
#include "browser.hpp"

#include <emscripten.h>

#include <cstdlib>

#include "viewer/session.hpp"

namespace {

// Each returns a JavaScript string as a malloc'd C string (emscripten's allocateUTF8; freed by
// the caller, owned() below), or null for none.
EM_JS(char*, js_take_pending, (), {
    const text = Module.cgPending;
    Module.cgPending = null;
    if (text === null || text === undefined) return 0;
    return allocateUTF8(text);
});

EM_JS(char*, js_fragment, (), {
    if (location.hash.length < 2) return 0;
    let text;
    try { text = decodeURIComponent(location.hash.slice(1)); } catch (e) { text = location.hash.slice(1); }
    return allocateUTF8(text);
});

EM_JS(void, js_download, (const char* name, const char* mime, const void* data, int size), {
    const blob = new Blob([HEAPU8.slice(data, data + size)], {type: UTF8ToString(mime)});
    const a = document.createElement('a');
    a.href = URL.createObjectURL(blob);
    a.download = UTF8ToString(name);
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 60000);
});

// The picker's answer comes back asynchronously, as Module.cgPending.
EM_JS(void, js_upload, (), {
    const input = document.createElement('input');
    input.type = 'file';
    input.accept = '.json,application/json';
    input.onchange = () => {
        if (input.files.length) input.files[0].text().then((t) => { Module.cgPending = t; });
    };
    input.click();
});

// history.replaceState: the address changes without a reload or a hashchange event (the viewer
// already shows that step). The clipboard may refuse (no user gesture, no secure context): the
// link is in the address bar and in the viewer's message anyway.
EM_JS(char*, js_share, (const char* json), {
    const url = location.href.split('#')[0] + '#' + encodeURIComponent(UTF8ToString(json));
    history.replaceState(null, "", url);
    if (navigator.clipboard) navigator.clipboard.writeText(url).catch(() => {});
    return allocateUTF8(url);
});

EM_JS(void, js_publish, (const char* state), {
    window.cgsandbox = JSON.parse(UTF8ToString(state));
    if (window.cgsandbox.frames >= 1 && !window.cgFirstFrameMs) {
        window.cgFirstFrameMs = performance.now();  // since the page's navigation started
        console.log('cgsandbox: first frame after ' + window.cgFirstFrameMs.toFixed(0) + ' ms');
    }
});

std::optional<std::string> owned(char* p) {
    if (!p) return std::nullopt;
    std::string s(p);
    std::free(p);
    return s;
}

}  // namespace

namespace cg::web {

void download(const std::string& name, const char* mime, const void* data, std::size_t size) {
    js_download(name.c_str(), mime, data, static_cast<int>(size));
}

bool download_file(const std::string& path, const char* mime) {
    try {
        const std::string bytes = read_text_file(path);
        download(path.substr(path.find_last_of('/') + 1), mime, bytes.data(), bytes.size());
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

void upload_checkpoint() { js_upload(); }

std::string share_link(const Checkpoint& c) {
    return owned(js_share(checkpoint_to_json(c).dump().c_str())).value_or("");
}

std::optional<std::string> fragment_json() { return owned(js_fragment()); }

std::optional<std::string> take_pending_checkpoint() { return owned(js_take_pending()); }

void publish(const viewer::Session& s, int frames) {
    json widgets = json::object();
    for (const auto& [name, w] : s.widgets)
        widgets[name] = {w.box.min.x,    w.box.min.y,    w.box.max.x,    w.box.max.y, w.visible,
                         w.window.min.x, w.window.min.y, w.window.max.x, w.window.max.y};
    const json state = {{"frames", frames},
                        {"algorithm", s.algorithm ? s.algorithm->spec->id : ""},
                        {"step", s.index()},
                        {"lesson", s.lesson_id},
                        {"status", s.status},
                        {"canvas", {s.canvas_rect.min.x, s.canvas_rect.min.y, s.canvas_rect.max.x,
                                    s.canvas_rect.max.y}},
                        {"widgets", widgets}};
    js_publish(state.dump().c_str());
}

}  // namespace cg::web
