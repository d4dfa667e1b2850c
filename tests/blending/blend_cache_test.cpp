// A blender started from a blend cache (blend_cache.h): the stored factor and
// kaji parameters give the exporting blender's blends bit for bit, a cache
// made with other options is used only where it fits, and inconsistent data
// is refused before it is used.

#include <gtest/gtest.h>

#include "blending_test_support.h"
#include "tetblend/blending/shape_blender.h"
#include "tetblend/core/constants.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/procedural_shapes.h"

namespace tetblend {
namespace {

using Fixture = testing::BarExamples;

// The bar twisted by 4 pi (the rotation lifts need corrections where the
// twist passes whole turns) and bent.
Fixture twistedBar() { return testing::twistedAndBentBar(24, 4.0 * kPi); }

ShapeBlenderOptions optionsFor(std::vector<BlendMethod> methods, bool consistency = true) {
  ShapeBlenderOptions options;
  options.methods = std::move(methods);
  options.rotationConsistency = consistency;
  return options;
}

const std::vector<std::vector<double>>& someWeights() {
  static const std::vector<std::vector<double>> weights = {
      {0.0, 0.0}, {1.0, 0.0}, {0.5, 0.25}, {-0.3, 1.2}};
  return weights;
}

TEST(BlendCache, ABlenderFromTheCacheBlendsBitForBitAsTheOneThatMadeIt) {
  const Fixture f = twistedBar();
  const auto options = optionsFor({BlendMethod::kKaji, BlendMethod::kDualQuaternion});
  const ShapeBlender made(f.rest, f.examples, options);
  const BlendCache cache = made.exportCache();
  ASSERT_FALSE(cache.kaji.correctedTets.empty()) << "the 4 pi twist should need lift corrections";
  const ShapeBlender loaded(f.rest, f.examples, options, cache);
  for (const auto& w : someWeights()) {
    for (BlendMethod method : options.methods) {
      EXPECT_TRUE(made.blend(w, method).vertices == loaded.blend(w, method).vertices)
          << blendMethodName(method) << " at " << w[0] << ", " << w[1];
    }
  }
  // The stored values are what it blends with: changed ones change the blend.
  const std::vector<double> one{1.0, 0.0};
  BlendCache zeroParameters = cache;
  std::fill(zeroParameters.kaji.params.begin(), zeroParameters.kaji.params.end(), 0.0);
  EXPECT_FALSE(ShapeBlender(f.rest, f.examples, options, zeroParameters).blend(one).vertices ==
               made.blend(one).vertices);
  BlendCache scaledFactor = cache;
  for (double& v : scaledFactor.factor.values) v *= 2.0;
  EXPECT_FALSE(ShapeBlender(f.rest, f.examples, options, scaledFactor).blend(one).vertices ==
               made.blend(one).vertices);

  const BlendCache again = loaded.exportCache();
  EXPECT_EQ(again.factor.values, cache.factor.values);
  EXPECT_EQ(again.factor.perm, cache.factor.perm);
  EXPECT_EQ(again.kaji.params, cache.kaji.params);
  EXPECT_EQ(again.kaji.corrections, cache.kaji.corrections);
}

TEST(BlendCache, KajiParametersMadeWithAnotherConsistencyAreRecomputed) {
  const Fixture f = twistedBar();
  const BlendCache cache =
      ShapeBlender(f.rest, f.examples, optionsFor({BlendMethod::kKaji})).exportCache();
  const auto principal = optionsFor({BlendMethod::kKaji}, false);
  const ShapeBlender fresh(f.rest, f.examples, principal);
  const ShapeBlender loaded(f.rest, f.examples, principal, cache);
  EXPECT_FALSE(loaded.exportCache().kaji.rotationConsistency);
  for (const auto& w : someWeights()) {
    EXPECT_TRUE(fresh.blend(w).vertices == loaded.blend(w).vertices) << w[0] << ", " << w[1];
  }
}

TEST(BlendCache, ExportNeedsTheKajiMethod) {
  const Fixture f = twistedBar();
  const ShapeBlender dq(f.rest, f.examples, optionsFor({BlendMethod::kDualQuaternion}));
  EXPECT_THROW(dq.exportCache(), InputError);
}

// Each damage is one a corrupt or foreign file could carry; all are refused
// with an InputError naming what is wrong, before anything is solved.
TEST(BlendCache, InconsistentDataIsRefused) {
  const Fixture f = twistedBar();
  const auto options = optionsFor({BlendMethod::kKaji});
  const BlendCache good = ShapeBlender(f.rest, f.examples, options).exportCache();
  ASSERT_GT(good.factor.rows.size(), 1u);
  const auto refused = [&](BlendCache cache, const std::string& expected) {
    try {
      ShapeBlender(f.rest, f.examples, options, std::move(cache));
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
      return;
    }
    ADD_FAILURE() << "accepted, expected: " << expected;
  };
  BlendCache c = good;
  c.factor.perm[1] = c.factor.perm[0];
  refused(c, "permutation repeats");
  c = good;
  c.factor.perm.pop_back();
  refused(c, "permutation has");
  c = good;
  c.factor.super.back() += 1;
  refused(c, "do not cover");
  c = good;
  c.factor.rows[0] = static_cast<int>(c.factor.perm.size());
  refused(c, "out of order or range");
  c = good;
  c.factor.values.pop_back();
  refused(c, "value count");
  c = good;
  c.factor.valueStart[1] += 1;
  refused(c, "wrong number of values");
  c = good;
  c.kaji.params.pop_back();
  refused(c, "values for");
  c = good;
  c.kaji.correctedTets.back() = c.kaji.tets;
  refused(c, "out of range or order");
  c = good;
  c.kaji.correctionExample[0] = c.kaji.examples;
  refused(c, "names example");
  c = good;
  c.kaji.tets += 1;
  refused(c, "made for");
}

}  // namespace
}  // namespace tetblend
