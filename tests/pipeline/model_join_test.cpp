// The join of models of disjoint sets of the input's faces (model_join.h):
// rows, tets, examples, excluded tets and input vertex rows, checked
// against the layout worked out by hand for two small parts that share one
// input vertex.

#include "model_join.h"

#include <gtest/gtest.h>

#include "tetblend/core/error.h"

namespace tetblend {
namespace {

// A part with `surface` surface rows and `interior` more, one tet over the
// given rows, positions (row, 10 * row + offset, 0) in the rest and
// (row, 0, offset) in the one example.
ModelPart part(int surface, int interior, const std::vector<int>& inputVertices,
               const std::vector<int>& tet, double offset) {
  ModelPart p;
  p.inputVertices = inputVertices;
  ModelData& m = p.model;
  m.surfaceVertexCount = surface;
  const int rows = surface + interior;
  m.rest.vertices.resize(rows, 3);
  Vertices example(rows, 3);
  for (int r = 0; r < rows; ++r) {
    m.rest.vertices.row(r) << r, 10.0 * r + offset, 0.0;
    example.row(r) << r, 0.0, offset;
  }
  m.examples.push_back(example);
  m.exampleSources = {"example.obj"};
  m.restSource = "rest.obj";
  m.rest.tets.resize(1, 4);
  m.rest.tets << tet[0], tet[1], tet[2], tet[3];
  m.excludedTets = {0};
  return p;
}

TEST(ModelJoin, RowsAreSurfacesFirstThenInteriorsAndASharedVertexKeepsTheFirstRow) {
  // Input: 5 vertices. Part a has input vertices 0, 2, 4 (surface rows 0-2)
  // and one interior row; part b has input vertices 1, 4, 3 (surface rows
  // 0-2, input vertex 4 shared with a) and two interior rows.
  const ModelPart a = part(3, 1, {0, 2, 4}, {0, 1, 2, 3}, 0.5);
  const ModelPart b = part(3, 2, {1, 4, 3}, {0, 1, 3, 4}, 0.25);
  const Triangles faces = (Triangles(2, 3) << 0, 2, 4, 1, 4, 3).finished();
  const ModelData joined = joinedModel({a, b}, faces, 5);
  // Rows: a's surface 0-2, b's surface 3-5, a's interior 6, b's interior 7-8.
  EXPECT_EQ(joined.surfaceVertexCount, 6);
  ASSERT_EQ(joined.rest.vertices.rows(), 9);
  const std::vector<std::pair<int, int>> rowOfPartRow = {
      {0, 0}, {1, 1}, {2, 2}, {6, 3}};  // a: joined row, own row
  for (const auto& [row, own] : rowOfPartRow) {
    EXPECT_TRUE(joined.rest.vertices.row(row) == a.model.rest.vertices.row(own)) << row;
    EXPECT_TRUE(joined.examples[0].row(row) == a.model.examples[0].row(own)) << row;
  }
  for (const auto& [row, own] :
       std::vector<std::pair<int, int>>{{3, 0}, {4, 1}, {5, 2}, {7, 3}, {8, 4}}) {
    EXPECT_TRUE(joined.rest.vertices.row(row) == b.model.rest.vertices.row(own)) << row;
  }
  // a's tet as it was; b's tet (own rows 0, 1, 3, 4) with own row 1, input
  // vertex 4, on a's row 2: joined rows 3, 2, 7, 8. b's own copy (row 4)
  // is in no tet.
  ASSERT_EQ(joined.rest.tets.rows(), 2);
  EXPECT_TRUE((joined.rest.tets.row(0).array() == Eigen::RowVector4i(0, 1, 2, 6).array()).all());
  EXPECT_TRUE((joined.rest.tets.row(1).array() == Eigen::RowVector4i(3, 2, 7, 8).array()).all());
  // Input 0, 2, 4 on a's rows 0, 1, 2 (4 stays a's); 1 and 3 on b's 3, 5.
  EXPECT_EQ(joined.inputVertexRows, (std::vector<int>{0, 3, 1, 5, 2}));
  EXPECT_EQ(joined.excludedTets, (std::vector<int>{0, 1}));
  EXPECT_TRUE(joined.surfaceTriangles == faces);
  EXPECT_EQ(joined.exampleSources, a.model.exampleSources);
}

TEST(ModelJoin, InputRowsInOrderAreLeftImplicitAndAVertexInNoPartIsAnError) {
  const ModelPart whole = part(3, 1, {0, 1, 2}, {0, 1, 2, 3}, 0.0);
  const Triangles face = (Triangles(1, 3) << 0, 1, 2).finished();
  EXPECT_TRUE(joinedModel({whole}, face, 3).inputVertexRows.empty());
  EXPECT_THROW(joinedModel({whole}, face, 4), InputError);
  ModelPart twoExamples = part(3, 0, {0, 1, 2}, {0, 1, 2, 0}, 0.0);
  twoExamples.model.examples.push_back(twoExamples.model.examples.front());
  EXPECT_THROW(joinedModel({whole, twoExamples}, face, 3), InputError);
}

}  // namespace
}  // namespace tetblend
