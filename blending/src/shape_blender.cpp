#include "tetblend/blending/shape_blender.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <chrono>
#include <exception>
#include <sstream>

#include "tetblend/blending/kaji_blend.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

ShapeBlender::ShapeBlender(const TetMesh& rest, const std::vector<Vertices>& examples,
                           const ShapeBlenderOptions& options)
    : ShapeBlender(rest, examples, options, nullptr) {}

ShapeBlender::ShapeBlender(const TetMesh& rest, const std::vector<Vertices>& examples,
                           const ShapeBlenderOptions& options, BlendCache* cache)
    : examples_(examples), options_(options) {
  if (examples_.empty()) throw InputError("shape blender: give at least one example");
  if (options_.methods.empty()) throw InputError("shape blender: options.methods is empty");
  for (size_t k = 0; k < examples_.size(); ++k) {
    if (examples_[k].rows() != rest.vertices.rows()) {
      std::ostringstream message;
      message << "example " << k + 1 << " has " << examples_[k].rows()
              << " vertices but the rest mesh has " << rest.vertices.rows()
              << ": the meshes must be compatible";
      throw InputError(message.str());
    }
  }
  build(rest, cache);
}

ShapeBlender::ShapeBlender(const TetMesh& rest, const std::vector<Vertices>& examples,
                           const ShapeBlenderOptions& options, BlendCache cache)
    : ShapeBlender(rest, examples, options, &cache) {}

void ShapeBlender::build(const TetMesh& rest, BlendCache* cache) {
  const bool cachedFactor =
      cache != nullptr && options_.stitch.backend == StitchBackend::kCholmodSupernodal;
  const bool cachedKaji =
      cache != nullptr && cache->kaji.rotationConsistency == options_.rotationConsistency;
  if (cachedKaji && (cache->kaji.tets != rest.tets.rows() ||
                     cache->kaji.examples != static_cast<int>(examples_.size()))) {
    throw InputError("stored kaji parameters: made for " + std::to_string(cache->kaji.tets) +
                     " tets and " + std::to_string(cache->kaji.examples) + " examples, not " +
                     std::to_string(rest.tets.rows()) + " and " + std::to_string(examples_.size()));
  }
  // The factorisation and the parametrisations are independent: they run
  // side by side (on a cold start of a large model each is about half of the
  // work). Their errors are rethrown in a fixed order, the stitch's first
  // (it checks the rest tets), so a bad input always gets the same message.
  std::exception_ptr stitchError;
  std::exception_ptr methodError;
  std::map<BlendMethod, std::unique_ptr<TetMapBlender>> prepared;
  tbb::parallel_invoke(
      [&] {
        try {
          stitch_ = cachedFactor ? std::make_unique<StitchSolver>(rest, std::move(cache->factor))
                                 : std::make_unique<StitchSolver>(rest, options_.stitch);
        } catch (...) {
          stitchError = std::current_exception();
        }
      },
      [&] {
        try {
          for (BlendMethod method : options_.methods) {
            if (prepared.count(method) > 0) continue;
            prepared[method] = method == BlendMethod::kKaji && cachedKaji
                                   ? kajiBlenderFromData(std::move(cache->kaji))
                                   : parametrise(rest, method);
          }
        } catch (...) {
          methodError = std::current_exception();
        }
      });
  if (stitchError) std::rethrow_exception(stitchError);
  if (methodError) std::rethrow_exception(methodError);
  blenders_ = std::move(prepared);
  restCentroids_ = stitch_->componentCentroids(rest.vertices);
  for (const Vertices& example : examples_) {
    exampleCentroids_.push_back(stitch_->componentCentroids(example));
  }
}

ShapeBlender::~ShapeBlender() = default;
ShapeBlender::ShapeBlender(ShapeBlender&&) noexcept = default;
ShapeBlender& ShapeBlender::operator=(ShapeBlender&&) noexcept = default;

void ShapeBlender::prepare(BlendMethod method) {
  if (!isPrepared(method)) blenders_[method] = parametrise(stitch_->rest(), method);
}

std::unique_ptr<TetMapBlender> ShapeBlender::parametrise(const TetMesh& rest,
                                                         BlendMethod method) const {
  if (method == BlendMethod::kVertexLinear) return nullptr;
  // The rest data, gradient fields and adjacency are only needed while
  // preparing.
  const RestTetData restData = restTetData(rest);
  std::vector<std::vector<Eigen::Matrix3d>> gradients;
  for (size_t k = 0; k < examples_.size(); ++k) {
    gradients.push_back(deformationGradients(rest, restData, examples_[k], static_cast<int>(k)));
  }
  const TetAdjacency adjacency = buildTetAdjacency(rest.tets);
  const TetComponents components = tetComponents(adjacency);
  BlendInput input;
  input.rest = &rest;
  input.restData = &restData;
  input.examples = &examples_;
  input.gradients = &gradients;
  input.adjacency = &adjacency;
  input.components = &components;
  input.rotationConsistency = options_.rotationConsistency;
  return prepareTetMapBlender(method, input);
}

bool ShapeBlender::isPrepared(BlendMethod method) const { return blenders_.count(method) > 0; }

BlendCache ShapeBlender::exportCache() const {
  const auto kaji = blenders_.find(BlendMethod::kKaji);
  if (kaji == blenders_.end()) {
    throw InputError("shape blender: the cache holds the kaji parameters; prepare 'kaji' first");
  }
  return {stitch_->factorData(), kajiParameterData(*kaji->second)};
}

BlendResult ShapeBlender::blend(const std::vector<double>& weights) const {
  return blend(weights, options_.methods.front());
}

BlendResult ShapeBlender::blend(const std::vector<double>& weights, BlendMethod method) const {
  BlendResult result;
  blendInto(weights, method, result);
  return result;
}

Centroids ShapeBlender::blendedCentroids(const std::vector<double>& weights) const {
  checkWeights(weights, exampleCount());
  double restWeight = 1.0;
  for (double w : weights) restWeight -= w;
  Centroids centroids = restWeight * restCentroids_;
  for (int k = 0; k < exampleCount(); ++k) centroids += weights[k] * exampleCentroids_[k];
  return centroids;
}

void ShapeBlender::blendInto(const std::vector<double>& weights, BlendMethod method,
                             BlendResult& result) const {
  checkWeights(weights, exampleCount());
  const auto found = blenders_.find(method);
  if (found == blenders_.end()) {
    throw InputError("shape blender: method '" + blendMethodName(method) +
                     "' was not prepared: add it to ShapeBlenderOptions::methods or call "
                     "prepare()");
  }
  result.method = method;
  result.timings = BlendTimings{};
  auto start = Clock::now();
  if (method == BlendMethod::kVertexLinear) {
    double restWeight = 1.0;
    for (double w : weights) restWeight -= w;
    const Vertices& restVertices = stitch_->rest().vertices;
    const auto rows = restVertices.rows();
    result.vertices.resize(rows, 3);
    result.targets.clear();
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, rows, 4096),
                      [&](const tbb::blocked_range<Eigen::Index>& range) {
                        for (Eigen::Index v = range.begin(); v != range.end(); ++v) {
                          Eigen::RowVector3d sum = restWeight * restVertices.row(v);
                          for (int k = 0; k < exampleCount(); ++k) {
                            sum += weights[k] * examples_[k].row(v);
                          }
                          result.vertices.row(v) = sum;
                        }
                      });
    result.timings.blendSeconds = secondsSince(start);
    return;
  }
  const TetMapBlender& blender = *found->second;
  StitchTimings stitchTimings;
  StitchWorkspace workspace;
  const Centroids centroids = blendedCentroids(weights);
  if (options_.keepTargets || options_.nonlinearStitch) {
    blender.blendTargets(weights, result.targets);
    result.timings.blendSeconds = secondsSince(start);
    stitch_->solveInto(result.targets, centroids, result.vertices, workspace, &stitchTimings);
  } else {
    // Fused: each chunk of maps goes into the right-hand side as it is
    // blended (the chunks of blendTargets, so the same vertices bit for bit).
    std::vector<Eigen::Matrix3d>().swap(result.targets);
    stitch_->solveInto([&](int begin, int end,
                           Eigen::Matrix3d* out) { blender.blendRange(weights, begin, end, out); },
                       centroids, result.vertices, workspace, &stitchTimings);
    result.timings.blendSeconds = stitchTimings.targetSeconds;
  }
  result.timings.rhsSeconds = stitchTimings.rhsSeconds;
  result.timings.solveSeconds = stitchTimings.solveSeconds;
  result.nonlinear = NonlinearStitchReport{};
  if (options_.nonlinearStitch) {
    start = Clock::now();
    result.vertices = nonlinearStitch(*stitch_, result.targets, result.vertices, centroids,
                                      options_.nonlinear, &result.nonlinear);
    result.timings.nonlinearSeconds = secondsSince(start);
  }
}

int ShapeBlender::exampleCount() const { return static_cast<int>(examples_.size()); }
const TetMesh& ShapeBlender::rest() const { return stitch_->rest(); }
const StitchSolver& ShapeBlender::stitch() const { return *stitch_; }
const ShapeBlenderOptions& ShapeBlender::options() const { return options_; }

BlendResult blendShapes(const TetMesh& rest, const std::vector<Vertices>& examples,
                        const std::vector<double>& weights, const ShapeBlenderOptions& options) {
  ShapeBlenderOptions single = options;
  if (!single.methods.empty()) single.methods.resize(1);
  return ShapeBlender(rest, examples, single).blend(weights);
}

}  // namespace tetblend
