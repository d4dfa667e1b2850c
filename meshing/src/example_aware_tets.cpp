#include "tetblend/meshing/example_aware_tets.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <utility>

#include <tbb/collaborative_call_once.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "example_concurrency.h"
#include "half_edge_table.h"
#include "hidden_parts.h"
#include "interior_ordering.h"
#include "inverted_tet_splits.h"
#include "rigid_simplices_outside.h"
#include "tet_stellar_split.h"
#include "tetblend/core/blas_threads.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"
#include "tetblend/meshing/collapsed_faces.h"
#include "tetblend/meshing/self_intersection.h"
#include "tetblend/meshing/tet_boundary.h"

namespace tetblend {
namespace {

// Stage 3 rounds in a row without fewer inverted tets of an example before
// its refinement gives up. Rounds past the best are undone, so more patience
// costs time only where an example would otherwise keep inverted tets: over
// the README's sets of The untangler (2026-12-02), 4 instead of 2 repaired
// the homer's frame 8 at 100° (1 tet) in its 3rd and 4th rounds, changed no
// other model, and took the homer's 48 frames from 28.9, 28.3 s to 34.2,
// 32.7 s (paired runs).
constexpr int kPatience = 4;

// Stage 3 refines while the rest mesh has at most this many times the tets
// it had after stage 1. Each round splits the inverted tets of one example
// and their neighbours, and with them the inverted tets of the examples
// still waiting, so the mesh can grow geometrically over rounds where an
// example cannot be repaired. Without the bound, a mirrored bar (every tet
// must invert; example_aware_tets_test) ran for over 12 minutes, past 1 GB,
// before it was stopped, and the lion's 48 gallop frames, with the untangler
// allowed 500 rounds instead of 150, reached 277 k inverted tets of one
// frame (3 GB, stopped after 20 minutes). Stage 3 needs room, though: the
// hard-pose corpus's knot1 grew from TetGen's 10 k tets to 24 k, and with a
// bound of 2 its 1080° twist kept 371 inverted tets; on the prepare sets of
// The untangler (README) meshes grew by at most 38 %.
constexpr double kMaxStage3Growth = 4.0;

template <typename T>
void sortUnique(std::vector<T>& values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
}

// What to split to free the tets `bad` of `mesh` (simplicesToSplit), edges
// first, each once.
std::vector<Simplex> simplicesFreeing(const TetMesh& mesh, const std::vector<int>& bad,
                                      int surfaceCount, const BoundarySimplices& boundary) {
  std::vector<Simplex> simplices;
  for (int t : bad) {
    for (const Simplex& simplex : simplicesToSplit(mesh, t, surfaceCount, boundary)) {
      simplices.push_back(simplex);
    }
  }
  std::sort(simplices.begin(), simplices.end());
  simplices.erase(std::unique(simplices.begin(), simplices.end()), simplices.end());
  return simplices;
}

// `positions` (one row per vertex before the split) extended by the centroid
// of each split simplex, in the order splitSimplices appends them.
Vertices extendedPositions(const Vertices& positions, const std::vector<Simplex>& simplices) {
  Vertices result(positions.rows() + static_cast<Eigen::Index>(simplices.size()), 3);
  result.topRows(positions.rows()) = positions;
  for (std::size_t i = 0; i < simplices.size(); ++i) {
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (int j = 0; j < simplices[i].count; ++j) {
      centroid += positions.row(simplices[i].vertices[static_cast<std::size_t>(j)]);
    }
    result.row(positions.rows() + static_cast<Eigen::Index>(i)) = centroid / simplices[i].count;
  }
  return result;
}

// The positions in `simplices` of those whose new vertex (index
// firstNew + position, splitSimplices' order) lies in a tet of `refined`
// whose signed volume is not positive in floating point. Only tets with a
// new vertex changed; the others keep their positive volume.
std::vector<std::size_t> splitsLeavingFlatTets(const TetMesh& refined, Eigen::Index firstNew) {
  std::vector<std::size_t> flat;
  for (Eigen::Index t = 0; t < refined.tets.rows(); ++t) {
    if (refined.tets.row(t).maxCoeff() < firstNew ||
        tetSignedVolume(refined.vertices, refined.tets.row(t)) > 0.0) {
      continue;
    }
    for (int c = 0; c < 4; ++c) {
      if (refined.tets(t, c) >= firstNew) {
        flat.push_back(static_cast<std::size_t>(refined.tets(t, c) - firstNew));
      }
    }
  }
  return flat;
}

// Splits `simplices` in the rest mesh and extends every placed example;
// false, changing nothing, when none could be split or the refined mesh
// would have more than maxTets tets. A split halves a tet's volume exactly
// only in exact arithmetic: a sliver of the rest (a triangle of nearly zero
// area and its tet) can round to a child of volume 0 or below, which no
// later step accepts (a 16-frame elephant with such triangles was refused),
// so the simplices whose split does that are left out, and the rest split.
bool split(std::vector<Simplex> simplices, CompatibleTetMeshes& meshes,
           Eigen::Index maxTets = std::numeric_limits<Eigen::Index>::max()) {
  const Eigen::Index firstNew = meshes.rest.vertices.rows();
  TetMesh refined = splitSimplices(meshes.rest, simplices);
  for (std::vector<std::size_t> flat = splitsLeavingFlatTets(refined, firstNew); !flat.empty();
       flat = splitsLeavingFlatTets(refined, firstNew)) {
    sortUnique(flat);
    for (auto i = flat.rbegin(); i != flat.rend(); ++i) {
      simplices.erase(simplices.begin() + static_cast<std::ptrdiff_t>(*i));
    }
    if (simplices.empty()) return false;
    refined = splitSimplices(meshes.rest, simplices);
  }
  if (refined.tets.rows() > maxTets) return false;
  meshes.rest = std::move(refined);
  for (CompatibleTetResult& example : meshes.examples) {
    example.vertices = extendedPositions(example.vertices, simplices);
  }
  meshes.steinerPoints += static_cast<int>(simplices.size());
  ++meshes.rounds;
  return true;
}

// Per vertex of `mesh`, its tet component (tets linked through shared
// vertices), numbered 0, 1, ... by first vertex. Components meshed each on
// their own (component_meshing.h) may overlap: each bounds a solid of its
// own, and only the faces of one component must not intersect.
std::vector<int> vertexComponents(const TetMesh& mesh) {
  detail::UnionFind sets(static_cast<std::size_t>(mesh.vertices.rows()));
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    for (int c = 1; c < 4; ++c) {
      sets.unite(static_cast<std::size_t>(mesh.tets(t, 0)),
                 static_cast<std::size_t>(mesh.tets(t, c)));
    }
  }
  std::vector<int> label(static_cast<std::size_t>(mesh.vertices.rows()), -1);
  std::vector<int> rootLabel(label.size(), -1);
  int count = 0;
  for (std::size_t v = 0; v < label.size(); ++v) {
    int& root = rootLabel[sets.find(v)];
    if (root < 0) root = count++;
    label[v] = root;
  }
  return label;
}

// Per face of `triangles`, the component of its first corner.
std::vector<int> faceComponents(const Triangles& triangles,
                                const std::vector<int>& vertexComponent) {
  std::vector<int> group(static_cast<std::size_t>(triangles.rows()));
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    group[static_cast<std::size_t>(f)] = vertexComponent[static_cast<std::size_t>(triangles(f, 0))];
  }
  return group;
}

// How hard to untangle an example: the whole interior if it can be embedded,
// briefly and locally if its surface intersects itself or collapses faces
// (it cannot be valid there).
const UntangleEffort& effortFor(bool embeddable, const ExampleAwareOptions& options) {
  return embeddable ? options.placement.untangleEffort : options.intersectingUntangle;
}

// `effort` measuring distortion against thickened slivers: a clean example's
// last attempt (UntangleEffort::thickenedReference). Rest slivers (volume
// 1e-6 of a regular tet's on CGAL's triceratops) made det F in a frame
// about −1000. 48 gallop-like frames (40°), clean frames keeping inverted
// tets, without it and with it: triceratops 9 and 2, lion 4 and 3 (the
// triceratops' slivers sat on two caps, which degenerate_faces.h now
// re-splits for meshing, so it keeps none either way). Thickening in every attempt
// instead of the last also gave 2, but left CGAL's dino 3 tets in its 720°
// twist; every clean example's attempts thickened after the usual ones
// gave 2 too, but CGAL's lion's gallop frames took 961 s instead of 118 s
// and 12 kept tets instead of 4.
UntangleEffort thickenedEffort(const UntangleEffort& effort) {
  UntangleEffort result = effort;
  result.thickenedReference = true;
  return result;
}

// Untangles `example` (placed on `builder`'s mesh, or extended to it by
// splits) with `effort`, keeping the counts of its placement.
void untangleAgain(const CompatibleTetBuilder& builder, const UntangleEffort& effort,
                   CompatibleTetResult& example) {
  CompatibleTetResult repaired = builder.repair(example.vertices, effort);
  repaired.harmonicInvertedCount = example.harmonicInvertedCount;
  repaired.arapIterations = example.arapIterations;
  repaired.untangleRounds += example.untangleRounds;
  example = std::move(repaired);
}

// Untangles `example`, extended by splits to `builder`'s mesh, with
// `effort`; if tets stay inverted, also places `surface` afresh on that mesh
// and untangles the placement, and keeps whichever leaves fewer inverted
// tets. A split puts its new vertex at the centroid of the example's
// (inverted) simplex, inside the tangle it should resolve, while a fresh
// placement starts from the finer mesh's harmonic and ARAP maps. On the
// README's sets of The untangler (2026-12-02) this left the open lion's
// frame 14 with 1 inverted tet instead of 11 and the 3-holes femur's frame 4
// with none instead of 2, and doubled the open lion's time (16 → 32-35 s,
// four fresh placements on 39 k tets).
void untangleRefined(const CompatibleTetBuilder& builder, const Vertices& surface,
                     const UntangleEffort& effort, CompatibleTetResult& example) {
  untangleAgain(builder, effort, example);
  if (example.invertedTets.empty()) return;
  CompatibleTetResult fresh = builder.place(surface);
  if (!fresh.invertedTets.empty()) untangleAgain(builder, effort, fresh);
  if (fresh.invertedTets.size() < example.invertedTets.size()) example = std::move(fresh);
}

// Measures `example` again on `builder`'s mesh, keeping its counts.
void evaluateAgain(const CompatibleTetBuilder& builder, CompatibleTetResult& example) {
  CompatibleTetResult measured = builder.evaluate(example.vertices);
  measured.harmonicInvertedCount = example.harmonicInvertedCount;
  measured.arapIterations = example.arapIterations;
  measured.untangleRounds = example.untangleRounds;
  example = std::move(measured);
}

}  // namespace

std::vector<int> invertedAllSurfaceTets(const Tets& tets, int surfaceVertexCount,
                                        const Vertices& positions) {
  std::vector<int> result;
  for (Eigen::Index t = 0; t < tets.rows(); ++t) {
    if (tets.row(t).maxCoeff() >= surfaceVertexCount) continue;
    if (!(tetSignedVolume(positions, tets.row(t)) > 0.0)) result.push_back(static_cast<int>(t));
  }
  return result;
}

CompatibleTetMeshes buildCompatibleTetMeshes(const TetMesh& rest, int surfaceVertexCount,
                                             const std::vector<Vertices>& exampleSurfaces,
                                             const ExampleAwareOptions& options,
                                             const MeshingProgress& progress) {
  for (const Vertices& example : exampleSurfaces) {
    if (example.rows() != surfaceVertexCount || !example.allFinite()) {
      throw InputError("buildCompatibleTetMeshes: an example surface has " +
                       std::to_string(example.rows()) + " vertices (need " +
                       std::to_string(surfaceVertexCount) + ", all finite)");
    }
  }
  // Examples are placed one per core: OpenBLAS's thread team would only
  // spin beside them (blas_threads.h).
  const SerialBlas serialBlas;
  std::mutex progressMutex;  // examples may be placed on several threads
  auto report = [&](const char* stage) {
    if (!progress) return;
    const std::lock_guard<std::mutex> lock(progressMutex);
    progress(stage);
  };
  // METIS orders the interior while the examples are checked and the mesh
  // refined (interior_ordering.h): on bench_meshing's 1 M-tet bar it takes
  // as long as the interior's factorisation.
  const std::shared_future<InteriorOrder> interiorOrder = metisInteriorOrderInBackground(
      rest.tets, surfaceVertexCount, static_cast<int>(rest.vertices.rows()));
  CompatibleTetMeshes meshes;
  meshes.rest = rest;
  const Triangles triangles = surfaceFirstBoundary(rest.tets, surfaceVertexCount);
  const BoundarySimplices boundary = boundarySimplices(triangles);
  const std::vector<int> vertexComponent = vertexComponents(rest);
  const std::vector<int> faceComponent = faceComponents(triangles, vertexComponent);
  meshes.selfIntersections.resize(exampleSurfaces.size());
  meshes.collapsedFaces.resize(exampleSurfaces.size());
  const Vertices restSurface = rest.vertices.topRows(surfaceVertexCount);
  // The surfaces placed: the examples', with the parts they hide replaced
  // by stand-ins (hiddenPartsStandIn).
  std::vector<Vertices> surfaces = exampleSurfaces;
  // Examples whose placed surface neither intersects itself nor collapses a
  // face: every tet can be valid there. Before collapsed faces were told
  // apart, CGAL's homer beside an armadillo scaled to a point took 837 s and
  // 1.7 GB to prepare (the part untangled over the whole interior, then
  // refined up to the growth bound).
  std::vector<char> embeddable(exampleSurfaces.size());
  std::vector<char> standIn(exampleSurfaces.size(), 0);  // surfaces[k] differs from the example's
  // Stage 1 begins in the same tasks: the rigid edges and faces (made by
  // the first task that needs them) that leave an embeddable example's
  // solid. One task per example, so that an example's rigid tests need not
  // wait for the other examples' checks: bench_meshing's 10 k row checked
  // three examples on two threads in 8-9 ms, then tested two examples' rigid
  // simplices in 5-6 ms.
  // While METIS orders a large interior on a thread of its own, these run
  // on one thread: METIS comes first on the way to the factorisation, and
  // three threads on two cores slowed it. bench_meshing's 1 M row, four
  // interleaved runs each, two threads → one: METIS done after 1.58-1.74 →
  // 1.39-1.51 s, the factorisation after it 1.90-2.15 → 1.62-1.83 s (not
  // explained), embedding 5.27-5.59 → 4.71-5.03 s; the checks and stage 1
  // took 0.33-0.41 s either way.
  tbb::task_arena checking(interiorOrder.valid() ? 1 : tbb::task_arena::automatic);
  checking.execute([&] {
    tbb::collaborative_once_flag rigidOnce;
    std::vector<Simplex> rigid;
    std::vector<std::vector<Simplex>> outsideOf(exampleSurfaces.size());
    tbb::parallel_for(std::size_t{0}, exampleSurfaces.size(), [&](std::size_t k) {
      meshes.selfIntersections[k] =
          findSelfIntersections(exampleSurfaces[k], triangles, 1, faceComponent);
      const std::vector<int> collapsed = collapsedFaces(restSurface, exampleSurfaces[k], triangles);
      meshes.collapsedFaces[k] = collapsed.size();
      if (!collapsed.empty()) {
        surfaces[k] = hiddenPartsStandIn(restSurface, exampleSurfaces[k], triangles, faceComponent,
                                         collapsed);
        standIn[k] = !(surfaces[k] == exampleSurfaces[k]);
      }
      embeddable[k] =
          meshes.selfIntersections[k].pairCount == 0 &&
          (collapsed.empty() || collapsedFaces(restSurface, surfaces[k], triangles).empty());
      if (!embeddable[k] || options.maxRounds <= 0) return;
      tbb::collaborative_call_once(
          rigidOnce, [&] { rigid = rigidSimplices(meshes.rest, surfaceVertexCount, boundary); });
      outsideOf[k] =
          rigidSimplicesOutside(rigid, surfaces[k], triangles, vertexComponent, faceComponent);
    });
    std::vector<Simplex> outside;
    for (const std::vector<Simplex>& list : outsideOf) {
      outside.insert(outside.end(), list.begin(), list.end());
    }
    sortUnique(outside);
    if (!outside.empty()) {
      meshes.rigidSimplicesOutside = static_cast<int>(outside.size());
      if (split(outside, meshes)) report("refine");
    }
  });
  // Then all-surface tets an example inverts (no placement can help either).
  for (int round = 0; round < options.maxRounds; ++round) {
    std::vector<int> bad;
    for (const Vertices& example : surfaces) {
      const std::vector<int> inverted =
          invertedAllSurfaceTets(meshes.rest.tets, surfaceVertexCount, example);
      bad.insert(bad.end(), inverted.begin(), inverted.end());
    }
    sortUnique(bad);
    const std::vector<Simplex> simplices =
        simplicesFreeing(meshes.rest, bad, surfaceVertexCount, boundary);
    if (simplices.empty()) break;
    if (!split(simplices, meshes)) break;
    meshes.allSurfaceTetsInverted += static_cast<int>(bad.size());
    report("refine");
  }

  // Stage 2: place every example, several at once (concurrentExamples), those
  // that cannot be embedded first: their placement always takes ARAP and
  // untangling, where an embeddable example's harmonic map may already be
  // valid (bench_meshing's 10 k row started its self-intersecting elbow
  // 6.5 ms late, after a clean example, and finished last).
  CompatibleTetOptions placement = options.placement;
  placement.untangle = false;
  const CompatibleTetBuilder builder(meshes.rest, surfaceVertexCount, placement, interiorOrder);
  const std::size_t exampleCount = exampleSurfaces.size();
  meshes.examples.resize(exampleCount);
  std::vector<std::size_t> placingOrder(exampleCount);
  std::iota(placingOrder.begin(), placingOrder.end(), std::size_t{0});
  std::stable_partition(placingOrder.begin(), placingOrder.end(),
                        [&](std::size_t k) { return !embeddable[k]; });
  auto placeExample = [&](std::size_t k) {
    meshes.examples[k] = embeddable[k]
                             ? builder.place(surfaces[k], options.placement.arapIterations)
                             : builder.place(surfaces[k], options.intersectingArapIterations,
                                             options.intersectingArapRings);
  };
  auto untangleExample = [&](std::size_t k) {
    if (options.placement.untangle && !meshes.examples[k].invertedTets.empty()) {
      untangleAgain(builder, effortFor(embeddable[k], options), meshes.examples[k]);
    }
  };
  // The interior is factored first, alone: a thread waiting for the
  // factorisation beside it would take cycles from the factorisation's own.
  // Then each example is placed and untangled in one go, unless memory
  // allows fewer untanglings at once than placements: then all are placed
  // first, several at once, and untangled after. bench_meshing's 1 M row
  // placed its two clean examples (0.33 s, harmonic maps already valid)
  // after its self-intersecting elbow's untangling (0.7-1.3 s), and now
  // beside the elbow's placement: the time after the factorisation, 1.99,
  // 2.19, 2.23, 1.99 s before and 1.95, 1.77, 1.78, 2.07 s after
  // (interleaved runs, scratch timers; the factorisation itself took
  // 1.8-2.7 s either way).
  if (exampleCount > 0) builder.factor();
  const Eigen::Index tets = meshes.rest.tets.rows();
  const std::size_t placing = concurrentExamples(tets, exampleCount, kHarmonicArapBytesPerTet);
  const std::size_t untangling = concurrentExamples(tets, exampleCount);
  if (untangling >= placing) {
    forEachExample(exampleCount, untangling, [&](std::size_t i) {
      placeExample(placingOrder[i]);
      untangleExample(placingOrder[i]);
      report("place");
    });
  } else {
    forEachExample(exampleCount, placing, [&](std::size_t i) { placeExample(placingOrder[i]); });
    // The interior's factorisation is not needed to untangle: freed, its
    // memory serves the Newton factorisations that follow. bench_meshing's
    // 1 M row, two interleaved pairs (scratch timers, the same excluded
    // tets): peak 1029, 1033 -> 865, 864 MB; the elbow's first Newton
    // factorisation 339, 286 -> 194, 153 ms (fresh memory is slow to fault
    // in on this machine); its untangling phase, the release included,
    // 805, 789 -> 701, 635 ms.
    builder.releaseFactor();
    // Untangled one at a time, an example has the cores to itself: its
    // Newton factorisations may use OpenBLAS's thread team. bench_meshing's
    // 1 M row, four interleaved runs each (scratch timers, the same excluded
    // tets): the elbow's untangling 1134, 1148, 1187, 1048 → 1032, 980, 725,
    // 910 ms.
    std::optional<ParallelBlas> alone;
    if (untangling == 1) alone.emplace();
    forEachExample(exampleCount, untangling, [&](std::size_t i) {
      untangleExample(placingOrder[i]);
      report("place");
    });
  }

  // Stage 3: refine where embeddable examples stay inverted, untangle again, one
  // example at a time, the one with the fewest inverted tets first (a hopeless
  // example refined first would split the others' remaining inverted tets
  // too), each with its own budget of maxRounds rounds (a budget shared by
  // all examples was spent on the first few frames of an animation). A split
  // halves an inverted tet into two that may both stay inverted, so a round
  // may count more before the next one counts fewer: an example's rounds stop
  // after kPatience rounds without a new best, and its best state is kept.
  // Valid placements stay valid through every split.
  // A round splits around the inverted tets and their neighbours
  // (inverted_tet_splits.h).
  // The splits made for one example also split the other examples' inverted
  // tets, each into more inverted tets (a self-intersecting frame's 19 grew
  // to 6336 while the dino's clean frames were refined): an example is
  // untangled again on the refined mesh before its own rounds, and at the
  // end, when it has more inverted tets than after its last untangling
  // (untangledCount; a split never lowers the count, so more means its
  // inverted tets were split). The other examples are measured on the
  // refined mesh only when their turn comes and at the end, not after every
  // round (#examples × #rounds passes over all tets: 2 s of the dino's 91 s
  // with frame 5 as the rest, more on large meshes): measuredOn[k] is the
  // tet count of the mesh example k was last measured on (splits only add
  // tets, so a count names one mesh).
  std::vector<std::size_t> untangledCount;
  for (const CompatibleTetResult& example : meshes.examples) {
    untangledCount.push_back(example.invertedTets.size());
  }
  std::vector<Eigen::Index> measuredOn(exampleSurfaces.size(), meshes.rest.tets.rows());
  auto splitSinceUntangled = [&](std::size_t k) {
    return meshes.examples[k].invertedTets.size() > untangledCount[k];
  };
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < exampleSurfaces.size(); ++k) {
    if (embeddable[k] && !meshes.examples[k].invertedTets.empty()) {
      order.push_back(k);
    }
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return meshes.examples[a].invertedTets.size() < meshes.examples[b].invertedTets.size();
  });
  if (!options.placement.untangle) order.clear();
  const auto maxTets =
      static_cast<Eigen::Index>(kMaxStage3Growth * static_cast<double>(meshes.rest.tets.rows()));
  for (std::size_t k : order) {
    if (measuredOn[k] != meshes.rest.tets.rows()) {
      const CompatibleTetBuilder current(meshes.rest, surfaceVertexCount, placement, interiorOrder);
      evaluateAgain(current, meshes.examples[k]);
      measuredOn[k] = meshes.rest.tets.rows();
      if (splitSinceUntangled(k)) {
        untangleAgain(current, options.placement.untangleEffort, meshes.examples[k]);
        untangledCount[k] = meshes.examples[k].invertedTets.size();
      }
    }
    int rounds = 0;
    std::size_t best = meshes.examples[k].invertedTets.size();
    CompatibleTetMeshes bestMeshes;
    int sinceBest = 0;
    while (best > 0 && sinceBest < kPatience && rounds < options.maxRounds) {
      const std::vector<Simplex> simplices =
          splitsForInverted(meshes.rest, meshes.examples[k].invertedTets, surfaces[k], triangles,
                            surfaceVertexCount, boundary);
      if (simplices.empty()) break;
      if (sinceBest == 0) bestMeshes = meshes;
      if (!split(simplices, meshes, maxTets)) break;
      ++rounds;
      const CompatibleTetBuilder refined(meshes.rest, surfaceVertexCount, placement, interiorOrder);
      untangleRefined(refined, surfaces[k], options.placement.untangleEffort, meshes.examples[k]);
      untangledCount[k] = meshes.examples[k].invertedTets.size();
      measuredOn[k] = meshes.rest.tets.rows();
      report("refine");
      const std::size_t count = meshes.examples[k].invertedTets.size();
      if (count < best) {
        best = count;
        sinceBest = 0;
      } else {
        ++sinceBest;
      }
    }
    if (sinceBest > 0) {
      meshes = std::move(bestMeshes);
      untangledCount[k] = meshes.examples[k].invertedTets.size();  // untangled there
      measuredOn[k] = meshes.rest.tets.rows();
    }
  }
  // Last, examples not measured on the final mesh are, and untangled again
  // if their inverted tets were split; embeddable examples that still keep
  // inverted tets get one attempt against thickened slivers (thickenedEffort).
  auto embeddableAndInverted = [&](std::size_t k) {
    return options.placement.untangle && embeddable[k] && !meshes.examples[k].invertedTets.empty();
  };
  std::vector<std::size_t> pending;
  for (std::size_t k = 0; k < exampleCount; ++k) {
    if (measuredOn[k] != meshes.rest.tets.rows() || embeddableAndInverted(k)) pending.push_back(k);
  }
  if (!pending.empty()) {
    const UntangleEffort thickened = thickenedEffort(options.placement.untangleEffort);
    const CompatibleTetBuilder refined(meshes.rest, surfaceVertexCount, placement, interiorOrder);
    forEachExample(pending.size(), concurrentExamples(meshes.rest.tets.rows(), pending.size()),
                   [&](std::size_t i) {
                     const std::size_t k = pending[i];
                     CompatibleTetResult& example = meshes.examples[k];
                     if (measuredOn[k] != meshes.rest.tets.rows()) {
                       evaluateAgain(refined, example);
                       if (!example.invertedTets.empty() && options.placement.untangle &&
                           splitSinceUntangled(k)) {
                         untangleAgain(refined, effortFor(embeddable[k], options), example);
                       }
                     }
                     if (embeddableAndInverted(k)) untangleAgain(refined, thickened, example);
                   });
  }
  // Each example's own surface back where a stand-in of a hidden part was
  // placed: the part's tets, of no volume, are measured inverted.
  if (std::find(standIn.begin(), standIn.end(), 1) != standIn.end()) {
    const CompatibleTetBuilder last(meshes.rest, surfaceVertexCount, placement, interiorOrder);
    for (std::size_t k = 0; k < exampleCount; ++k) {
      if (!standIn[k]) continue;
      meshes.examples[k].vertices.topRows(surfaceVertexCount) = exampleSurfaces[k];
      evaluateAgain(last, meshes.examples[k]);
    }
  }
  return meshes;
}

}  // namespace tetblend
