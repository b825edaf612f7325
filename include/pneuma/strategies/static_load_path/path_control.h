#pragma once

/**
 * @file
 * Path control of the static load path ("Load stepping/Path following";
 * doc/theory.md "Path following"): in a stage under arc-length or
 * displacement control the load factor is an unknown, bordered by one
 * constraint (solvers/path_following.h). This class holds the settings,
 * the monitored component, and the steps that only a path-controlled
 * stage has: the monitored component and the target, the constraint, the
 * stage's record (PathRecord). The steps of a path-controlled stage are
 * StaticLoadPath's (prediction.cc, judgement.cc, acceptance.cc).
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/solvers/bordered_vector.h>
#include <pneuma/solvers/path_following.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace pneuma
{
  class Model;

  namespace strategies
  {
    /// The monitored component w . u, or NaN without a monitor (w empty).
    inline double
    monitor_value(const LA::Vector &w, const LA::Vector &field)
    {
      return w.size() > 0 ? w * field
                          : std::numeric_limits<double>::quiet_NaN();
    }

    /// The path-controlled stage's record (part of the path's checkpoint).
    struct PathRecord
    {
      /// In a path-controlled stage (and which).
      bool         active = false;
      unsigned int stage  = 0;
      /// Its scales: |du/dtau|, |dR/dtau| and the monitor's rate at the
      /// stage's start.
      double u_scale = 1., force_scale = 1., monitor_rate = 1.;
      /// The arc length travelled, its steps, the last change of the load
      /// factor, and whether a limit point was reported since the load
      /// factor last turned.
      double       arc_length = 0., last_dtau = 0.;
      unsigned int steps              = 0;
      bool         limit_since_return = false;
      /// The next predictor is the secant (the last accepted step).
      bool secant = false;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &active &stage &u_scale &force_scale &monitor_rate &arc_length
          &last_dtau &steps &limit_since_return &secant;
      }
    };

    /// "Load stepping/Path following" and the steps of a followed path.
    class PathControl
    {
    public:
      /// A step forced to end exactly where a stage ends.
      enum class Forced
      {
        none,
        to_stage_end,
        to_target
      };

      /// Declare the entries of "Path following" (in the current
      /// subsection "Load stepping").
      void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Check them; @p last_is_path: the last stage is path-controlled.
      void
      parse_parameters(const bool last_is_path);

      /// The entry Monitor point.
      unsigned int
      monitor_point_index() const
      {
        return monitor_point;
      }

      /// InputError naming Monitor point (@p what needs it) unless it is
      /// one of the @p n_points monitor points.
      void
      check_monitor_point(const unsigned int n_points,
                          const std::string &what) const;

      /// The monitor functional w (w . u the monitored component) of
      /// @p model, or an empty vector without a monitor point.
      LA::Vector
      monitor_functional(const Model &model) const;

      bool
      has_target() const
      {
        return with_target;
      }
      double
      target() const
      {
        return target_value;
      }
      /// The spherical constraint's weight of the load factor (0:
      /// cylindrical).
      double
      psi2() const
      {
        return spherical ? 1. : 0.;
      }
      unsigned int
      max_steps() const
      {
        return max_path_steps;
      }
      bool
      stop_at_critical() const
      {
        return stop_at_critical_point;
      }

    private:
      /// Constraint: spherical (true) or cylindrical (false).
      bool         spherical         = false;
      unsigned int monitor_point     = 0;
      std::string  monitor_component = "z";
      std::string  target_text;
      double       target_value           = 0.;
      bool         with_target            = false;
      unsigned int max_path_steps         = 200;
      bool         stop_at_critical_point = false;
    };
  } // namespace strategies
} // namespace pneuma
