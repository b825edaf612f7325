#include <deal.II/base/utilities.h>

#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pneuma
{
  using namespace dealii;

  namespace
  {
    /// deal.II writes JSON keys mangled: "_20" for a blank, etc.
    std::string
    demangle(const std::string &s)
    {
      std::string out;
      for (unsigned int i = 0; i < s.size(); ++i)
        if (s[i] == '_' && i + 2 < s.size() + 0
            && std::isxdigit(static_cast<unsigned char>(s[i + 1]))
            && std::isxdigit(static_cast<unsigned char>(s[i + 2])))
          {
            out +=
              static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          out += s[i];
      return out;
    }

    std::string
    join(const std::vector<std::string> &stack, const std::string &name)
    {
      std::string path;
      for (const auto &s : stack)
        path += s + "/";
      return path + name;
    }

    /// Remove a comment (an unescaped '#') from a .prm line.
    std::string
    strip_comment(const std::string &line)
    {
      std::string out;
      for (unsigned int i = 0; i < line.size(); ++i)
        {
          if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '#')
            {
              out += '#';
              ++i;
              continue;
            }
          if (line[i] == '#')
            break;
          out += line[i];
        }
      return out;
    }

    bool
    starts_with_word(const std::string &line, const std::string &word)
    {
      return line.size() > word.size()
             && line.compare(0, word.size(), word) == 0
             && std::isspace(static_cast<unsigned char>(line[word.size()]));
    }
  } // namespace

  InputLayout
  InputLayout::read(const std::string              &file,
                    const std::vector<std::string> &overrides)
  {
    InputLayout     layout;
    std::error_code ec;
    check_input(!std::filesystem::is_directory(file, ec),
                file,
                "is a directory, not a parameter file");
    std::ifstream in(file);
    check_input(static_cast<bool>(in), file, "cannot open parameter file");
    std::stringstream text;
    text << in.rdbuf();
    if (file.size() > 5 && file.substr(file.size() - 5) == ".json")
      {
        boost::property_tree::ptree tree;
        try
          {
            boost::property_tree::read_json(text, tree);
          }
        catch (const std::exception &e)
          {
            throw InputError(file, std::string("not valid JSON: ") + e.what());
          }
        std::vector<std::string>                                 stack;
        std::function<void(const boost::property_tree::ptree &)> walk =
          [&](const boost::property_tree::ptree &node) {
            for (const auto &[key, child] : node)
              {
                check_input(!key.empty(),
                            file,
                            "is a JSON array, not an object of subsections "
                            "and entries");
                const std::string name = demangle(key);
                // An array's items have empty keys: no entry takes one.
                check_input(std::none_of(child.begin(),
                                         child.end(),
                                         [](const auto &item) {
                                           return item.first.empty();
                                         }),
                            join(stack, name),
                            "is a JSON array; give the value as one string "
                            "or number (a list as \"1, 2, 3\")");
                if (child.empty())
                  layout.values[join(stack, name)] = child.data();
                else if (child.count("value") > 0)
                  layout.values[join(stack, name)] =
                    child.get<std::string>("value");
                else
                  {
                    layout.add_subsection(join(stack, name));
                    stack.push_back(name);
                    walk(child);
                    stack.pop_back();
                  }
              }
          };
        walk(tree);
      }
    else
      layout.scan_prm(text.str(), file, 0);
    // An input that sets nothing would run the default scene, which has
    // no supports: almost certainly not what was meant. --set overrides
    // alone do not make a scene.
    check_input(!layout.values.empty(),
                file,
                "sets no parameter (an empty file?); pneuma "
                "--print-parameters lists them all");
    layout.add_overrides(overrides);
    return layout;
  }

  InputLayout
  InputLayout::from_text(const std::string              &prm_text,
                         const std::vector<std::string> &overrides)
  {
    InputLayout layout;
    layout.scan_prm(prm_text, "", 0);
    layout.add_overrides(overrides);
    return layout;
  }

  InputLayout
  InputLayout::template_layout()
  {
    InputLayout layout;
    layout.template_mode = true;
    return layout;
  }

  void
  InputLayout::add_subsection(const std::string &path)
  {
    if (std::find(subsection_paths.begin(), subsection_paths.end(), path)
        == subsection_paths.end())
      subsection_paths.push_back(path);
  }

  void
  InputLayout::scan_prm(const std::string &text,
                        const std::string &file,
                        const unsigned int depth)
  {
    check_input(depth < 16, file, "include files nest too deeply");
    std::vector<std::string> stack;
    std::istringstream       in(text);
    std::string              line, pending;
    while (std::getline(in, line))
      {
        line = strip_comment(line);
        // A trailing backslash continues the line.
        const std::string trimmed = Utilities::trim(line);
        if (!trimmed.empty() && trimmed.back() == '\\')
          {
            pending += trimmed.substr(0, trimmed.size() - 1) + " ";
            continue;
          }
        line    = Utilities::trim(pending + line);
        pending = "";
        if (line.empty())
          continue;
        if (starts_with_word(line, "subsection"))
          {
            const std::string name = Utilities::trim(line.substr(10));
            add_subsection(join(stack, name));
            stack.push_back(name);
          }
        else if (line == "end")
          {
            if (!stack.empty())
              stack.pop_back();
          }
        else if (starts_with_word(line, "set"))
          {
            const auto eq = line.find('=');
            if (eq == std::string::npos)
              continue; // ParameterHandler reports it
            values[join(stack, Utilities::trim(line.substr(3, eq - 3)))] =
              Utilities::trim(line.substr(eq + 1));
          }
        else if (starts_with_word(line, "include"))
          {
            std::string name = Utilities::trim(line.substr(7));
            if (!file.empty() && std::filesystem::path(name).is_relative())
              name =
                (std::filesystem::path(file).parent_path() / name).string();
            std::ifstream included(name);
            check_input(static_cast<bool>(included),
                        file,
                        "cannot open the included file '" + name + "'");
            std::stringstream content;
            content << included.rdbuf();
            scan_prm(content.str(), name, depth + 1);
          }
      }
  }

  void
  InputLayout::add_overrides(const std::vector<std::string> &overrides)
  {
    for (const auto &o : overrides)
      {
        const auto eq = o.find('=');
        if (eq == std::string::npos)
          continue; // parse_input() reports it
        const auto path = Utilities::split_string_list(o.substr(0, eq), '/');
        std::vector<std::string> stack;
        for (unsigned int i = 0; i + 1 < path.size(); ++i)
          {
            add_subsection(join(stack, path[i]));
            stack.push_back(path[i]);
          }
        if (!path.empty())
          values[join(stack, path.back())] = Utilities::trim(o.substr(eq + 1));
      }
  }

  std::string
  InputLayout::value(const std::string &path, const std::string &fallback) const
  {
    const auto it = values.find(path);
    return it == values.end() ? fallback : it->second;
  }

  std::vector<std::string>
  InputLayout::subsections(const std::string &parent) const
  {
    std::vector<std::string> names;
    const std::string        prefix = parent + "/";
    for (const auto &p : subsection_paths)
      if (p.compare(0, prefix.size(), prefix) == 0
          && p.find('/', prefix.size()) == std::string::npos)
        names.push_back(p.substr(prefix.size()));
    return names;
  }

  std::vector<std::string>
  InputLayout::numbered(const std::string &parent,
                        const std::string &prefix,
                        const std::string &count_entry) const
  {
    unsigned int n = 1;
    if (!template_mode)
      {
        // A malformed count declares nothing here; the parse of the entry
        // itself then names it.
        n = 0;
        try
          {
            const int v = Utilities::string_to_int(
              Utilities::trim(value(count_entry, "0")));
            n = v > 0 ? v : 0;
          }
        catch (...)
          {
          }
        // Every instance is declared with all its entries before the
        // parse: a count beyond any scene is a typing error.
        check_input(n <= 1000,
                    count_entry,
                    "is " + std::to_string(n) + "; at most 1000");
        for (const auto &name : subsections(parent))
          if (name.compare(0, prefix.size() + 1, prefix + " ") == 0)
            {
              unsigned int k = 0;
              try
                {
                  k = Utilities::string_to_int(name.substr(prefix.size() + 1));
                }
              catch (...)
                {
                  throw InputError(parent + "/" + name,
                                   "expected '" + prefix + " <number>'");
                }
              check_input(k >= 1 && k <= n,
                          parent + "/" + name,
                          "is not used: " + count_entry + " is "
                            + std::to_string(n) + " (numbered 1.."
                            + std::to_string(n)
                            + "); raise the count or remove the subsection");
            }
      }
    std::vector<std::string> names;
    for (unsigned int k = 1; k <= n; ++k)
      names.push_back(prefix + " " + std::to_string(k));
    return names;
  }

  std::vector<unsigned int>
  InputLayout::keyed(const std::string               &parent,
                     const std::string               &prefix,
                     const std::vector<unsigned int> &fallback) const
  {
    if (template_mode)
      return fallback;
    std::vector<unsigned int> ids;
    for (const auto &name : subsections(parent))
      {
        check_input(name.compare(0, prefix.size() + 1, prefix + " ") == 0,
                    parent + "/" + name,
                    "unknown subsection: expected '" + prefix + " <id>'");
        const std::string id = name.substr(prefix.size() + 1);
        check_input(!id.empty()
                      && std::all_of(id.begin(),
                                     id.end(),
                                     [](const char c) {
                                       return std::isdigit(c);
                                     })
                      && id.size() < 10,
                    parent + "/" + name,
                    "the id must be a non-negative integer (a Gmsh physical "
                    "surface tag)");
        ids.push_back(std::stoul(id));
      }
    return ids.empty() ? fallback : ids;
  }
} // namespace pneuma
