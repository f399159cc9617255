// cgsandbox: with no arguments the viewer, with a subcommand the CLI.
#include "cli.hpp"

int main(int argc, char** argv) { return cg::cli_main(argc, argv); }
