// The command line: list, example, run, render (and the viewer when no command is given).
//
// Every error is one line on stderr naming the file, the field and the reason, with exit
// code 2; --help works on every command.
#pragma once

namespace cg {

int cli_main(int argc, char** argv);

}  // namespace cg
