#pragma once

/**
 * @file
 * Derived membrane fields for VTU output, as cell averages over the
 * quadrature points: Cauchy membrane forces per current length (tensor
 * entries, principal values and directions), principal Green-Lagrange
 * strains, and the thickness stretch lambda_3 = h/H.
 */

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/membrane/constitutive_law.h>

#include <string>
#include <vector>

namespace pneuma
{
  namespace postprocess
  {
    using namespace dealii;

    /// Named cell-data vectors (one value per active cell).
    struct CellFields
    {
      std::vector<std::string>    names;
      std::vector<Vector<double>> values;
    };

    /// Compute the membrane cell fields at the ghosted displacement @p u.
    CellFields
    membrane_cell_fields(const Mapping<2, 3>             &mapping,
                         const DoFHandler<2, 3>          &dof_handler,
                         const membrane::MaterialRegions &materials,
                         const LA::Vector                &u);
  } // namespace postprocess
} // namespace pneuma
