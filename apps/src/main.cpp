// tetblend: the command line. main() only wires the subcommands (one per
// cmd_*.cpp file) and turns every error into one line
// "tetblend: error: ..." on stderr with a non-zero exit code:
// 2 for bad command-line usage, 1 for everything else.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "commands.h"

namespace {

std::string oneLine(std::string message) {
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  return message;
}

int fail(const std::string& message, int code) {
  std::fprintf(stderr, "tetblend: error: %s\n", oneLine(message).c_str());
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "tetblend: blend compatible tetrahedral shapes (Kaji-Ochiai parametrisation, dual "
      "quaternions, Lie bodies), make variations and animations, inspect the results.\n"
      "Run 'tetblend SUBCOMMAND --help' for the options of each subcommand.",
      "tetblend"};
  app.require_subcommand(1, 1);
  app.set_version_flag("--version", "tetblend 0.1.0");
  tetblend::cli::registerPrepare(app);
  tetblend::cli::registerBlend(app);
  tetblend::cli::registerBatch(app);
  tetblend::cli::registerVariations(app);
  tetblend::cli::registerAnimate(app);
  tetblend::cli::registerDeform(app);
  tetblend::cli::registerInspect(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    return fail(std::string(e.what()) + " (see 'tetblend --help')", 2);
  } catch (const std::exception& e) {
    return fail(e.what(), 1);
  }
  return 0;
}
