#pragma once
// Typed errors raised by every tetblend library. Library code never prints or
// exits: it throws one of these, and the command line turns it into one line.

#include <stdexcept>
#include <string>

namespace tetblend {

/// Base of every tetblend error.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Bad user data: the message names the file, the element, the value and what
/// to do about it.
class InputError : public Error {
public:
  using Error::Error;
};

/// A mathematical precondition failed (e.g. det A <= 0 where Aff+(3) is
/// required, or a matrix without a real logarithm).
class DomainError : public Error {
public:
  using Error::Error;
};

/// An iterative method or a solver did not reach its goal.
class NumericalError : public Error {
public:
  using Error::Error;
};

/// The machine lacks a resource the work needs (memory): the message says
/// how much and what to change.
class ResourceError : public Error {
public:
  using Error::Error;
};

} // namespace tetblend
