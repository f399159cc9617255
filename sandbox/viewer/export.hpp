// "Export worked example…": the current run written out as the CLI's `cgsandbox worked` does,
// without any ImGui or SDL, so the tests can compare it with the golden files.
#pragma once

#include <string>

#include "viewer/session.hpp"

namespace cg::viewer {

// The document for the session's run: Markdown (LaTeX math kept), or pretty JSON. The
// subtitle is the loaded lesson preset's name; in exam practice the document is the exam
// problem, question included, subtitled "exam problem, seed N". Throws InputError when no
// run has started or the input is refused.
std::string export_worked(const Session& s, bool as_json);

// JSON when the path ends in .json, Markdown otherwise.
bool exports_json(const std::string& path);

// worked-<id>.md
std::string default_export_path(const Algorithm& a);

}  // namespace cg::viewer
