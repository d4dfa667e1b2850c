#pragma once
// Closed meshes shipped by Debian's libcgal-demo (data.tar.gz, data/meshes),
// extracted at test time into a fresh temporary folder.

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace tetblend::testing_cgal {

/// The path of libcgal-demo's data.tar.gz, or "" when the package is missing.
inline std::string cgalDataTarball() {
  FILE* pipe = popen("dpkg -L libcgal-demo 2>/dev/null | grep 'data.tar.gz$'", "r");
  if (pipe == nullptr) return "";
  char line[4096] = {0};
  std::string path;
  if (std::fgets(line, sizeof line, pipe) != nullptr) path = line;
  pclose(pipe);
  while (!path.empty() && (path.back() == '\n' || path.back() == '\r')) path.pop_back();
  return std::filesystem::exists(path) ? path : "";
}

/// The why of a GTEST_SKIP when cgalDataTarball() is "".
inline const char* kMissingCgalDemo =
    "Debian package libcgal-demo is not installed (setup.sh installs it): no data/meshes/*.off "
    "to test on";

/// Extracts data/meshes/<name> for each of `names` (e.g. "elephant.off")
/// into a new folder under the temporary directory, named after `tag`, and
/// returns the folder holding them ("" if tar failed). The caller removes
/// the folder two levels up (meshFolder.parent_path().parent_path()) when
/// done: remove_all of a path ending in ".." leaves the folder behind.
inline std::filesystem::path extractCgalMeshes(const std::string& tarball,
                                               const std::vector<std::string>& names,
                                               const std::string& tag) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("tetblend_cgal_" + tag + "_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::string command = "tar -xzf '" + tarball + "' -C '" + dir.string() + "'";
  for (const std::string& n : names) command += " data/meshes/" + n;
  if (std::system(command.c_str()) != 0) return "";
  return dir / "data" / "meshes";
}

}  // namespace tetblend::testing_cgal
