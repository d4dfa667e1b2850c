#pragma once
// Helpers of the end-to-end tests of the tetblend command line: run the built
// binaries (paths from compile definitions), make a scratch folder per test,
// make the procedural samples and a prepared model, read outputs back with
// VTK's own XML readers (independent of tetblend's writers).

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <set>
#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"
#include "tetblend/meshing/surface_io.h"

namespace tetblend::apps_test {

namespace fs = std::filesystem;

// Interpolation holds to round-off of the stitch solve (a sparse Cholesky of a
// Laplacian with condition ~1e4 on the prepared bar): 1e-7 of the bar's size
// (the bounding-box diagonal is ~4.1) leaves two orders of margin.
constexpr double kInterpolationTolerance = 1e-7 * 4.1;
// The rest's per-tet quality (volume ratio 1, distortion 1, rotation angle 0):
// functions of each tet's gradient, which the rest's reproduction error moves
// by about that error over the tet's edge length. With the stitch at
// round-off (~cond * eps = 2e-12 of the size) that is far below 1e-6; 1e-6
// caps these O(1) quantities absolutely and is not derived from
// kInterpolationTolerance.
constexpr double kRestQualityTolerance = 1e-6;

struct RunResult {
  int code = -1;
  std::string out;
  std::string err;
};

inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs `program` with `args`, capturing stdout and stderr.
inline RunResult runProgram(const std::string& program, const std::vector<std::string>& args,
                            const fs::path& scratch) {
  std::string cmd = quote(program);
  for (const std::string& a : args) cmd += " " + quote(a);
  const fs::path out = scratch / ".stdout", err = scratch / ".stderr";
  cmd += " > " + quote(out.string()) + " 2> " + quote(err.string()) + " < /dev/null";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

/// Runs the tetblend binary.
inline RunResult tetblend(const std::vector<std::string>& args, const fs::path& scratch) {
  return runProgram(TETBLEND_EXE, args, scratch);
}

/// A fresh empty folder for the current test.
inline fs::path scratchDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) / "tetblend_apps" /
                       (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Writes the procedural samples (tetblend-make-samples) into `dir`.
inline void makeSamples(const fs::path& dir) {
  const RunResult r = runProgram(TETBLEND_MAKE_SAMPLES, {dir.string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
}

/// Prepares the bar samples (rest, 4 pi twist, bend) into dir/bar.tbm.
inline fs::path prepareBar(const fs::path& dir) {
  makeSamples(dir);
  const fs::path model = dir / "bar.tbm";
  const RunResult r =
      tetblend({"prepare", (dir / "bar_rest.obj").string(), (dir / "bar_twist4pi.obj").string(),
                (dir / "bar_bend.obj").string(), "-o", model.string()},
               dir);
  EXPECT_EQ(r.code, 0) << r.err;
  return model;
}

/// One line on stderr starting "tetblend: error: ".
inline void expectOneLineError(const RunResult& r) {
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(r.err.rfind("tetblend: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

/// Files in `dir` (names only, hidden ones included), sorted.
inline std::vector<std::string> listDir(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

inline vtkSmartPointer<vtkUnstructuredGrid> readVtu(const fs::path& p) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(p.string().c_str());
  reader->Update();
  return reader->GetOutput();
}

inline vtkSmartPointer<vtkPolyData> readVtp(const fs::path& p) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(p.string().c_str());
  reader->Update();
  return reader->GetOutput();
}

/// Points of a VTK data set as #V by 3.
/// The names of a grid's cell arrays.
inline std::set<std::string> cellArrayNames(vtkUnstructuredGrid* grid) {
  std::set<std::string> names;
  for (int i = 0; i < grid->GetCellData()->GetNumberOfArrays(); ++i)
    names.insert(grid->GetCellData()->GetArrayName(i));
  return names;
}

inline Vertices pointsOf(vtkPointSet* data) {
  Vertices v(data->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    v.row(i) << p[0], p[1], p[2];
  }
  return v;
}

/// Largest distance between corresponding rows.
inline double maxDistance(const Vertices& a, const Vertices& b) {
  EXPECT_EQ(a.rows(), b.rows());
  if (a.rows() != b.rows()) return 1e300;
  return (a - b).rowwise().norm().maxCoeff();
}

}  // namespace tetblend::apps_test
