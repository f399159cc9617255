// A file the viewer wrote for the student (a screenshot, a checkpoint, a worked example): on the
// desktop it stays where it was written; in a browser (sandbox/web/) it was written into the
// page's memory and is handed over as a download. Its message says which happened.
#pragma once

#include <string>

#ifdef __EMSCRIPTEN__
#include "browser.hpp"
#endif

namespace cg::viewer {

// True once the file at `path` (just written) is where the student gets it.
inline bool deliver([[maybe_unused]] const std::string& path, [[maybe_unused]] const char* mime) {
#ifdef __EMSCRIPTEN__
    return web::download_file(path, mime);
#else
    return true;
#endif
}

// The message for a delivered file: "<verb> PATH" on the desktop ("Saved", "Wrote"),
// "Downloaded PATH" in a browser.
inline std::string delivered([[maybe_unused]] const char* verb, const std::string& path) {
#ifdef __EMSCRIPTEN__
    verb = "Downloaded";
#endif
    return std::string(verb) + " " + path;
}

}  // namespace cg::viewer
