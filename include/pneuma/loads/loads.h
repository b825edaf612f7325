#pragma once

/**
 * @file
 * The loads on the membrane, all functions of the reference position
 * (x, y, z) and of the pseudo time t (load curves, several stages in
 * sequence): follower pressure on the current surface, gravity, dead surface
 * and line loads.
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace pneuma
{
  namespace loads
  {
    using namespace dealii;

    /**
     * "Loads" subsection. The pressure p(x,t) acts along the outward normal
     * of the current surface (a follower load, virtual work
     * \f$\int p\,n\cdot\delta u\,da\f$) on the regions listed in "Pressure
     * regions". Gravity acts on the mass rho H per reference area. The
     * surface load is a dead traction per reference area; the line load is a
     * dead force per reference length on the boundaries listed; point
     * loads are dead forces at the membrane vertices nearest to the points
     * listed.
     */
    class Loads
    {
    public:
      Loads();

      /// Declare the entries, bound to this object (which must outlive the
      /// parsing of @p prm).
      void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Why a membrane load is not finite at t = 0 at one of @p points
      /// (reference cell centres) or @p line_points (centres of line-load
      /// edges), as "parameter: what", or an empty string.
      std::string
      non_finite_at_start(const std::vector<Point<3>> &points,
                          const std::vector<Point<3>> &line_points) const;

      /// Follower pressure [Pa] at reference point @p x and pseudo time @p t.
      double
      pressure(const Point<3> &x, const double t) const;
      /// The pressure expression does not depend on x, y, z (it is
      /// evaluated once per assembly instead of per quadrature point).
      bool
      pressure_is_uniform() const
      {
        return pressure_uniform;
      }
      /// True if the pressure acts on cells of material @p material_id.
      bool
      pressure_acts_on(const types::material_id material_id) const;
      /// True if the surface load is on and acts on cells of material
      /// @p material_id ("Surface load regions").
      bool
      surface_load_acts_on(const types::material_id material_id) const;
      /**
       * Set the pseudo time @p t of the load functions before a cell loop
       * that runs on several threads: pressure(), surface_load() and
       * line_load() at this time then only read them (a time that differs
       * is set on the spot, for calls outside such a loop).
       */
      void
      set_time(const double t) const;
      /// Gravity vector [m/s^2] at pseudo time @p t.
      Tensor<1, 3>
      gravity(const double t) const;
      /// Dead surface traction [N/m^2 per reference area].
      Tensor<1, 3>
      surface_load(const Point<3> &x, const double t) const;
      /// Dead line load [N/m per reference length] on boundary @p id.
      Tensor<1, 3>
      line_load(const Point<3> &x, const double t) const;
      /// The dead point loads' points ("Point loads"), each loaded at the
      /// membrane vertex nearest to it.
      const std::vector<Point<3>> &
      point_load_points() const
      {
        return point_points;
      }
      /// Dead point load [N] at point @p x (one of point_load_points()).
      Tensor<1, 3>
      point_load(const Point<3> &x, const double t) const;

      bool
      has_gravity() const
      {
        return gravity_on;
      }
      const std::set<types::boundary_id> &
      line_load_boundaries() const
      {
        return line_load_ids;
      }
      const std::set<types::material_id> &
      pressure_regions() const
      {
        return pressure_ids;
      }
      const std::set<types::material_id> &
      surface_load_regions() const
      {
        return surface_ids;
      }

    private:
      /// The pressure expression does not use the position.
      bool                                          pressure_uniform = false;
      std::unique_ptr<Functions::ParsedFunction<3>> pressure_function;
      std::unique_ptr<Functions::ParsedFunction<3>> gravity_function;
      std::unique_ptr<Functions::ParsedFunction<3>> surface_function;
      std::unique_ptr<Functions::ParsedFunction<3>> line_function;
      std::unique_ptr<Functions::ParsedFunction<3>> point_function;
      /// Entry "Point loads" as given and its points.
      std::string           point_loads_text;
      std::vector<Point<3>> point_points;
      /// Entries "Pressure regions", "Surface load regions" and "Line
      /// load boundaries" as given, and the ids parsed from them.
      std::string pressure_regions_text, surface_regions_text, line_load_text;
      std::set<types::material_id> pressure_ids, surface_ids;
      std::set<types::boundary_id> line_load_ids;
      /// Entries "Gravity" and "Surface load".
      bool gravity_on = false, surface_load_on = false;
    };

    /// Declare a ParsedFunction subsection @p name of (x, y, z, t) with
    /// @p n_components and a default expression.
    void
    declare_function(ParameterHandler  &prm,
                     const std::string &name,
                     const unsigned int n_components,
                     const std::string &expression);

    /// Parse a ParsedFunction subsection, turning parser errors into a
    /// message that names the subsection; its constants must be finite,
    /// and with @p finite_at_origin (load curves of t alone) so must its
    /// values at t = 0.
    void
    parse_function(ParameterHandler             &prm,
                   Functions::ParsedFunction<3> &function,
                   const std::string            &name,
                   const std::string            &path,
                   const bool                    finite_at_origin = false);

    /// Why @p function is not finite at one of @p points (at its current
    /// time), or an empty string.
    std::string
    first_non_finite(const Functions::ParsedFunction<3> &function,
                     const std::vector<Point<3>>        &points);

    /// Parse "x, y, z" into a point; errors name @p path.
    Point<3>
    parse_point(const std::string &text, const std::string &path);

    /// Parse a comma separated list of non-negative ids.
    std::set<unsigned int>
    parse_id_list(const std::string &text, const std::string &path);
  } // namespace loads
} // namespace pneuma
