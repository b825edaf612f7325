#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <iostream>
#include <sstream>

#include <pneuma/core/input_error.h>
#include <pneuma/loads/loads.h>

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
                   const std::string            &path)
    {
      prm.enter_subsection(name);
      const std::string expression = prm.get("Function expression");
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
          // Evaluate once: muparser reports some errors only then.
          Vector<double> values(function.n_components);
          function.vector_value(Point<3>(), values);
        }
      catch (...)
        {
          prm.leave_subsection();
          throw InputError(path + "/Function expression",
                           "cannot parse '" + expression + "'");
        }
      prm.leave_subsection();
    }

    Loads::Loads()
      : pressure_function(std::make_unique<Functions::ParsedFunction<3>>(1))
      , gravity_function(std::make_unique<Functions::ParsedFunction<3>>(3))
      , surface_function(std::make_unique<Functions::ParsedFunction<3>>(3))
      , line_function(std::make_unique<Functions::ParsedFunction<3>>(3))
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
      prm.add_parameter("Line load boundaries",
                        line_load_text,
                        "Boundary ids carrying the dead line load.",
                        Patterns::List(Patterns::Integer(0)));
      declare_function(prm, "Line load", 3, "0; 0; 0");
      prm.leave_subsection();
    }

    void
    Loads::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Loads");
      parse_function(prm, *pressure_function, "Pressure", "Loads/Pressure");
      const auto pr =
        parse_id_list(pressure_regions_text, "Loads/Pressure regions");
      pressure_ids = std::set<types::material_id>(pr.begin(), pr.end());
      parse_function(prm,
                     *gravity_function,
                     "Gravity vector",
                     "Loads/Gravity vector");
      parse_function(prm,
                     *surface_function,
                     "Surface traction",
                     "Loads/Surface traction");
      const auto ll =
        parse_id_list(line_load_text, "Loads/Line load boundaries");
      line_load_ids = std::set<types::boundary_id>(ll.begin(), ll.end());
      parse_function(prm, *line_function, "Line load", "Loads/Line load");
      prm.leave_subsection();
    }

    double
    Loads::pressure(const Point<3> &x, const double t) const
    {
      pressure_function->set_time(t);
      return pressure_function->value(x);
    }

    bool
    Loads::pressure_acts_on(const types::material_id id) const
    {
      return pressure_ids.empty() || pressure_ids.count(id) > 0;
    }

    namespace
    {
      Tensor<1, 3>
      vector_value(Functions::ParsedFunction<3> &f,
                   const Point<3>               &x,
                   const double                  t)
      {
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
  } // namespace loads
} // namespace pneuma
