#include "errors.h"

#include <exception>

#include "tetblend/core/error.h"

namespace py = pybind11;

namespace tetblend::python {
namespace {

// The classes live as long as the interpreter (module attributes hold a
// reference); these handles are never released, so nothing runs at exit.
PyObject* errorType = nullptr;
PyObject* inputErrorType = nullptr;
PyObject* domainErrorType = nullptr;
PyObject* numericalErrorType = nullptr;
PyObject* resourceErrorType = nullptr;

PyObject* newException(py::module_& module, const char* name, py::tuple bases, const char* doc) {
  const std::string qualified = module.attr("__name__").cast<std::string>() + "." + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (type == nullptr) throw py::error_already_set();
  module.attr(name) = py::handle(type);
  return type;
}

}  // namespace

void registerErrors(py::module_& module) {
  const py::handle error = py::handle(PyExc_Exception);
  errorType = newException(module, "Error", py::make_tuple(error), "Base of every tetblend error.");
  const py::handle base(errorType);
  inputErrorType =
      newException(module, "InputError", py::make_tuple(base, py::handle(PyExc_ValueError)),
                   "Bad input data; the message names the array or file, the "
                   "element and the value.");
  domainErrorType =
      newException(module, "DomainError", py::make_tuple(base, py::handle(PyExc_ValueError)),
                   "A mathematical precondition failed (e.g. a map with det <= 0 "
                   "where Aff+(3) is required).");
  numericalErrorType = newException(module, "NumericalError",
                                    py::make_tuple(base, py::handle(PyExc_ArithmeticError)),
                                    "A solver did not reach its goal.");
  resourceErrorType =
      newException(module, "ResourceError", py::make_tuple(base, py::handle(PyExc_MemoryError)),
                   "The machine lacks the memory the work needs; the message says how much "
                   "and what to change.");
  py::register_local_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(inputErrorType, e.what());
    } catch (const DomainError& e) {
      PyErr_SetString(domainErrorType, e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(numericalErrorType, e.what());
    } catch (const ResourceError& e) {
      PyErr_SetString(resourceErrorType, e.what());
    } catch (const Error& e) {
      PyErr_SetString(errorType, e.what());
    }
  });
}

}  // namespace tetblend::python
