#include <deal.II/lac/full_matrix.h>

#include <pneuma/core/capabilities.h>
#include <pneuma/core/model.h>
#include <pneuma/solvers/border.h>
#include <pneuma/strategies/border_projection.h>

#include <cmath>
#include <sstream>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;

    namespace
    {
      /// The largest |g_j| / scale_j.
      double
      largest_error(const std::vector<BorderConstraint> &constraints)
      {
        double error = 0.;
        for (const auto &c : constraints)
          error = std::max(error, std::abs(c.value) / std::abs(c.scale));
        return error;
      }

      /// The directions W_j = -a M^-1 B_j of the constraint rows (free
      /// dofs only) and S = C^T W; "" or why S is singular.
      std::string
      directions(const solvers::BorderCoupling       &coupling,
                 const std::vector<BorderConstraint> &constraints,
                 const LA::Vector                    &inverse_mass,
                 const double                         a,
                 std::vector<LA::Vector>             &W,
                 FullMatrix<double>                  &S)
      {
        const unsigned int n = constraints.size();
        W.assign(n, inverse_mass);
        S.reinit(n, n);
        for (unsigned int k = 0; k < n; ++k)
          {
            const unsigned int j = constraints[k].row;
            if (!coupling.has_B[j] || !coupling.has_C[j])
              return "border row " + std::to_string(j)
                     + " is a constraint without a field coupling";
            W[k].scale(coupling.B[j]);
            W[k] *= -a;
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int k = 0; k < n; ++k)
            S(i, k) = coupling.C[constraints[i].row] * W[k];
        for (unsigned int i = 0; i < n; ++i)
          if (!(std::abs(S(i, i)) > 0.))
            return "the constraint of border row "
                   + std::to_string(constraints[i].row)
                   + " does not depend on the free unknowns";
        return "";
      }

      /// step = -S^-1 g; false if S is singular.
      bool
      solve(const FullMatrix<double> &S,
            const Vector<double>     &g,
            Vector<double>           &step)
      {
        FullMatrix<double> S_inverse(S);
        S_inverse.gauss_jordan();
        S_inverse.vmult(step, g);
        step *= -1.;
        for (const double s : step)
          if (!std::isfinite(s))
            return false;
        return true;
      }
    } // namespace

    std::string
    project_border(Model                   &model,
                   solvers::BorderedVector &x,
                   const double             t,
                   const LA::Vector        &inverse_mass,
                   const double             a,
                   BorderProjection        &projection)
    {
      std::vector<BorderConstraint> constraints;
      Vector<double>                border =
        model.border_for(x.field, t, x.border, constraints);
      projection.rows.clear();
      projection.increments.clear();
      projection.error       = largest_error(constraints);
      projection.evaluations = 1;
      if (constraints.empty())
        {
          x.border = border;
          return "";
        }
      std::vector<LA::Vector> W;
      FullMatrix<double>      S;
      const std::string       error = directions(
        model.last_border_coupling(), constraints, inverse_mass, a, W, S);
      if (!error.empty())
        return error;
      const unsigned int n = constraints.size();
      for (const auto &c : constraints)
        projection.rows.push_back(c.row);
      projection.increments.assign(n, 0.);
      projection.free_change.reinit(inverse_mass);
      projection.field_change.reinit(inverse_mass);
      // Newton on g(delta lambda) with S updated by Broyden's rule (the
      // volume is a cubic of the positions: in a small step S barely
      // changes; a large one, a relaxation's first, needs the update):
      // at most 12 evaluations, to round-off.
      constexpr double       tolerance = 1e-14;
      constexpr unsigned int most      = 12;
      Vector<double>         g(n), step(n), g_new(n), S_step(n);
      for (unsigned int k = 0; k < n; ++k)
        g[k] = constraints[k].value;
      LA::Vector change(inverse_mass);
      while (projection.error > tolerance && projection.evaluations < most)
        {
          if (!solve(S, g, step))
            return "the border constraints are not independent";
          change = 0.;
          for (unsigned int k = 0; k < n; ++k)
            {
              change.add(step[k], W[k]);
              projection.increments[k] += step[k];
              x.border[constraints[k].row] += step[k] / constraints[k].unit;
            }
          projection.free_change += change;
          // The dependent dofs follow their masters.
          model.distribute_increment(change);
          projection.field_change += change;
          x.field += change;
          border = model.border_for(x.field, t, x.border, constraints);
          projection.error = largest_error(constraints);
          ++projection.evaluations;
          // Broyden: S += (dg - S step) step^T / |step|^2.
          for (unsigned int k = 0; k < n; ++k)
            g_new[k] = constraints[k].value;
          S.vmult(S_step, step);
          const double step_norm = step.norm_sqr();
          if (step_norm > 0.)
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int k = 0; k < n; ++k)
                S(i, k) += (g_new[i] - g[i] - S_step[i]) * step[k] / step_norm;
          g = g_new;
        }
      x.border = border;
      return "";
    }
  } // namespace strategies
} // namespace pneuma
