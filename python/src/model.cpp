#include "model.h"

#include "tetblend/pipeline/make_blender.h"

namespace tetblend::python {

Model::Model(ModelData data) : data_(std::make_shared<const ModelData>(std::move(data))) {}

std::shared_ptr<const ShapeBlender> Model::blender(BlendMethod method, bool consistency,
                                                   bool nonlinear) const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::shared_ptr<const ShapeBlender>& slot = blenders_[Key{method, consistency, nonlinear}];
  if (!slot) {
    slot =
        std::make_shared<const ShapeBlender>(makeBlender(*data_, {method}, consistency, nonlinear));
  }
  return slot;
}

}  // namespace tetblend::python
