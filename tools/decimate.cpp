// Decimates a closed triangle mesh to about N vertices (CGAL's edge
// collapse with Garland–Heckbert quadric costs and placements), for the
// low-poly rehearsals of `tetblend prepare` (issue 10: game characters of
// 255–351 vertices). Not part of the build; with Debian 12's packages:
//   g++ -O2 -std=c++17 -I/usr/include/eigen3 -DCGAL_EIGEN3_ENABLED \
//       tools/decimate.cpp -o /tmp/decimate -lgmp -lmpfr
//   /tmp/decimate IN.off OUT.off 300
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <iostream>
#include <string>

namespace SMS = CGAL::Surface_mesh_simplification;
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: decimate IN OUT VERTICES\n";
    return 2;
  }
  Mesh mesh;
  if (!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(argv[1], mesh)) {
    std::cerr << argv[1] << ": not a readable polygon mesh\n";
    return 1;
  }
  // A closed triangle mesh has about 3 edges per vertex.
  const std::size_t edges = 3 * std::stoul(argv[3]);
  SMS::GarlandHeckbert_plane_policies<Mesh, Kernel> quadrics(mesh);
  SMS::edge_collapse(
      mesh, SMS::Count_stop_predicate<Mesh>(edges),
      CGAL::parameters::get_cost(quadrics.get_cost()).get_placement(quadrics.get_placement()));
  mesh.collect_garbage();
  if (!CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17))) {
    std::cerr << argv[2] << ": cannot be written\n";
    return 1;
  }
  std::cout << argv[2] << ": " << mesh.number_of_vertices() << " vertices\n";
  return 0;
}
