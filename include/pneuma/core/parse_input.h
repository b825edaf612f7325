#pragma once

/**
 * @file
 * Reading the input into a declared ParameterHandler: a .prm or .json
 * file, or parameter text, then the "Path/To/Entry=value" overrides of
 * the command line (doc/user-guide.md "Input").
 */

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace pneuma
{
  /**
   * Read @p file (.prm or .json) into @p prm (declared) and apply the
   * "Path/To/Entry=value" @p overrides; throws InputError naming the file
   * or parameter.
   */
  void
  parse_input(dealii::ParameterHandler       &prm,
              const std::string              &file,
              const std::vector<std::string> &overrides = {});

  /// Same, for parameter text in .prm syntax (tests).
  void
  parse_input_text(dealii::ParameterHandler       &prm,
                   const std::string              &text,
                   const std::vector<std::string> &overrides = {});
} // namespace pneuma
