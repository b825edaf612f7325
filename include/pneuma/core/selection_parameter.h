#pragma once

/**
 * @file
 * A Selection entry bound to a member of any type (an enum, a bool), the
 * counterpart of ParameterHandler::add_parameter for choices
 * (doc/architecture.md "Parameters"): the member's value is the default,
 * so the default has one source.
 * @code
 * add_selection(prm, "Filling", def.filling,
 *               {{"gas", Filling::gas}, {"liquid", Filling::liquid}},
 *               "What fills the chamber.");
 * @endcode
 * declares "Filling" with the pattern Selection("gas|liquid") and the
 * default named by the current value of def.filling, and binds it: the
 * member takes the value of the chosen name whenever the entry is read or
 * set (and once now, for the default).
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <string>
#include <utility>
#include <vector>

namespace pneuma
{
  /**
   * Declare the Selection entry @p entry of the names in @p choices in the
   * current subsection of @p prm, with the default named by the current
   * value of @p value, and bind @p value to it. @p value must be one of
   * the choices; it must outlive the parsing of @p prm.
   */
  template <typename T>
  void
  add_selection(dealii::ParameterHandler                     &prm,
                const std::string                            &entry,
                T                                            &value,
                const std::vector<std::pair<std::string, T>> &choices,
                const std::string                            &documentation)
  {
    std::string names, default_name;
    for (const auto &[name, choice] : choices)
      {
        names += (names.empty() ? "" : "|") + name;
        if (choice == value && default_name.empty())
          default_name = name;
      }
    AssertThrow(!default_name.empty(),
                dealii::ExcMessage("the default of '" + entry
                                   + "' is not one of " + names));
    prm.declare_entry(entry,
                      default_name,
                      dealii::Patterns::Selection(names),
                      documentation);
    prm.add_action(entry, [&value, choices](const std::string &text) {
      const std::string name = dealii::Utilities::trim(text);
      for (const auto &[n, choice] : choices)
        if (n == name)
          value = choice;
    });
  }
} // namespace pneuma
