#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <iostream>
#include <regex>
#include <sstream>

#include <pneuma/core/input_error.h>
#include <pneuma/loads/loads.h>

#include <cmath>

namespace pneuma
{
  namespace loads
  {
    void
    declare_function(ParameterHandler  &prm,
                     const std::string &name,
                     const unsigned int n_components,
                     const std::string &expression)
    {
      prm.enter_subsection(name);
      Functions::ParsedFunction<3>::declare_parameters(prm, n_components);
      prm.set("Function expression", expression);
      prm.leave_subsection();
    }

    Point<3>
    parse_point(const std::string &text, const std::string &path)
    {
      const auto xyz = Utilities::split_string_list(text, ',');
      check_input(xyz.size() == 3,
                  path,
                  "'" + text + "' is not of the form x, y, z");
      Point<3> p;
      for (unsigned int d = 0; d < 3; ++d)
        try
          {
            p[d] = Utilities::string_to_double(xyz[d]);
          }
        catch (...)
          {
            throw InputError(path, "'" + xyz[d] + "' is not a number");
          }
      check_input(std::isfinite(p[0]) && std::isfinite(p[1])
                    && std::isfinite(p[2]),
                  path,
                  "'" + text + "' is not a finite point");
      return p;
    }

    std::set<unsigned int>
    parse_id_list(const std::string &text, const std::string &path)
    {
      std::set<unsigned int> ids;
      for (const auto &item : Utilities::split_string_list(text))
        {
          int id = -1;
          try
            {
              id = Utilities::string_to_int(item);
            }
          catch (...)
            {
            }
          check_input(id >= 0, path, "'" + item + "' is not an id >= 0");
          ids.insert(id);
        }
      return ids;
    }

    void
    parse_function(ParameterHandler             &prm,
                   Functions::ParsedFunction<3> &function,
                   const std::string            &name,
                   const std::string            &path,
                   const bool                    finite_at_origin)
    {
      prm.enter_subsection(name);
      const std::string expression = prm.get("Function expression");
      // Constants are "name=value" with a finite number.
      for (const auto &item :
           Utilities::split_string_list(prm.get("Function constants"), ','))
        {
          const auto eq    = item.find('=');
          bool       valid = eq != std::string::npos && eq > 0;
          if (valid)
            try
              {
                valid = std::isfinite(
                  Utilities::string_to_double(item.substr(eq + 1)));
              }
            catch (...)
              {
                valid = false;
              }
          if (!valid)
            {
              prm.leave_subsection();
              throw InputError(path + "/Function constants",
                               "expected name=value with a finite number, "
                               "got '"
                                 + item + "'");
            }
        }
      // The parser reports errors on the standard streams itself: keep
      // them quiet, the one message is ours.
      std::ostringstream sink;
      auto *const        out_buf = std::cout.rdbuf(sink.rdbuf());
      auto *const        err_buf = std::cerr.rdbuf(sink.rdbuf());
      struct Restore
      {
        std::streambuf *o, *e;
        ~Restore()
        {
          std::cout.rdbuf(o);
          std::cerr.rdbuf(e);
        }
      } restore{out_buf, err_buf};
      try
        {
          function.parse_parameters(prm);
        }
      catch (...)
        {
          prm.leave_subsection();
          throw InputError(path + "/Function expression",
                           "cannot parse '" + expression + "'");
        }
      // Evaluate once: muparser reports some errors only then.
      Vector<double> values(function.n_components);
      try
        {
          function.vector_value(Point<3>(), values);
        }
      catch (...)
        {
          prm.leave_subsection();
          throw InputError(path + "/Function expression",
                           "cannot evaluate '" + expression + "'");
        }
      prm.leave_subsection();
      if (finite_at_origin)
        for (unsigned int c = 0; c < values.size(); ++c)
          check_input(std::isfinite(values[c]),
                      path + "/Function expression",
                      "'" + expression + "' is not finite at t = 0");
    }

    std::string
    first_non_finite(const Functions::ParsedFunction<3> &function,
                     const std::vector<Point<3>>        &points)
    {
      Vector<double> values(function.n_components);
      for (const auto &x : points)
        {
          function.vector_value(x, values);
          for (unsigned int c = 0; c < values.size(); ++c)
            if (!std::isfinite(values[c]))
              {
                std::ostringstream s;
                s << "is not finite at t = " << function.get_time()
                  << " at the reference point (" << x << ")";
                return s.str();
              }
        }
      return "";
    }

    Loads::Loads()
      : pressure_function(std::make_unique<Functions::ParsedFunction<3>>(1))
      , gravity_function(std::make_unique<Functions::ParsedFunction<3>>(3))
      , surface_function(std::make_unique<Functions::ParsedFunction<3>>(3))
      , line_function(std::make_unique<Functions::ParsedFunction<3>>(3))
      , point_function(std::make_unique<Functions::ParsedFunction<3>>(3))
    {
    }

    void
    Loads::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Loads");
      declare_function(prm, "Pressure", 1, "0");
      prm.add_parameter("Pressure regions",
                        pressure_regions_text,
                        "Material ids on which the follower pressure acts; "
                        "empty = all cells.",
                        Patterns::List(Patterns::Integer(0)));
      prm.add_parameter("Gravity",
                        gravity_on,
                        "Apply the gravity function to the membrane mass.");
      declare_function(prm, "Gravity vector", 3, "0; 0; -9.81");
      prm.add_parameter("Surface load",
                        surface_load_on,
                        "Apply the dead surface traction function.");
      declare_function(prm, "Surface traction", 3, "0; 0; 0");
      prm.add_parameter("Surface load regions",
                        surface_regions_text,
                        "Material ids on which the dead surface traction "
                        "acts; empty = all cells.",
                        Patterns::List(Patterns::Integer(0)));
      prm.add_parameter("Line load boundaries",
                        line_load_text,
                        "Boundary ids carrying the dead line load.",
                        Patterns::List(Patterns::Integer(0)));
      declare_function(prm, "Line load", 3, "0; 0; 0");
      prm.add_parameter("Point loads",
                        point_loads_text,
                        "Points 'x, y, z; x, y, z; ...' [m] carrying the dead "
                        "force 'Point load' [N] of (x, y, z, t) evaluated at "
                        "each point (e.g. 'if(x > 0, 1, -1)*t; 0; 0'), applied "
                        "at the membrane vertex nearest to it (a pinching "
                        "force on a shell; on a membrane it is singular).");
      declare_function(prm, "Point load", 3, "0; 0; 0");
      prm.leave_subsection();
    }

    namespace
    {
      /// Does the expression of function subsection @p name use one of
      /// its first three (spatial) variable names?
      bool
      depends_on_position(ParameterHandler &prm, const std::string &name)
      {
        prm.enter_subsection(name);
        const std::string expression = prm.get("Function expression");
        const auto        variables =
          Utilities::split_string_list(prm.get("Variable names"), ',');
        prm.leave_subsection();
        const std::regex identifier("[A-Za-z_][A-Za-z_0-9]*");
        for (auto it = std::sregex_iterator(expression.begin(),
                                            expression.end(),
                                            identifier);
             it != std::sregex_iterator();
             ++it)
          for (unsigned int d = 0;
               d < std::min<std::size_t>(3, variables.size());
               ++d)
            if (it->str() == variables[d])
              return true;
        return false;
      }
    } // namespace

    void
    Loads::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Loads");
      parse_function(prm, *pressure_function, "Pressure", "Loads/Pressure");
      pressure_uniform = !depends_on_position(prm, "Pressure");
      const auto pr =
        parse_id_list(pressure_regions_text, "Loads/Pressure regions");
      pressure_ids = std::set<types::material_id>(pr.begin(), pr.end());
      const auto sr =
        parse_id_list(surface_regions_text, "Loads/Surface load regions");
      surface_ids = std::set<types::material_id>(sr.begin(), sr.end());
      parse_function(prm,
                     *gravity_function,
                     "Gravity vector",
                     "Loads/Gravity vector",
                     gravity_on);
      parse_function(prm,
                     *surface_function,
                     "Surface traction",
                     "Loads/Surface traction");
      const auto ll =
        parse_id_list(line_load_text, "Loads/Line load boundaries");
      line_load_ids = std::set<types::boundary_id>(ll.begin(), ll.end());
      parse_function(prm, *line_function, "Line load", "Loads/Line load");
      point_points.clear();
      for (const auto &item :
           Utilities::split_string_list(point_loads_text, ';'))
        if (!item.empty())
          point_points.push_back(parse_point(item, "Loads/Point loads"));
      parse_function(prm, *point_function, "Point load", "Loads/Point load");
      prm.leave_subsection();
    }

    std::string
    Loads::non_finite_at_start(const std::vector<Point<3>> &points,
                               const std::vector<Point<3>> &line_points) const
    {
      const auto check = [](Functions::ParsedFunction<3> &f,
                            const std::vector<Point<3>>  &x,
                            const std::string            &path) {
        f.set_time(0.);
        const std::string why = first_non_finite(f, x);
        return why.empty() ? why : path + "/Function expression: " + why;
      };
      std::string error = check(*pressure_function, points, "Loads/Pressure");
      if (error.empty() && surface_load_on)
        error = check(*surface_function, points, "Loads/Surface traction");
      if (error.empty())
        error = check(*line_function, line_points, "Loads/Line load");
      if (error.empty())
        error = check(*point_function, point_points, "Loads/Point load");
      return error;
    }

    void
    Loads::set_time(const double t) const
    {
      for (auto *f : {pressure_function.get(),
                      gravity_function.get(),
                      surface_function.get(),
                      line_function.get(),
                      point_function.get()})
        if (f->get_time() != t)
          f->set_time(t);
    }

    double
    Loads::pressure(const Point<3> &x, const double t) const
    {
      if (pressure_function->get_time() != t)
        pressure_function->set_time(t);
      return pressure_function->value(x);
    }

    bool
    Loads::pressure_acts_on(const types::material_id id) const
    {
      return pressure_ids.empty() || pressure_ids.count(id) > 0;
    }

    bool
    Loads::surface_load_acts_on(const types::material_id id) const
    {
      return surface_load_on
             && (surface_ids.empty() || surface_ids.count(id) > 0);
    }

    namespace
    {
      Tensor<1, 3>
      vector_value(Functions::ParsedFunction<3> &f,
                   const Point<3>               &x,
                   const double                  t)
      {
        if (f.get_time() != t)
          f.set_time(t);
        Vector<double> v(3);
        f.vector_value(x, v);
        Tensor<1, 3> r;
        for (unsigned int d = 0; d < 3; ++d)
          r[d] = v[d];
        return r;
      }
    } // namespace

    Tensor<1, 3>
    Loads::gravity(const double t) const
    {
      return vector_value(*gravity_function, Point<3>(), t);
    }

    Tensor<1, 3>
    Loads::surface_load(const Point<3> &x, const double t) const
    {
      return vector_value(*surface_function, x, t);
    }

    Tensor<1, 3>
    Loads::line_load(const Point<3> &x, const double t) const
    {
      return vector_value(*line_function, x, t);
    }

    Tensor<1, 3>
    Loads::point_load(const Point<3> &x, const double t) const
    {
      return vector_value(*point_function, x, t);
    }
  } // namespace loads
} // namespace pneuma
