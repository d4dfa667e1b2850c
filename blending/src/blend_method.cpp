#include "tetblend/blending/blend_method.h"

#include <cmath>
#include <sstream>

#include "blend_common.h"
#include "tetblend/blending/baseline_blend.h"
#include "tetblend/blending/dq_blend.h"
#include "tetblend/blending/kaji_blend.h"
#include "tetblend/blending/lie_bodies_blend.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

struct NamedMethod {
  BlendMethod method;
  const char* name;
};

constexpr NamedMethod kMethodNames[] = {
    {BlendMethod::kKaji, "kaji"},
    {BlendMethod::kKajiFrechet, "kaji-frechet"},
    {BlendMethod::kLieBodies, "liebodies"},
    {BlendMethod::kDualQuaternion, "dq"},
    {BlendMethod::kDib, "dib"},
    {BlendMethod::kAlexa, "alexa"},
    {BlendMethod::kPolarSlerp, "polar-slerp"},
    {BlendMethod::kLinear, "linear"},
    {BlendMethod::kVertexLinear, "vertex-linear"},
};

struct MethodAlias {
  const char* alias;
  const char* name;
};

constexpr MethodAlias kMethodAliases[] = {{"dqs", "dq"}};

}  // namespace

const std::vector<BlendMethod>& allBlendMethods() {
  static const std::vector<BlendMethod> methods = [] {
    std::vector<BlendMethod> all;
    for (const NamedMethod& named : kMethodNames) all.push_back(named.method);
    return all;
  }();
  return methods;
}

std::string blendMethodName(BlendMethod method) {
  for (const NamedMethod& named : kMethodNames) {
    if (named.method == method) return named.name;
  }
  throw InputError("unknown blend method value " + std::to_string(static_cast<int>(method)));
}

BlendMethod blendMethodFromName(const std::string& name) {
  const std::string canonical = canonicalMethodName(name);
  std::string valid;
  for (const NamedMethod& named : kMethodNames) {
    if (canonical == named.name) return named.method;
    valid += valid.empty() ? named.name : std::string(", ") + named.name;
  }
  throw InputError("unknown blend method '" + name + "': use one of " + valid + " (" +
                   methodAliasNote() + ")");
}

std::string canonicalMethodName(const std::string& name) {
  for (const MethodAlias& a : kMethodAliases) {
    if (name == a.alias) return a.name;
  }
  return name;
}

std::string methodAliasNote() {
  std::string note;
  for (const MethodAlias& a : kMethodAliases) {
    note += (note.empty() ? "" : ", ") + std::string(a.alias) + " = " + a.name;
  }
  return note;
}

bool usesRotationLogs(BlendMethod method) {
  return method == BlendMethod::kKaji || method == BlendMethod::kLieBodies;
}

void checkWeights(const std::vector<double>& weights, int exampleCount) {
  if (static_cast<int>(weights.size()) != exampleCount) {
    std::ostringstream message;
    message << "blend: " << weights.size() << " weights given for " << exampleCount
            << " examples: give one weight per example (the rest gets 1 - sum)";
    throw InputError(message.str());
  }
  for (size_t k = 0; k < weights.size(); ++k) {
    if (!std::isfinite(weights[k])) {
      std::ostringstream message;
      message << "blend: weight " << k << " is " << weights[k] << ": weights must be finite";
      throw InputError(message.str());
    }
  }
}

std::unique_ptr<TetMapBlender> prepareTetMapBlender(BlendMethod method, const BlendInput& input) {
  switch (method) {
    case BlendMethod::kLinear:
    case BlendMethod::kAlexa:
    case BlendMethod::kPolarSlerp:
      return prepareBaselineBlender(method, input);
    case BlendMethod::kKaji:
    case BlendMethod::kKajiFrechet:
      return prepareKajiBlender(method, input);
    case BlendMethod::kDualQuaternion:
    case BlendMethod::kDib:
      return prepareDualQuaternionBlender(method, input);
    case BlendMethod::kLieBodies:
      return prepareLieBodiesBlender(input);
    case BlendMethod::kVertexLinear:
      throw InputError("vertex-linear blends vertex positions and has no per-tet maps");
    default:
      break;
  }
  throw InputError("blend method '" + blendMethodName(method) + "' is not available in this build");
}

void TetMapBlender::blendRange(const std::vector<double>& weights, int begin, int end,
                               Eigen::Matrix3d* out) const {
  checkWeights(weights, exampleCount());
  if (begin < 0 || begin > end || end > tetCount()) {
    throw InputError("blend: tet range [" + std::to_string(begin) + ", " + std::to_string(end) +
                     ") is outside the " + std::to_string(tetCount()) + " tets");
  }
  blendChunk(weights, begin, end, out);
}

void TetMapBlender::blendTargets(const std::vector<double>& weights,
                                 std::vector<Eigen::Matrix3d>& targets) const {
  checkWeights(weights, exampleCount());
  targets.resize(tetCount());
  blend_detail::forEachTetChunk(tetCount(), [&](int begin, int end) {
    blendChunk(weights, begin, end, targets.data() + begin);
  });
}

namespace blend_detail {

InputSizes checkInput(const BlendInput& input) {
  if (input.rest == nullptr || input.restData == nullptr || input.examples == nullptr ||
      input.gradients == nullptr || input.adjacency == nullptr || input.components == nullptr) {
    throw InputError("blend: incomplete BlendInput (every pointer must be set)");
  }
  InputSizes sizes;
  sizes.tets = static_cast<int>(input.rest->tets.rows());
  sizes.examples = static_cast<int>(input.gradients->size());
  if (static_cast<int>(input.examples->size()) != sizes.examples) {
    throw InputError("blend: BlendInput has different example and gradient-field counts");
  }
  return sizes;
}

std::vector<Eigen::Matrix3d> tetMajorGradients(const BlendInput& input, const InputSizes& sizes) {
  std::vector<Eigen::Matrix3d> maps(static_cast<size_t>(sizes.tets) * sizes.examples);
  forEachTet(sizes.tets, [&](int j) {
    for (int k = 0; k < sizes.examples; ++k) {
      maps[static_cast<size_t>(j) * sizes.examples + k] = (*input.gradients)[k][j];
    }
  });
  return maps;
}

void rethrowForTet(const std::string& method, int example, int tet, const std::exception& error) {
  std::ostringstream message;
  message << method << ": ";
  if (example >= 0) {
    message << "example " << example + 1 << ", ";
  }
  message << "tet " << tet << ": " << error.what();
  throw DomainError(message.str());
}

}  // namespace blend_detail
}  // namespace tetblend
