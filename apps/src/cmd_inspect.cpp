// tetblend inspect: what a surface, tet mesh or model file is (counts,
// bounding box), its validation problems and its quality figures, on stdout.

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/surface_validation.h"
#include "tetblend/meshing/tet_boundary.h"
#include "tetblend/meshing/tet_mesh_io.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::cli {

namespace {

constexpr std::size_t kShownProblems = 10;  // problems listed per file; all are counted

struct InspectArgs {
  std::vector<std::string> files;
  bool quiet = false;
};

void printBox(const Vertices& v) {
  if (v.rows() == 0) return;
  const Eigen::RowVector3d lo = v.colwise().minCoeff(), hi = v.colwise().maxCoeff();
  std::printf("  bounding box: [%g, %g, %g] .. [%g, %g, %g] (diagonal %g)\n", lo.x(), lo.y(),
              lo.z(), hi.x(), hi.y(), hi.z(), boundingBoxDiagonal(v));
}

void printProblems(const std::vector<SurfaceProblem>& problems) {
  if (problems.empty()) {
    std::printf("  validation: ok\n");
    return;
  }
  std::printf(
      "  validation: %zu problem(s) for one solid bounded by the file's faces as they are "
      "(prepare works around most: it fills holes, zips seams, merges zero-length edges, meshes "
      "overlapping parts on their own, gives parts no interior fits a tet per face, and says what "
      "it did)\n",
      problems.size());
  for (std::size_t i = 0; i < problems.size() && i < kShownProblems; ++i)
    std::printf("    %s\n", problems[i].message.c_str());
}

// Signed volumes of `tets` on `vertices` against the rest volumes: min/max
// ratio and inverted count.
void printVolumeRatios(const char* what, const Vertices& rest, const Vertices& shape,
                       const Tets& tets) {
  double lo = 1e300, hi = -1e300;
  int inverted = 0;
  for (Eigen::Index j = 0; j < tets.rows(); ++j) {
    const double r = tetSignedVolume(shape, tets.row(j)) / tetSignedVolume(rest, tets.row(j));
    lo = std::min(lo, r);
    hi = std::max(hi, r);
    inverted += tetSignedVolume(shape, tets.row(j)) <= 0.0 ? 1 : 0;
  }
  std::printf("  %s: volume ratio to rest %g .. %g, inverted tets %d\n", what, lo, hi, inverted);
}

void printTetQuality(const TetMesh& mesh) {
  double lo = 1e300, hi = -1e300, total = 0.0;
  int inverted = 0;
  for (Eigen::Index j = 0; j < mesh.tets.rows(); ++j) {
    const double v = tetSignedVolume(mesh.vertices, mesh.tets.row(j));
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    total += v;
    inverted += v <= 0.0 ? 1 : 0;
  }
  std::printf("  tet volumes: min %g, max %g, total %g; inverted or flat tets: %d\n", lo, hi, total,
              inverted);
}

bool isModelFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  in.read(magic, 8);
  return in && std::string(magic, 7) == "TBMODEL";
}

void inspectModel(const std::string& path) {
  const ModelData m = readModelFile(path);
  std::printf("%s: tetblend model (format version %u)\n", path.c_str(), m.formatVersion);
  std::printf("  rest: %s; %lld vertices (%d on the surface), %lld tets, %lld surface triangles\n",
              m.restSource.c_str(), static_cast<long long>(m.rest.vertices.rows()),
              m.surfaceVertexCount, static_cast<long long>(m.rest.tets.rows()),
              static_cast<long long>(m.surfaceTriangles.rows()));
  if (!m.inputVertexRows.empty()) {
    const auto loose = std::count_if(m.inputVertexRows.begin(), m.inputVertexRows.end(),
                                     [&](int row) { return row >= m.surfaceVertexCount; });
    std::printf(
        "  input surface: %lld vertices (copies along seams or zero-length edges merged for the "
        "tets; %lld used by no face, kept beside the tets)\n",
        static_cast<long long>(m.inputVertexCount()), static_cast<long long>(loose));
  }
  if (m.blendCache) {
    std::printf(
        "  fast load: the stitch factor (%zu entries) and the kaji parameters (rotation "
        "consistency %s) are kept\n",
        m.blendCache->factor.values.size(), m.blendCache->kaji.rotationConsistency ? "on" : "off");
  }
  printBox(m.rest.vertices);
  printTetQuality(m.rest);
  if (!m.excludedTets.empty()) {
    // Tets some example cannot embed (its surface folds or intersects itself).
    constexpr std::size_t kListed = 20;
    std::printf("  excluded from the stitch: %zu tets (", m.excludedTets.size());
    for (std::size_t i = 0; i < std::min(kListed, m.excludedTets.size()); ++i) {
      std::printf("%s%d", i > 0 ? ", " : "", m.excludedTets[i]);
    }
    std::printf("%s)\n", m.excludedTets.size() > kListed ? ", ..." : "");
  }
  for (std::size_t k = 0; k < m.examples.size(); ++k) {
    const std::string label = "example " + std::to_string(k + 1) + " (" + m.exampleSources[k] + ")";
    printVolumeRatios(label.c_str(), m.rest.vertices, m.examples[k], m.rest.tets);
  }
}

void inspectTetMesh(const std::string& path) {
  const TetMesh mesh = readTetMesh(path);
  std::printf("%s: tet mesh; %lld vertices, %lld tets\n", path.c_str(),
              static_cast<long long>(mesh.vertices.rows()),
              static_cast<long long>(mesh.tets.rows()));
  printBox(mesh.vertices);
  printTetQuality(mesh);
  const SurfaceMesh boundary = boundarySurface(mesh);
  std::printf("  boundary: %lld triangles\n", static_cast<long long>(boundary.triangles.rows()));
}

void inspectSurface(const std::string& path) {
  const SurfaceMesh mesh = readSurface(path);
  std::printf("%s: surface; %lld vertices, %lld triangles\n", path.c_str(),
              static_cast<long long>(mesh.vertices.rows()),
              static_cast<long long>(mesh.triangles.rows()));
  printBox(mesh.vertices);
  const SurfaceValidation v = validateSurface(mesh, path);
  std::printf("  components: %d\n", v.componentCount);
  printProblems(v.problems);
}

void runInspect(const InspectArgs& a) {
  for (const std::string& f : a.files) {
    const std::string ext = extensionOf(f);
    if (ext == ".tbm" || isModelFile(f)) {
      inspectModel(f);
    } else if (ext == ".vtu" || ext == ".node" || ext == ".ele" || ext == ".mesh") {
      inspectTetMesh(f);
    } else {
      inspectSurface(f);
    }
    std::fflush(stdout);
  }
}

}  // namespace

void registerInspect(CLI::App& root) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* cmd = root.add_subcommand(
      "inspect",
      "Print what each file is: a model (sources, counts, bounding box, per-example volume "
      "ratios and inverted tets), a tet mesh (.vtu/.node/.ele/.mesh: counts, bounding box, tet "
      "volumes, boundary) or a surface (counts, bounding box, components, validation problems: "
      "the first 10 are listed, all counted). Problems are reported, not errors; an unreadable "
      "file is an error.");
  cmd->add_option("FILE", args->files, "files to inspect")->required();
  addQuietOption(*cmd, args->quiet);
  cmd->callback([args] { runInspect(*args); });
}

}  // namespace tetblend::cli
