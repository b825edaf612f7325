#include <deal.II/base/utilities.h>

#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/parse_input.h>

#include <fstream>
#include <sstream>

namespace pneuma
{
  namespace
  {
    /// The user-relevant part of a deal.II exception text.
    std::string
    short_message(const std::exception &e)
    {
      std::string       text = e.what();
      const std::string key  = "Additional information:";
      const auto        pos  = text.find(key);
      if (pos != std::string::npos)
        text = text.substr(pos + key.size());
      const auto stack = text.find("Stacktrace:");
      if (stack != std::string::npos)
        text = text.substr(0, stack);
      // Collapse white space and dashes of the deal.II frame.
      std::string out;
      bool        space = false;
      for (const char c : text)
        {
          if (c == '\n' || c == ' ' || c == '\t')
            space = true;
          else if (c != '-' || !out.empty())
            {
              if (space && !out.empty())
                out += ' ';
              out += c;
              space = false;
            }
        }
      while (!out.empty() && (out.back() == '-' || out.back() == ' '))
        out.pop_back();
      return out;
    }

    /**
     * Set the entry @p path ("A/B/Entry") to @p value; an InputError
     * naming @p label (the path, or the whole --set argument's path) if
     * there is no such entry or the value does not match its pattern.
     */
    void
    set_entry(dealii::ParameterHandler &prm,
              const std::string        &path,
              const std::string        &value,
              const std::string        &label)
    {
      const auto parts = dealii::Utilities::split_string_list(path, '/');
      check_input(!parts.empty(), label, "empty parameter path");
      unsigned int depth = 0;
      try
        {
          for (unsigned int i = 0; i + 1 < parts.size(); ++i, ++depth)
            prm.enter_subsection(parts[i]);
          prm.set(parts.back(), value);
        }
      catch (const std::exception &e)
        {
          for (; depth > 0; --depth)
            prm.leave_subsection();
          std::string what = short_message(e);
          if (what.find("not yet declared") != std::string::npos)
            what = "no such entry (pneuma --print-parameters lists "
                   "them all)";
          throw InputError(label, what);
        }
      for (; depth > 0; --depth)
        prm.leave_subsection();
    }

    void
    apply_overrides(dealii::ParameterHandler       &prm,
                    const std::vector<std::string> &overrides)
    {
      for (const auto &o : overrides)
        {
          const auto eq = o.find('=');
          check_input(eq != std::string::npos,
                      "--set " + o,
                      "expected Path/To/Entry=value");
          check_input(!dealii::Utilities::trim(o.substr(0, eq)).empty(),
                      "--set " + o,
                      "empty parameter path");
          set_entry(prm,
                    o.substr(0, eq),
                    dealii::Utilities::trim(o.substr(eq + 1)),
                    o.substr(0, eq));
        }
    }
  } // namespace

  void
  parse_input(dealii::ParameterHandler       &prm,
              const std::string              &file,
              const std::vector<std::string> &overrides)
  {
    {
      std::ifstream in(file);
      check_input(static_cast<bool>(in), file, "cannot open parameter file");
    }
    // A JSON file entry by entry, so that a message names the entry
    // (InputLayout::read names a value that is an array).
    if (file.size() > 5 && file.substr(file.size() - 5) == ".json")
      {
        const InputLayout layout = InputLayout::read(file, {});
        for (const auto &[path, value] : layout.entries())
          set_entry(prm, path, value, path);
      }
    else
      try
        {
          prm.parse_input(file, "", /*skip_undefined=*/false, true);
        }
      catch (const std::exception &e)
        {
          throw InputError(file, short_message(e));
        }
    apply_overrides(prm, overrides);
  }

  void
  parse_input_text(dealii::ParameterHandler       &prm,
                   const std::string              &text,
                   const std::vector<std::string> &overrides)
  {
    try
      {
        prm.parse_input_from_string(text, "", /*skip_undefined=*/false);
      }
    catch (const std::exception &e)
      {
        throw InputError("parameter text", short_message(e));
      }
    apply_overrides(prm, overrides);
  }
} // namespace pneuma
