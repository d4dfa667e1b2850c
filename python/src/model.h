#pragma once
// The Python module's Model: a prepared model (ModelData) and the blenders
// made for it, one per (method, rotation consistency, nonlinear stitch),
// each made on first use and then kept, so that a thousand blends cost one
// parametrisation and one stitch factorisation.

#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "tetblend/blending/shape_blender.h"
#include "tetblend/pipeline/model_file.h"

namespace tetblend::python {

/// A model and its blenders. Thread-safe: blenders are made under a lock and
/// only read afterwards (ShapeBlender::blend is safe to call concurrently).
class Model {
 public:
  explicit Model(ModelData data);

  const ModelData& data() const { return *data_; }

  /// The blender for these settings, made (parametrisation, stitch factor)
  /// on the first call and kept.
  std::shared_ptr<const ShapeBlender> blender(BlendMethod method, bool consistency,
                                              bool nonlinear) const;

 private:
  using Key = std::tuple<BlendMethod, bool, bool>;
  std::shared_ptr<const ModelData> data_;
  mutable std::mutex mutex_;
  mutable std::map<Key, std::shared_ptr<const ShapeBlender>> blenders_;
};

}  // namespace tetblend::python
