// tetblend: the command line. main() only wires the subcommands (one per
// cmd_*.cpp file) and turns every error into one line
// "tetblend: error: ..." on stderr with a non-zero exit code:
// 2 for bad command-line usage, 1 for everything else.

#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "cli_common.h"
#include "commands.h"

namespace {

// Line breaks become spaces and other control bytes \xNN, so that a message
// quoting a file name or a value stays one harmless line on the terminal.
std::string oneLine(const std::string& message) {
  static const char kHex[] = "0123456789abcdef";
  std::string line;
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n' || c == '\r') {
      line += ' ';
    } else if (byte < 0x20 || byte == 0x7f) {
      line += "\\x";
      line += kHex[byte >> 4];
      line += kHex[byte & 0xf];
    } else {
      line += c;
    }
  }
  return line;
}

int fail(const std::string& message, int code) {
  std::fprintf(stderr, "tetblend: error: %s\n", oneLine(message).c_str());
  return code;
}

// Under an address-space limit (ulimit -v) OpenBLAS's worker threads can be
// stuck from start-up, retrying forever to map their 128 MB buffers
// (memory_preflight.h), and OpenBLAS's exit handler waits for them. So with a
// limit set, the process leaves without exit handlers: every file is complete
// or absent already (atomic writes) and the standard streams are flushed.
int finish(int code) {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    std::cout.flush();
    std::fflush(nullptr);
    std::_Exit(code);
  }
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
  int code = 0;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    code = e.get_exit_code() == 0 ? app.exit(e)  // --help, --version
                                  : fail(std::string(e.what()) + " (see 'tetblend --help')", 2);
  } catch (const std::bad_alloc&) {
    code = fail(tetblend::cli::outOfMemoryMessage(std::vector<std::string>(argv + 1, argv + argc)),
                1);
  } catch (const std::exception& e) {
    code = fail(e.what(), 1);
  }
  return finish(code);
}
