// tetblend deform: the probe/skinning deformer (handle_deformer.h).

#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "progress.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/tet_mesh_io.h"
#include "tetblend/pipeline/handle_deformer.h"

namespace tetblend::cli {

namespace {

struct DeformArgs {
  std::string mesh;
  std::string handles;
  std::string output;
  std::string method = "kaji";
  double falloff = 2.0;
  bool quiet = false;
};

bool isTetFormat(const std::string& path) {
  const std::string e = extensionOf(path);
  return e == ".vtu" || e == ".node" || e == ".ele" || e == ".mesh";
}

// The files behind a mesh path: a TetGen mesh is its .node and .ele pair.
std::vector<std::string> tetGenPair(const std::string& path) {
  const std::string e = extensionOf(path);
  if (e != ".node" && e != ".ele") return {path};
  return {withExtension(path, ".node"), withExtension(path, ".ele")};
}

NamedArray displacement(const Vertices& after, const Vertices& before) {
  NamedArray a{"displacement", 3, {}};
  for (Eigen::Index i = 0; i < after.rows(); ++i)
    for (int c = 0; c < 3; ++c) a.values.push_back(after(i, c) - before(i, c));
  return a;
}

void runDeform(const DeformArgs& a) {
  const HandleBlend method = parseHandleBlend(a.method);
  const bool tets = isTetFormat(a.mesh);
  if (tets != isTetFormat(a.output)) {
    throw InputError(
        "-o " + a.output + ": a " + (tets ? "tet mesh" : "surface") + " input needs a " +
        (tets ? "tet mesh (.vtu/.node/.mesh)" : "surface (.obj/.off/.ply/.vtp)") + " output");
  }
  checkOutputs(tetGenPair(a.output), [&] {
    std::vector<std::string> inputs = tetGenPair(a.mesh);
    inputs.push_back(a.handles);
    return inputs;
  }());
  const HandleSpec spec = readHandleSpec(a.handles);
  TetMesh tetMesh;
  SurfaceMesh surface;
  if (tets) {
    tetMesh = readTetMesh(a.mesh);
  } else {
    surface = readSurface(a.mesh);
  }
  const Vertices& rest = tets ? tetMesh.vertices : surface.vertices;
  ProgressBar progress("deform", 2, a.quiet);
  Eigen::MatrixXd weights = spec.weights;
  if (weights.size() == 0) {
    weights = distanceWeights(rest, spec.handles, a.falloff);
  } else if (weights.rows() != rest.rows()) {
    throw InputError(a.handles + ": " + std::to_string(weights.rows()) + " weight rows for " +
                     std::to_string(rest.rows()) + " vertices of " + a.mesh);
  }
  const Vertices moved = deformByHandles(rest, spec.handles, weights, method);
  progress.advance();
  const bool vtk = extensionOf(a.output) == ".vtu" || extensionOf(a.output) == ".vtp";
  MeshDataArrays data;
  if (vtk) data.pointData.push_back(displacement(moved, rest));
  if (tets) {
    writeTetMesh(a.output, TetMesh{moved, tetMesh.tets}, data);
  } else {
    writeSurface(a.output, SurfaceMesh{moved, surface.triangles}, data);
  }
  progress.advance();
}

}  // namespace

void registerDeform(CLI::App& root) {
  auto args = std::make_shared<DeformArgs>();
  CLI::App* cmd = root.add_subcommand(
      "deform",
      "Probe/skinning deformer (Kaji-Ochiai 6.1, Kavan et al. 6): every vertex moves by the "
      "blend of the handles' transforms with its weights. Weights come from the handle file or, "
      "if it has none, from distance to the handle centres: w_i ~ (|u - c_i| + delta)^-p, "
      "normalised to sum 1, delta = 1e-3 x bounding-box diagonal. A surface in gives a surface "
      "out, a tet mesh a tet mesh; .vtu/.vtp outputs carry point data 'displacement'.");
  cmd->add_option("MESH", args->mesh,
                  "surface (.obj/.off/.ply/.stl/.vtp) or tet mesh (.vtu/.node/.mesh)")
      ->required();
  cmd->add_option("--handles", args->handles,
                  "handle JSON: {\"handles\": [{\"name\", \"centre\": [x,y,z], \"matrix\": 4x4 | "
                  "\"translation\", \"rotation\" (rotation vector, radians, any length), "
                  "\"stretch_log\": 3x3}], \"weights\": [[one per handle] per vertex] (optional)}")
      ->required();
  cmd->add_option("-o,--output", args->output, "output mesh (format by extension)")->required();
  cmd->add_option("--method", args->method,
                  "per-vertex blend: " + handleBlendNames() + "; dq blends rigid handles only")
      ->capture_default_str();
  cmd->add_option("--falloff", args->falloff, "exponent p of the distance weights")
      ->capture_default_str();
  addQuietOption(*cmd, args->quiet);
  cmd->callback([args] { runDeform(*args); });
}

}  // namespace tetblend::cli
