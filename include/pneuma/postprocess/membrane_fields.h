#pragma once

/**
 * @file
 * Derived membrane fields for VTU output, as cell averages over the
 * quadrature points: Cauchy membrane forces per current length (tensor
 * entries, principal values and directions), principal Green-Lagrange
 * strains, and the thickness stretch lambda_3 = h/H; where a region
 * wrinkles (membrane/tension_field.h) also the wrinkling state that covers
 * most of the cell (0 taut, 1 wrinkled, 2 slack), the direction of the
 * wrinkles' crests (the tension) and the relaxed compression (the smaller
 * principal membrane force H S_2 [N/m, per reference length] the plain law
 * would carry).
 */

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/geometry/scene_generator.h>
#include <pneuma/membrane/constitutive_law.h>

#include <array>
#include <string>
#include <vector>

namespace pneuma
{
  namespace postprocess
  {
    using namespace dealii;

    /// The in-plane principal membrane forces of a membrane force tensor.
    struct PrincipalForces
    {
      /// N1 >= N2 [N/m] and their unit directions.
      double       N1 = 0., N2 = 0.;
      Tensor<1, 3> direction_1, direction_2;
    };

    /// The principal forces of @p n in the surface of normal @p normal
    /// (the eigenvector along the normal dropped).
    PrincipalForces
    in_plane_principal(const SymmetricTensor<2, 3> &n,
                       const Tensor<1, 3>          &normal);

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
                         const geometry::SceneGenerator  &geometry,
                         const LA::Vector                &u);

    /// The wrinkling of the regions that wrinkle, over all ranks.
    struct WrinklingSummary
    {
      /// Reference areas [m^2] of the taut, wrinkled and slack points.
      std::array<double, 3> areas{{0., 0., 0.}};
      /// The least minor principal force H S_2 [N/m] of the plain law at
      /// any point: it crosses zero where wrinkling starts.
      double minor_force = 0.;
    };

    /// The wrinkling summary at the ghosted displacement @p u.
    WrinklingSummary
    wrinkling_summary(const Mapping<2, 3>             &mapping,
                      const DoFHandler<2, 3>          &dof_handler,
                      const membrane::MaterialRegions &materials,
                      const geometry::SceneGenerator  &geometry,
                      const LA::Vector                &u);
  } // namespace postprocess
} // namespace pneuma
