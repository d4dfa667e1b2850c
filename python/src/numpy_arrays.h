#pragma once
// numpy arrays in and out of the module. Inputs are checked before any work:
// the array's name, its shape and its dtype appear in the message of the
// error. Coordinates may be any real float or integer dtype (converted to
// float64); indices any integer dtype (converted to int32, range-checked).
// Booleans, complex numbers, strings and objects are refused, never cast.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "tetblend/core/mesh_types.h"

namespace tetblend::python {

/// `obj` (an array or anything numpy.asarray takes) as a `rows` (any number
/// when negative) by `columns` float64 matrix. TypeError for a non-real
/// dtype; InputError for another shape or a NaN or infinite value.
Eigen::MatrixXd toMatrix(pybind11::handle obj, const std::string& name, Eigen::Index rows,
                         Eigen::Index columns);

/// toMatrix(obj, name, -1, 3) as #V by 3 positions.
Vertices toVertices(pybind11::handle obj, const std::string& name);

/// `obj` as rows of `Columns` vertex indices in [0, vertexCount). TypeError
/// for a non-integer dtype; InputError for another shape or an index out of
/// range.
template <int Columns>
Eigen::Matrix<int, Eigen::Dynamic, Columns, Eigen::RowMajor> toIndices(pybind11::handle obj,
                                                                       const std::string& name,
                                                                       Eigen::Index vertexCount);

/// `obj` (a sequence or 1-D array of real numbers) as a weight vector.
/// TypeError for a non-real dtype; InputError for another shape.
std::vector<double> toWeights(pybind11::handle obj, const std::string& name);

/// `values` as a new 1-D float64 array.
pybind11::array_t<double> toNumpy(const std::vector<double>& values);

}  // namespace tetblend::python
