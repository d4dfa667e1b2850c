#include "tetblend/pipeline/handle_deformer.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tetblend/blending/blend_method.h"
#include "tetblend/core/dual_quaternion.h"
#include "tetblend/core/dual_quaternion_blend.h"
#include "tetblend/core/error.h"
#include "tetblend/core/tet_geometry.h"

namespace tetblend {

namespace {

using nlohmann::json;

// Relative offset delta / (bounding-box diagonal) of the distance weights.
constexpr double kDistanceOffset = 1e-3;

struct NamedHandleBlend {
  HandleBlend method;
  const char* name;
};

// The names of the command line; "dq" is also the blend method's name, and
// both take the same aliases (canonicalMethodName).
constexpr NamedHandleBlend kHandleBlendNames[] = {{HandleBlend::kLbs, "lbs"},
                                                  {HandleBlend::kDqs, "dq"},
                                                  {HandleBlend::kKaji, "kaji"},
                                                  {HandleBlend::kKajiFrechet, "kaji-frechet"}};

// A handle is rigid for dq when its log-stretch has Frobenius norm below this
// (dimensionless; ~1e-9 relative stretch, far above round-off of psi).
constexpr double kRigidStretchTolerance = 1e-9;

Eigen::Vector3d vector3(const json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw InputError(what + ": expected 3 numbers");
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

Handle parseHandle(const json& j, const std::string& where) {
  Handle h;
  h.name = j.value("name", where);
  if (j.contains("centre")) h.centre = vector3(j["centre"], where + ".centre");
  if (j.contains("matrix")) {
    const json& m = j["matrix"];
    if (!m.is_array() || m.size() != 4) throw InputError(where + ".matrix: expected 4 rows");
    Eigen::Matrix4d a;
    for (int r = 0; r < 4; ++r) {
      if (!m[r].is_array() || m[r].size() != 4)
        throw InputError(where + ".matrix: row " + std::to_string(r) + " needs 4 numbers");
      for (int c = 0; c < 4; ++c) a(r, c) = m[r][c].get<double>();
    }
    h.params = psi(a);
  } else {
    if (j.contains("translation")) h.params.translation = vector3(j["translation"], where);
    if (j.contains("rotation")) h.params.rotationLog = vector3(j["rotation"], where);
    if (j.contains("stretch_log")) {
      const json& y = j["stretch_log"];
      if (!y.is_array() || y.size() != 3) throw InputError(where + ".stretch_log: 3 rows");
      for (int r = 0; r < 3; ++r) h.params.stretchLog.row(r) = vector3(y[r], where).transpose();
      h.params.stretchLog = 0.5 * (h.params.stretchLog + h.params.stretchLog.transpose()).eval();
    }
  }
  return h;
}

}  // namespace

HandleBlend parseHandleBlend(const std::string& name) {
  const std::string canonical = canonicalMethodName(name);
  for (const NamedHandleBlend& named : kHandleBlendNames) {
    if (canonical == named.name) return named.method;
  }
  throw InputError("method: unknown deformer '" + name + "'; use " + handleBlendNames());
}

std::string handleBlendNames() {
  std::string names;
  for (const NamedHandleBlend& named : kHandleBlendNames) {
    names += (names.empty() ? "" : ", ") + std::string(named.name);
  }
  return names + " (" + methodAliasNote() + ")";
}

HandleSpec parseHandleSpec(const std::string& text, const std::string& what) {
  HandleSpec spec;
  try {
    const json j = json::parse(text);
    if (!j.contains("handles") || !j["handles"].is_array() || j["handles"].empty()) {
      throw InputError("needs a non-empty \"handles\" array");
    }
    for (std::size_t i = 0; i < j["handles"].size(); ++i)
      spec.handles.push_back(parseHandle(j["handles"][i], "handles[" + std::to_string(i) + "]"));
    if (j.contains("weights")) {
      const json& w = j["weights"];
      const auto n = static_cast<Eigen::Index>(spec.handles.size());
      spec.weights.resize(static_cast<Eigen::Index>(w.size()), n);
      for (std::size_t v = 0; v < w.size(); ++v) {
        if (!w[v].is_array() || static_cast<Eigen::Index>(w[v].size()) != n)
          throw InputError("weights[" + std::to_string(v) + "] needs " + std::to_string(n) +
                           " numbers, one per handle");
        for (Eigen::Index i = 0; i < n; ++i)
          spec.weights(static_cast<Eigen::Index>(v), i) =
              w[v][static_cast<std::size_t>(i)].get<double>();
      }
    }
  } catch (const json::exception& e) {
    throw InputError(what + ": bad handle JSON (" + e.what() + ")");
  } catch (const InputError& e) {
    throw InputError(what + ": " + e.what());
  }
  return spec;
}

HandleSpec readHandleSpec(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the handle file");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return parseHandleSpec(text, path);
}

Eigen::MatrixXd distanceWeights(const Vertices& vertices, const std::vector<Handle>& handles,
                                double falloff) {
  if (!(falloff > 0.0)) throw InputError("falloff must be > 0");
  const double delta = kDistanceOffset * std::max(boundingBoxDiagonal(vertices), 1e-300);
  Eigen::MatrixXd w(vertices.rows(), static_cast<Eigen::Index>(handles.size()));
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    for (std::size_t i = 0; i < handles.size(); ++i) {
      const double d = (vertices.row(v).transpose() - handles[i].centre).norm();
      w(v, static_cast<Eigen::Index>(i)) = std::pow(d + delta, -falloff);
    }
    w.row(v) /= w.row(v).sum();
  }
  return w;
}

Vertices deformByHandles(const Vertices& vertices, const std::vector<Handle>& handles,
                         const Eigen::MatrixXd& weights, HandleBlend method) {
  const auto n = static_cast<Eigen::Index>(handles.size());
  if (weights.rows() != vertices.rows() || weights.cols() != n) {
    throw InputError("handle weights are " + std::to_string(weights.rows()) + " by " +
                     std::to_string(weights.cols()) + ", the mesh needs " +
                     std::to_string(vertices.rows()) + " by " + std::to_string(n));
  }
  std::vector<AffineParams> params;
  std::vector<Eigen::Matrix4d> matrices;
  std::vector<DualQuaternion> dqs;
  for (const Handle& h : handles) {
    params.push_back(h.params);
    matrices.push_back(phi(h.params));
    if (method == HandleBlend::kDqs) {
      if (h.params.stretchLog.norm() > kRigidStretchTolerance) {
        throw DomainError("handle '" + h.name +
                          "' stretches (|log S| = " + std::to_string(h.params.stretchLog.norm()) +
                          "); dq blends rigid handles only, use kaji or lbs");
      }
      dqs.push_back(DualQuaternion::fromRigid(matrices.back()));
    }
  }
  Vertices out(vertices.rows(), 3);
  std::vector<double> w(handles.size());
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    for (Eigen::Index i = 0; i < n; ++i) w[static_cast<std::size_t>(i)] = weights(v, i);
    const Eigen::Vector3d u = vertices.row(v).transpose();
    Eigen::Vector3d p;
    if (method == HandleBlend::kDqs) {
      try {
        p = dlb(dqs.data(), w.data(), static_cast<int>(dqs.size())).transformPoint(u);
      } catch (const DomainError& e) {
        throw DomainError("vertex " + std::to_string(v) + ": " + e.what());
      }
    } else {
      Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
      if (method == HandleBlend::kLbs) {
        for (std::size_t i = 0; i < matrices.size(); ++i) a += w[i] * matrices[i];
      } else if (method == HandleBlend::kKaji) {
        a = kajiBlend(w, params);
      } else {
        a = kajiFrechetBlend(w, matrices).matrix;
      }
      p = a.topLeftCorner<3, 3>() * u + a.topRightCorner<3, 1>();
    }
    out.row(v) = p.transpose();
  }
  return out;
}

}  // namespace tetblend
