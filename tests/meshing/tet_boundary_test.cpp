#include "tetblend/meshing/tet_boundary.h"

#include <gtest/gtest.h>

#include <vector>

#include "tetblend/core/error.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

// Sums of O(#F) unit-scale terms: 1e-12 relative is ~1e4 ε.
constexpr double kRelativeTolerance = 1e-12;

// Divergence theorem oracle: Σ det[a, b, c] / 6 over a closed surface is its
// enclosed volume when triangles face outwards, minus it when inwards.
double enclosedVolume(const SurfaceMesh& surface) {
  double volume = 0.0;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    Eigen::Matrix3d corners;
    for (int k = 0; k < 3; ++k) corners.col(k) = surface.vertices.row(surface.triangles(f, k));
    volume += corners.determinant() / 6.0;
  }
  return volume;
}

TEST(TetBoundary, BoxBoundaryIsOutwardWithAnalyticAreaAndCount) {
  const Eigen::Vector3d size(2.0, 1.0, 3.0);
  const TetMesh box = boxTetMesh(3, 2, 4, size);
  const SurfaceMesh surface = boundarySurface(box);
  // Two triangles per boundary square: 2 (3·2 + 2·4 + 3·4) squares.
  EXPECT_EQ(surface.triangles.rows(), 2 * 2 * (3 * 2 + 2 * 4 + 3 * 4));
  EXPECT_NEAR(enclosedVolume(surface), size.prod(), kRelativeTolerance * size.prod());
  double area = 0.0;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    const Eigen::Vector3d a = surface.vertices.row(surface.triangles(f, 0));
    const Eigen::Vector3d b = surface.vertices.row(surface.triangles(f, 1));
    const Eigen::Vector3d c = surface.vertices.row(surface.triangles(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  const double expectedArea = 2 * (size.x() * size.y() + size.y() * size.z() + size.x() * size.z());
  EXPECT_NEAR(area, expectedArea, kRelativeTolerance * expectedArea);
}

TEST(TetBoundary, ReorderPutsBoundaryFirstAndKeepsGeometry) {
  const TetMesh box = boxTetMesh(3, 3, 3, Eigen::Vector3d::Ones());
  const BoundaryFirstMesh reordered = reorderBoundaryFirst(box);
  // A 4×4×4 grid has 2×2×2 interior vertices.
  EXPECT_EQ(reordered.boundaryVertexCount, 64 - 8);
  for (int v = 0; v < 64; ++v) {
    EXPECT_EQ(reordered.oldToNew[reordered.newToOld[v]], v);
    EXPECT_EQ(reordered.mesh.vertices.row(v), box.vertices.row(reordered.newToOld[v]));
    const bool boundary = (box.vertices.row(reordered.newToOld[v]).cwiseAbs().array() == 0.5).any();
    EXPECT_EQ(boundary, v < reordered.boundaryVertexCount) << "vertex " << v;
  }
  const SurfaceMesh surface = boundarySurface(reordered.mesh);
  EXPECT_LT(surface.triangles.maxCoeff(), reordered.boundaryVertexCount);
  EXPECT_NEAR(enclosedVolume(surface), 1.0, kRelativeTolerance);
}

// The oracle is boundarySurface, which groups every face; a 5×4×3 box has
// tets with all four corners on the boundary, so faces between boundary
// vertices that two tets share must be told apart from boundary faces.
TEST(TetBoundary, SurfaceFirstBoundaryIsTheBoundaryOfABoundaryFirstMesh) {
  const BoundaryFirstMesh reordered =
      reorderBoundaryFirst(boxTetMesh(5, 4, 3, Eigen::Vector3d::Ones()));
  const Tets& tets = reordered.mesh.tets;
  int allBoundaryTets = 0;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    allBoundaryTets += tets.row(t).maxCoeff() < reordered.boundaryVertexCount;
  }
  ASSERT_GT(allBoundaryTets, 0);
  const Triangles expected = boundarySurface(reordered.mesh).triangles;
  EXPECT_EQ(surfaceFirstBoundary(tets, reordered.boundaryVertexCount), expected);
}

TEST(TetBoundary, FaceSharedByThreeTetsIsRejected) {
  TetMesh mesh;
  mesh.vertices = Vertices::Random(6, 3);
  mesh.tets.resize(3, 4);
  mesh.tets << 0, 1, 2, 3, 0, 1, 2, 4, 0, 1, 2, 5;
  EXPECT_THROW(boundarySurface(mesh), InputError);
}

TEST(TetBoundary, CornerOutsideTheVerticesIsRejected) {
  TetMesh mesh;
  mesh.vertices = Vertices::Random(4, 3);
  mesh.tets.resize(1, 4);
  for (int bad : {4, -1}) {
    mesh.tets << 0, 1, 2, bad;
    EXPECT_THROW(boundarySurface(mesh), InputError) << "corner " << bad;
  }
}

}  // namespace
}  // namespace tetblend
