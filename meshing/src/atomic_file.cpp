#include "tetblend/meshing/atomic_file.h"

#include <filesystem>
#include <random>
#include <system_error>

#include "tetblend/core/error.h"

namespace tetblend {
namespace fs = std::filesystem;

namespace {

std::string temporarySibling(const fs::path& target) {
  std::random_device device;
  const auto tag = std::to_string(device());
  return (target.parent_path() / ("." + target.filename().string() + "." + tag + ".tmp")).string();
}

}  // namespace

std::string nonRegularOutputReason(const std::string& path) {
  std::error_code ec;
  switch (fs::symlink_status(path, ec).type()) {
    case fs::file_type::none:
    case fs::file_type::not_found:
    case fs::file_type::regular:
      return "";
    case fs::file_type::directory:
      return "is a directory, not a file";
    case fs::file_type::symlink:
      return "is a symbolic link (it would be replaced, not written through)";
    case fs::file_type::fifo:
      return "is a FIFO (named pipe), not a regular file";
    case fs::file_type::block:
    case fs::file_type::character:
      return "is a device, not a regular file";
    case fs::file_type::socket:
      return "is a socket, not a regular file";
    default:
      return "exists and is not a regular file";
  }
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tempPath)>& write) {
  const fs::path target(path);
  const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) {
    throw InputError(path + ": directory '" + directory.string() +
                     "' does not exist; create it first");
  }
  const std::string reason = nonRegularOutputReason(path);
  if (!reason.empty()) throw InputError(path + ": " + reason + "; choose another output name");
  const std::string temp = temporarySibling(target);
  try {
    write(temp);
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw InputError(path + ": cannot replace the file (" + ec.message() + "); check permissions");
  }
}

}  // namespace tetblend
