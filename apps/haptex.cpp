// haptex: one binary, one small Command per subcommand (apps/*_command.cpp).
#include <CLI/CLI.hpp>

#include "apps/command.hpp"

int main(int argc, char** argv) { return haptex::apps::run_main(argc, argv); }
