// What the viewer does differently in a browser (the emscripten build, sandbox/web/): files go
// out as downloads and come in as uploads, a checkpoint travels as a link (its JSON in the URL's
// fragment), and the page can read what the viewer shows (window.cgsandbox) for the browser
// test. Only built for the web; the viewer calls it from inside `#ifdef __EMSCRIPTEN__`.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "checkpoint.hpp"

namespace cg::viewer {
struct Session;
}

namespace cg::web {

// Hands `size` bytes to the browser as a download named `name`.
void download(const std::string& name, const char* mime, const void* data, std::size_t size);

// Hands a file of the page's memory file system (just written by the viewer) to the browser as
// a download, under its own name; false if it cannot be read.
bool download_file(const std::string& path, const char* mime);

// Asks the browser for a file (its file picker); when one is chosen, the viewer opens it as a
// checkpoint, at the start of a later frame.
void upload_checkpoint();

// The page's address with the checkpoint in its fragment: #<the checkpoint's JSON, URI-encoded>.
// Puts it in the address bar (without reloading) and on the clipboard; returns it.
std::string share_link(const Checkpoint& c);

// The checkpoint in the address's fragment, if any (the caller reads it with the registry).
std::optional<std::string> fragment_json();

// A checkpoint the page handed over since the last frame (an upload, a changed fragment).
std::optional<std::string> take_pending_checkpoint();

// window.cgsandbox = {frames, algorithm, step, lesson, status, canvas, widgets}: what the viewer shows
// now, for the browser test (tests/web/) and anyone curious in the console. widgets: by name,
// [x0, y0, x1, y1, visible, then the x0, y0, x1, y1 of the visible part of its window], in CSS
// pixels of the canvas; canvas: [x0, y0, x1, y1] of the picture's area, the same way.
void publish(const viewer::Session& s, int frames);

}  // namespace cg::web
