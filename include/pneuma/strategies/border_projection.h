#pragma once

/**
 * @file
 * Constraints on the field held by border multipliers (BorderConstraint,
 * core/capabilities.h: a gas chamber's prescribed volume V(u) = V(t), held
 * by its pressure) in a strategy that moves the field with a diagonal mass
 * (doc/theory.md "Explicit dynamics", "Prescribed volumes").
 *
 * The step has moved the field to \f$u^*\f$ by an update in which the
 * residual \f$r(u_n, \lambda)\f$ entered as \f$-a M^{-1} r\f$ (central
 * differences: \f$a = \Delta t\,\Delta t_n / (1 + \alpha \Delta t_n/2)\f$).
 * A change \f$\delta\lambda\f$ of the multipliers changes the residual by
 * \f$B\,\delta\lambda\f$ (\f$B_j = \partial r/\partial\lambda_j\f$, for a
 * pressure \f$-q\f$, \f$q = \partial V/\partial u\f$) and so moves the new
 * field by \f$W\delta\lambda\f$, \f$W_j = -a M^{-1} B_j\f$. The increments
 * solve \f$g(u^* + W\delta\lambda, t_{n+1}) = 0\f$ by Newton iterations
 * starting with \f$S = C^T W\f$ (\f$C_j = \partial g_j/\partial u\f$ at
 * \f$u_n\f$), \f$S\,\Delta(\delta\lambda) = -g\f$, and updating S by
 * Broyden's rule after each evaluation. For one chamber \f$S = a\,q^T
 * M^{-1} q > 0\f$. In a time step q barely changes: two or three volume
 * evaluations take the constraint to round-off at every step, so the
 * volume never drifts; a large jump (a relaxation's first step to a new
 * volume) takes a few more. This is the
 * SHAKE/RATTLE projection of constrained molecular dynamics (Ryckaert,
 * Ciccotti & Berendsen 1977) with the volume as the constraint.
 */

#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/solvers/bordered_vector.h>

#include <string>
#include <vector>

namespace pneuma
{
  class Model;

  namespace strategies
  {
    /// What a projection changed.
    struct BorderProjection
    {
      /// The constraint rows of the border and the multipliers' increments
      /// (physical units); empty: the model has no constraint rows now.
      std::vector<unsigned int> rows;
      std::vector<double>       increments;
      /// W delta lambda on the free dofs (the velocity's change times the
      /// step) and distributed to the dependent ones (the field's change).
      LA::Vector free_change, field_change;
      /// The largest |g_j| / scale_j after the projection.
      double       error       = 0.;
      unsigned int evaluations = 0;
    };

    /**
     * The border of @p x at @p t for its field (Model::border_for()), and,
     * where the model has constraint rows, the multipliers and the field
     * moved along W (above) with @p inverse_mass and @p a until the
     * constraints hold to round-off. The B and C blocks are the model's
     * last assembly's (of the state the step started from). Returns "" or
     * why the constraints cannot be held.
     */
    std::string
    project_border(Model                   &model,
                   solvers::BorderedVector &x,
                   const double             t,
                   const LA::Vector        &inverse_mass,
                   const double             a,
                   BorderProjection        &projection);
  } // namespace strategies
} // namespace pneuma
