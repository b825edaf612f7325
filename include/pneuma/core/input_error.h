#pragma once

/**
 * @file
 * The exception for anything a user can get wrong in the input: it carries
 * one clear message that names the parameter or file. The main program turns
 * it into a single line on stderr and exit code 1.
 */

#include <stdexcept>
#include <string>

namespace pneuma
{
  /// Bad input: an invalid parameter value, a missing file, an empty region.
  class InputError : public std::runtime_error
  {
  public:
    /// @p parameter names the entry (e.g. "Geometry/Mesh file") or file.
    InputError(const std::string &parameter, const std::string &what)
      : std::runtime_error(parameter + ": " + what)
    {
    }
    /// The complete message "parameter: what" (e.g. agreed on by the MPI
    /// ranks, core/collective_error.h).
    explicit InputError(const std::string &message)
      : std::runtime_error(message)
    {
    }
  };

  /// Throw an InputError for @p parameter unless @p condition holds.
  inline void
  check_input(const bool         condition,
              const std::string &parameter,
              const std::string &what)
  {
    if (!condition)
      throw InputError(parameter, what);
  }
} // namespace pneuma
