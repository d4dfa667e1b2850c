#include "numpy_arrays.h"

#include <cmath>
#include <cstdint>

#include "tetblend/core/error.h"

namespace py = pybind11;

namespace tetblend::python {
namespace {

std::string shapeText(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) {
    text += (d ? ", " : "") + std::to_string(a.shape(d));
  }
  return text + (a.ndim() == 1 ? ",)" : ")");
}

std::string dtypeText(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

py::array asArray(py::handle obj) {
  return py::module_::import("numpy").attr("asarray")(obj).cast<py::array>();
}

// Real numbers: numpy kinds 'f' (float), 'i' (signed) and 'u' (unsigned).
bool isReal(const py::array& a) {
  const char kind = a.dtype().kind();
  return kind == 'f' || kind == 'i' || kind == 'u';
}

bool isInteger(const py::array& a) {
  const char kind = a.dtype().kind();
  return kind == 'i' || kind == 'u';
}

// The array of `obj` with `columns` columns and `rows` rows (any when
// rows < 0) and an integer (or, when !integer, real) dtype.
py::array checked2d(py::handle obj, const std::string& name, py::ssize_t rows, py::ssize_t columns,
                    bool integer) {
  const py::array a = asArray(obj);
  if (!(integer ? isInteger(a) : isReal(a))) {
    throw py::type_error(name + ": dtype " + dtypeText(a) + " is not " +
                         (integer ? "an integer type (give int32 or int64 indices)"
                                  : "a real number type (give float64 values)"));
  }
  if (a.ndim() != 2 || (rows >= 0 && a.shape(0) != rows) || a.shape(1) != columns) {
    throw InputError(name + ": expected an array of shape (" +
                     (rows >= 0 ? std::to_string(rows) : std::string("n")) + ", " +
                     std::to_string(columns) + "), got shape " + shapeText(a));
  }
  return a;
}

}  // namespace

Eigen::MatrixXd toMatrix(py::handle obj, const std::string& name, Eigen::Index rows,
                         Eigen::Index columns) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(
      checked2d(obj, name, rows, columns, false));
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Eigen::MatrixXd m = Eigen::Map<const RowMajor>(a.data(), a.shape(0), columns);
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    for (Eigen::Index c = 0; c < columns; ++c) {
      if (!std::isfinite(m(i, c))) {
        throw InputError(name + "[" + std::to_string(i) + ", " + std::to_string(c) + "] is " +
                         std::to_string(m(i, c)) + ": values must be finite");
      }
    }
  }
  return m;
}

Vertices toVertices(py::handle obj, const std::string& name) { return toMatrix(obj, name, -1, 3); }

template <int Columns>
Eigen::Matrix<int, Eigen::Dynamic, Columns, Eigen::RowMajor> toIndices(py::handle obj,
                                                                       const std::string& name,
                                                                       Eigen::Index vertexCount) {
  const auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(
      checked2d(obj, name, -1, Columns, true));
  const std::int64_t* data = a.data();
  Eigen::Matrix<int, Eigen::Dynamic, Columns, Eigen::RowMajor> out(a.shape(0), Columns);
  for (Eigen::Index i = 0; i < out.rows(); ++i) {
    for (int c = 0; c < Columns; ++c) {
      const std::int64_t index = data[i * Columns + c];
      if (index < 0 || index >= vertexCount) {
        throw InputError(name + "[" + std::to_string(i) + ", " + std::to_string(c) +
                         "] = " + std::to_string(index) + " is not a vertex index (there are " +
                         std::to_string(vertexCount) + " vertices)");
      }
      out(i, c) = static_cast<int>(index);
    }
  }
  return out;
}

template Triangles toIndices<3>(py::handle, const std::string&, Eigen::Index);
template Tets toIndices<4>(py::handle, const std::string&, Eigen::Index);

std::vector<double> toWeights(py::handle obj, const std::string& name) {
  const py::array a = asArray(obj);
  if (!isReal(a)) {
    throw py::type_error(name + ": dtype " + dtypeText(a) +
                         " is not a real number type (give float64 weights)");
  }
  if (a.ndim() != 1) {
    throw InputError(name + ": expected a 1-D array of weights, one per example, got shape " +
                     shapeText(a));
  }
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  return std::vector<double>(d.data(), d.data() + d.shape(0));
}

py::array_t<double> toNumpy(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

}  // namespace tetblend::python
