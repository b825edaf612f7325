#pragma once

/**
 * @file
 * One registry per family of variants (membrane laws, gas laws, cable
 * elements, geometries): each variant registers its name, a description,
 * the declaration of its own constants and a factory, in its own .cc file
 * (doc/architecture.md "Add a material law"):
 * @code
 * PNEUMA_REGISTER_VARIANT(membrane::ConstitutiveLaw, GentLaw, "Gent",
 *                         "incompressible Gent law (rubber balloons)");
 * @endcode
 * The class @p Variant has a default constructor, a member
 * `declare_parameters(ParameterHandler &)` that declares (and binds, with
 * add_parameter) its constants inside its own subsection, and a member
 * `parse_parameters(ParameterHandler &, const std::string &path)` that
 * checks them, naming @p path in its messages.
 *
 * A parameter selects a variant by name; a name that is not registered is
 * an InputError that lists the valid ones.
 */

#include <deal.II/base/parameter_handler.h>

#include <pneuma/core/input_error.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pneuma
{
  /// The registered variants of the family with interface @p Interface.
  template <typename Interface>
  class Registry
  {
  public:
    struct Entry
    {
      std::string                                 name, description;
      std::function<std::unique_ptr<Interface>()> create;
    };

    /// The one registry of this family.
    static Registry &
    instance()
    {
      static Registry registry;
      return registry;
    }

    bool
    add(const Entry &entry)
    {
      entries.push_back(entry);
      return true;
    }

    /// "a|b|c" of every name, in registration order.
    std::string
    names(const std::string &separator = "|") const
    {
      std::string s;
      for (const auto &e : entries)
        s += (s.empty() ? "" : separator) + e.name;
      return s;
    }

    /// One line per variant: "name: description".
    std::string
    descriptions() const
    {
      std::string s;
      for (const auto &e : entries)
        s += (s.empty() ? "" : "; ") + e.name + ": " + e.description;
      return s;
    }

    bool
    has(const std::string &name) const
    {
      for (const auto &e : entries)
        if (e.name == name)
          return true;
      return false;
    }

    /// Throw an InputError for @p parameter unless @p name is registered.
    void
    check(const std::string &name, const std::string &parameter) const
    {
      check_input(has(name),
                  parameter,
                  "unknown '" + name + "'; valid: " + names(", "));
    }

    /**
     * One instance of every variant, each declaring its constants in the
     * subsection of its name under the current subsection of @p prm. The
     * caller keeps the instances (their members are bound) and later
     * selects one with take().
     */
    std::map<std::string, std::unique_ptr<Interface>>
    declare_all(dealii::ParameterHandler &prm) const
    {
      std::map<std::string, std::unique_ptr<Interface>> all;
      for (const auto &e : entries)
        {
          auto variant = e.create();
          prm.enter_subsection(e.name);
          variant->declare_parameters(prm);
          prm.leave_subsection();
          all[e.name] = std::move(variant);
        }
      return all;
    }

    /**
     * The variant @p name of @p all (from declare_all), parsed: its
     * parse_parameters() checks its constants, naming
     * @p path + "/" + name. Throws InputError for @p parameter if the name
     * is not registered.
     */
    std::unique_ptr<Interface>
    take(std::map<std::string, std::unique_ptr<Interface>> &all,
         dealii::ParameterHandler                          &prm,
         const std::string                                 &name,
         const std::string                                 &parameter,
         const std::string                                 &path) const
    {
      check(name, parameter);
      auto variant = std::move(all.at(name));
      prm.enter_subsection(name);
      variant->parse_parameters(prm, path + "/" + name);
      prm.leave_subsection();
      return variant;
    }

  private:
    std::vector<Entry> entries;
  };
} // namespace pneuma

#define PNEUMA_REGISTRY_CONCAT_IMPL(a, b) a##b
#define PNEUMA_REGISTRY_CONCAT(a, b) PNEUMA_REGISTRY_CONCAT_IMPL(a, b)

/**
 * Register the class @p Variant as the variant @p name (with a one-line
 * @p description) of the family @p Interface. Use once, at namespace
 * scope, in the variant's own .cc file.
 */
#define PNEUMA_REGISTER_VARIANT(Interface, Variant, name, description)        \
  namespace                                                                   \
  {                                                                           \
    const bool PNEUMA_REGISTRY_CONCAT(pneuma_registered_variant_, __LINE__) = \
      ::pneuma::Registry<Interface>::instance().add(                          \
        {name, description, []() {                                            \
           return std::unique_ptr<Interface>(std::make_unique<Variant>());    \
         }});                                                                 \
  }
