#pragma once

/**
 * @file
 * Gershgorin's bound on the stiffness of the model's last assembled
 * tangent, for the strategies that move with a diagonal mass (dynamic
 * relaxation's fictitious mass, explicit dynamics' stable time step): the
 * largest eigenvalue of \f$M^{-1}K\f$ with a diagonal \f$M\f$ is at most
 * \f$\max_i \sum_j |K_{ij}| / M_i\f$.
 */

#include <pneuma/core/linear_algebra.h>

namespace pneuma
{
  class Model;

  namespace strategies
  {
    /**
     * The row sums \f$\sum_j |K_{ij}|\f$ of the field block of the tangent
     * last assembled by @p model, plus the stiffness its border unknowns
     * add once they follow the field (a gas chamber's volume stiffness
     * \f$B D^{-1} C^T\f$), bounded by \f$\sum_{kl} |B_{ik}|\,|D^{-1}_{kl}|\,
     * |C_l|_1\f$. Owned entries.
     */
    LA::Vector
    stiffness_row_sums(const Model &model);
  } // namespace strategies
} // namespace pneuma
