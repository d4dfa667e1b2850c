#pragma once
// What a ShapeBlender computes once per model and can hand back to be stored:
// the stitch's supernodal Cholesky factor and the "kaji" parameters. A model
// that keeps them (`tetblend prepare --fast-load`) is blended without the
// fill-reducing ordering, the numeric factorisation, the polar
// decompositions and the rotation lifts: those are most of a one-shot blend
// of a large model (issue 13, cold start).
//
// Loaded data is checked for everything memory safety needs (sizes, index
// ranges, permutations); values are taken as stored, so the file holding
// them must be checksummed (model_file.h is).

#include <cstdint>
#include <vector>

namespace tetblend {

/// The stitch's factor L L^T = P A P^T as SupernodalFactor packs it: per
/// supernode s its columns [super[s], super[s + 1]), the rows of its
/// off-diagonal block rows[rowStart[s] .. rowStart[s + 1]) (ascending, all
/// below the supernode), and its values from values[valueStart[s]]: the lower
/// triangle of the diagonal block column by column, then the off-diagonal
/// block column-major. perm: row k of the permuted system is free unknown
/// perm[k].
struct StitchFactorData {
  std::vector<int> perm;
  std::vector<int> super;
  std::vector<int> rowStart;
  std::vector<int> rows;
  std::vector<std::int64_t> valueStart;
  std::vector<double> values;
};

/// The kaji blender's parameters (kaji_blend.h): per tet and example, tet
/// major, the rotation lift's base (3) and the upper triangle of the stretch
/// logarithm (6); the non-zero lift corrections of the tets in
/// correctedTets (ascending): for corrected tet i, entries
/// [correctionStart[i], correctionStart[i + 1]) of correctionExample (which
/// example) and of corrections (3 doubles each).
struct KajiParameterData {
  int tets = 0;
  int examples = 0;
  bool rotationConsistency = true;  ///< the option the lifts were made with
  std::vector<double> params;
  std::vector<int> correctedTets;
  std::vector<int> correctionStart;
  std::vector<int> correctionExample;
  std::vector<double> corrections;
};

/// Everything ShapeBlender can start from instead of computing it.
struct BlendCache {
  StitchFactorData factor;
  KajiParameterData kaji;
};

}  // namespace tetblend
