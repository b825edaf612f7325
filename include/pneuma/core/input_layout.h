#pragma once

/**
 * @file
 * What a parameter input uses, read before any parameter is declared
 * (doc/architecture.md "Parameters"): the subsections it opens and the
 * entries it sets, from the .prm or .json file and the --set overrides.
 * Subsystems declare exactly the repeated subsections the input uses (the
 * cables 1..N of "Number of cables", the material regions it names), so
 * `--print-parameters` shows one template of each, and an instance that
 * the counts do not declare is an error that names it.
 */

#include <deal.II/base/types.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace pneuma
{
  /// The subsections and entries a parameter input uses.
  class InputLayout
  {
  public:
    /**
     * Read the layout of @p file (.prm, with `include`, or .json) and of
     * the "Path/To/Entry=value" @p overrides. Throws InputError naming the
     * file if it cannot be read.
     */
    static InputLayout
    read(const std::string &file, const std::vector<std::string> &overrides);

    /// The layout of the text @p prm_text (.prm syntax) and @p overrides.
    static InputLayout
    from_text(const std::string              &prm_text,
              const std::vector<std::string> &overrides);

    /// One instance of every repeated subsection (--print-parameters).
    static InputLayout
    template_layout();

    /// True for template_layout().
    bool
    is_template() const
    {
      return template_mode;
    }

    /// The value the input gives @p path ("Cables/Number of cables"; the
    /// last one set), or @p fallback.
    std::string
    value(const std::string &path, const std::string &fallback) const;

    /// The names of the subsections directly under @p parent ("Materials")
    /// that the input opens, in first-seen order.
    std::vector<std::string>
    subsections(const std::string &parent) const;

    /**
     * Instances "<prefix> 1" .. "<prefix> N" of a numbered family under
     * @p parent, N from @p count_entry (a path; one in template mode).
     * Throws InputError naming an instance the input opens beyond N, or
     * @p count_entry if N is above 1000.
     */
    std::vector<std::string>
    numbered(const std::string &parent,
             const std::string &prefix,
             const std::string &count_entry) const;

    /**
     * Ids of a keyed family "<prefix> <id>" under @p parent (e.g.
     * "Materials/Region 100"), any non-negative integer id; @p fallback if
     * the input opens none (template mode: @p fallback). Throws InputError
     * naming a subsection whose id is not an integer.
     */
    std::vector<unsigned int>
    keyed(const std::string               &parent,
          const std::string               &prefix,
          const std::vector<unsigned int> &fallback) const;

    /// Every entry the input sets, "Path/To/Entry" -> its last value.
    const std::map<std::string, std::string> &
    entries() const
    {
      return values;
    }

  private:
    bool template_mode = false;
    /// Subsection paths in first-seen order ("Cables/Cable 1").
    std::vector<std::string> subsection_paths;
    /// Entry path -> last value.
    std::map<std::string, std::string> values;

    void
    add_subsection(const std::string &path);
    void
    scan_prm(const std::string &text,
             const std::string &file,
             unsigned int       depth);
    void
    add_overrides(const std::vector<std::string> &overrides);
  };
} // namespace pneuma
