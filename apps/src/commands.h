#pragma once
// The subcommands of the tetblend command line. Each register function adds
// one subcommand (with its options and --help text) to the root app and sets
// its callback; main.cpp only wires them and turns errors into one line.

#include <CLI/CLI.hpp>

namespace tetblend::cli {

void registerPrepare(CLI::App& root);     ///< tetblend prepare (cmd_prepare.cpp)
void registerBlend(CLI::App& root);       ///< tetblend blend (cmd_blend.cpp)
void registerBatch(CLI::App& root);       ///< tetblend batch (cmd_batch.cpp)
void registerVariations(CLI::App& root);  ///< tetblend variations (cmd_variations.cpp)
void registerAnimate(CLI::App& root);     ///< tetblend animate (cmd_animate.cpp)
void registerDeform(CLI::App& root);      ///< tetblend deform (cmd_deform.cpp)
void registerInspect(CLI::App& root);     ///< tetblend inspect (cmd_inspect.cpp)

}  // namespace tetblend::cli
