// Model.variations and Model.pca: the weight vectors of `tetblend
// variations`, random (weight_sampling.h) or along principal components
// (parameter_pca.h).

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "model.h"
#include "numpy_arrays.h"
#include "tetblend/pipeline/parameter_pca.h"
#include "tetblend/pipeline/weight_sampling.h"

namespace py = pybind11;

namespace tetblend::python {
namespace {

Eigen::MatrixXd rows(const std::vector<std::vector<double>>& vectors, Eigen::Index columns) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(vectors.size()), columns);
  for (std::size_t i = 0; i < vectors.size(); ++i) {
    out.row(static_cast<Eigen::Index>(i)) =
        Eigen::Map<const Eigen::RowVectorXd>(vectors[i].data(), columns);
  }
  return out;
}

py::dict pcaDict(const ParameterPca& pca) {
  Eigen::MatrixXd steps(static_cast<Eigen::Index>(pca.steps.size()), pca.meanWeights.size());
  for (std::size_t i = 0; i < pca.steps.size(); ++i) {
    steps.row(static_cast<Eigen::Index>(i)) = pca.steps[i].transpose();
  }
  py::dict out;
  out["mean_weights"] = pca.meanWeights;
  out["steps"] = steps;
  out["sigmas"] = toNumpy(pca.sigmas);
  return out;
}

}  // namespace

void bindVariations(py::module_& m) {
  auto model = py::reinterpret_borrow<py::class_<Model, std::shared_ptr<Model>>>(m.attr("Model"));
  model.def(
      "variations",
      [](const Model& self, int count, std::uint64_t seed, double extrapolate) {
        const auto n = static_cast<int>(self.data().examples.size());
        return rows(sampleSimplexWeights(count, n, seed, extrapolate), n);
      },
      py::arg("count"), py::arg("seed") = 1, py::arg("extrapolate") = 0.0,
      "Random weight vectors, those of 'tetblend variations --seed': float64 (count, n),\n"
      "one row per shape, for Model.blend. Barycentric coordinates (rest, examples)\n"
      "uniform on the simplex; extrapolate X >= 0 scales the simplex by 1 + X about its\n"
      "centre. The same seed gives the same rows on every platform.");
  model.def(
      "pca",
      [](const Model& self, bool consistency) {
        ParameterPca pca;
        {
          py::gil_scoped_release release;
          pca = modelPca(self.data(), consistency);
        }
        return pcaDict(pca);
      },
      py::arg("consistency") = true,
      "Principal components of the rest and the examples in Kaji-Ochiai's parameter space,\n"
      "as weight vectors (those of 'tetblend variations --pca'): a dict with mean_weights\n"
      "float64 (n,), the mean shape's weights; steps float64 (k, n), row i the weight step\n"
      "of +1 standard deviation along component i; sigmas float64 (k,), the standard\n"
      "deviations (parameter units times sqrt(volume)). Shapes: Model.blend(mean_weights\n"
      "+ t * steps[i]) (exact for method 'kaji').");
}

}  // namespace tetblend::python
