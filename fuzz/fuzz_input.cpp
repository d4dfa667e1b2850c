#include "fuzz_input.h"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>
#include <typeinfo>

#include "batch_spec.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/tet_mesh_io.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::fuzz {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& what) {
  std::cerr << "tetblend fuzz: " << what << std::endl;
  std::abort();
}

// A directory of this process's own, removed when the process ends normally.
class ScratchDir {
 public:
  ScratchDir()
      : path_(fs::temp_directory_path() / ("tetblend_fuzz_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

void writeBytes(const std::string& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) fail("cannot write the scratch file " + path);
}

// Sets the payload size and checksum fields of a model file (layout in
// pipeline/include/tetblend/pipeline/model_file.h) to match the bytes between them.
void repairModelFields(std::string& bytes) {
  constexpr std::size_t kHeader = 8 + 4 + 8, kTrailer = 8;
  if (bytes.size() < kHeader + kTrailer || bytes.compare(0, 8, std::string("TBMODEL\0", 8)) != 0) {
    return;
  }
  const std::uint64_t payloadSize = bytes.size() - kHeader - kTrailer;
  std::uint32_t version = 0;
  for (int i = 0; i < 4; ++i)
    version |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
  const std::uint64_t hash = modelChecksum(
      reinterpret_cast<const unsigned char*>(bytes.data() + kHeader), payloadSize, version);
  for (int i = 0; i < 8; ++i) {
    bytes[12 + i] = static_cast<char>((payloadSize >> (8 * i)) & 0xff);
    bytes[kHeader + payloadSize + i] = static_cast<char>((hash >> (8 * i)) & 0xff);
  }
}

template <typename Elements>
void checkMesh(const Vertices& vertices, const Elements& elements, const std::string& path) {
  if (!vertices.allFinite()) fail(path + ": the reader returned a non-finite position");
  if (elements.size() > 0 && (elements.minCoeff() < 0 || elements.maxCoeff() >= vertices.rows())) {
    fail(path + ": the reader returned an index outside 0.." + std::to_string(vertices.rows() - 1));
  }
}

void checkMessage(const std::string& message, const std::string& stem) {
  if (message.find_first_of("\n\r") != std::string::npos) {
    fail("the error message is more than one line:\n" + message);
  }
  if (message.find(stem) == std::string::npos) {
    fail("the error message does not name the file " + stem + ": " + message);
  }
}

// Writes the input file(s) and returns the path to read.
std::string writeInput(const ScratchDir& dir, std::string bytes, const std::string& extension) {
  const std::string path = dir.file("input" + extension);
  if (extension == ".node") {
    const std::size_t split = bytes.find(kTetGenSeparator);
    const bool hasEle = split != std::string::npos;
    writeBytes(path, std::string_view(bytes).substr(0, split));
    writeBytes(dir.file("input.ele"),
               hasEle ? std::string_view(bytes).substr(split + std::strlen(kTetGenSeparator))
                      : std::string_view());
    return path;
  }
  if (extension == ".tbm") repairModelFields(bytes);
  writeBytes(path, bytes);
  return path;
}

void readAndCheck(const std::string& path, const std::string& extension) {
  if (extension == ".tbm") {
    const ModelData model = readModelFile(path);
    try {
      checkModel(model, path);
    } catch (const Error& e) {
      fail(std::string("the reader returned a model its own check refuses: ") + e.what());
    }
  } else if (extension == ".json") {
    cli::readBatchSpec(path);
  } else if (extension == ".vtu" || extension == ".node" || extension == ".mesh") {
    const TetMesh mesh = readTetMesh(path);
    checkMesh(mesh.vertices, mesh.tets, path);
  } else {
    const SurfaceMesh mesh = readSurface(path);
    checkMesh(mesh.vertices, mesh.triangles, path);
  }
}

}  // namespace

int readFuzzInput(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  static const ScratchDir dir;
  const std::string path =
      writeInput(dir, std::string(reinterpret_cast<const char*>(data), size), extension);
  try {
    readAndCheck(path, extension);
  } catch (const Error& e) {
    checkMessage(e.what(), dir.file("input"));
  } catch (const std::exception& e) {
    fail(std::string("not a tetblend::Error but ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    fail("an exception that is not a std::exception");
  }
  return 0;
}

}  // namespace tetblend::fuzz
