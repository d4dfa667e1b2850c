#pragma once
// The one option a benchmark program takes besides Google Benchmark's flags.

#include <string>

namespace tetblend::bench {

/// Removes `--NAME VALUE` or `--NAME=VALUE` from argv (argc adjusted, the
/// other arguments kept in order, for benchmark::Initialize) and returns
/// VALUE; empty when the option is not given.
inline std::string takeOption(int& argc, char** argv, const std::string& name) {
  const std::string flag = "--" + name, prefix = flag + "=";
  std::string value;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind(prefix, 0) == 0) {
      value = arg.substr(prefix.size());
    } else if (arg == flag && i + 1 < argc) {
      value = argv[++i];
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  return value;
}

}  // namespace tetblend::bench
