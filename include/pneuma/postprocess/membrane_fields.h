#pragma once

/**
 * @file
 * Derived membrane fields for VTU output, as cell averages over the
 * quadrature points: Cauchy membrane forces per current length (tensor
 * entries, principal values and directions), principal Green-Lagrange
 * strains, and the thickness stretch lambda_3 = h/H; where a region
 * wrinkles (membrane/tension_field.h) also the fractions of the cell's
 * area that are wrinkled and slack, the wrinkling state that covers most
 * of the cell (0 taut, 1 wrinkled, 2 slack), the direction of the
 * wrinkles' crests (the tension) and the relaxed compression (the smaller
 * principal membrane force H S_2 [N/m, per reference length] the plain law
 * would carry).
 *
 * The wrinkled and slack areas have one definition, by quadrature point
 * (cell_wrinkling()): each point of the cell's Gauss rule is taut,
 * wrinkled or slack, and carries its reference area JxW. summary.json's
 * wrinkled_area and slack_area are their sums over all cells; the VTU's
 * wrinkled_fraction and slack_fraction are each cell's sums over its
 * reference area, so that summing fraction times cell area gives
 * summary.json's numbers.
 *
 * Every field is evaluated at the assembly's Gauss points with the strains
 * the assembly uses: a cell with assumed membrane strains
 * (membrane/assumed_strains.h) takes them, in the assembly's frame.
 */

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/geometry/scene_generator.h>
#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/membrane/reference_geometry.h>

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

    /**
     * The membrane kinematics of a cell's Gauss points as the assembly
     * sees them: the deformed tangents a_alpha of a material frame and
     * C, from the displacement gradients, or where the cell has assumed
     * strains (@p reference's tying()) C from those, in its frame.
     */
    class CellKinematics
    {
    public:
      CellKinematics(const Mapping<2, 3>               &mapping,
                     const DoFHandler<2, 3>            &dof_handler,
                     const membrane::ReferenceGeometry &reference);

      /// At the locally owned @p cell, @p warp its region's warp.
      void
      reinit(const DoFHandler<2, 3>::active_cell_iterator &cell,
             const LA::Vector                             &u,
             const Tensor<1, 3>                           &warp);

      unsigned int
      n_points() const
      {
        return quadrature.size();
      }
      double
      JxW(const unsigned int q) const
      {
        return fe_values.JxW(q);
      }
      const std::array<Tensor<1, 3>, 2> &
      tangents(const unsigned int q) const
      {
        return a[q];
      }
      const SymmetricTensor<2, 2> &
      C(const unsigned int q) const
      {
        return C_q[q];
      }

    private:
      const QGauss<2>                          quadrature;
      FEValues<2, 3>                           fe_values;
      const membrane::ReferenceGeometry       &reference;
      std::vector<int>                         owned_index;
      std::vector<Tensor<2, 3>>                grad_u;
      std::vector<std::array<double, 3>>       u_node;
      std::vector<std::array<Tensor<1, 3>, 2>> a;
      std::vector<SymmetricTensor<2, 2>>       C_q;
      membrane::TyingState                     tying;
    };

    /// The wrinkling of one cell, by quadrature point.
    struct CellWrinkling
    {
      /// Reference areas [m^2] of the taut, wrinkled and slack points.
      std::array<double, 3> areas{{0., 0., 0.}};
      /// The tension direction (current), summed over the wrinkled points
      /// with their areas, sign-aligned; zero if none is wrinkled.
      Tensor<1, 3> direction;
      /// The integral of the relaxed compression H min(S_2, 0) [N].
      double compression = 0.;
      /// The least minor principal force H S_2 [N/m] of the plain law.
      double minor_force = 0.;
    };

    /**
     * The wrinkling of the cell @p points is initialized on (its region's
     * @p material has a tension field): the one definition of the
     * wrinkled and slack areas that summary.json and the VTU share.
     */
    CellWrinkling
    cell_wrinkling(const CellKinematics           &points,
                   const membrane::RegionMaterial &material);

    /// Compute the membrane cell fields at the ghosted displacement @p u.
    CellFields
    membrane_cell_fields(const Mapping<2, 3>               &mapping,
                         const DoFHandler<2, 3>            &dof_handler,
                         const membrane::ReferenceGeometry &reference,
                         const membrane::MaterialRegions   &materials,
                         const geometry::SceneGenerator    &geometry,
                         const LA::Vector                  &u);

    /**
     * The membrane (in-plane) strain energy int H W(C) dA [J] of this
     * rank's cells at the ghosted displacement @p u: each region's law as
     * the assembly integrates it (wrinkling and prestress included), at
     * the assembly's Gauss points.
     */
    double
    membrane_strain_energy(const Mapping<2, 3>               &mapping,
                           const DoFHandler<2, 3>            &dof_handler,
                           const membrane::ReferenceGeometry &reference,
                           const membrane::MaterialRegions   &materials,
                           const geometry::SceneGenerator    &geometry,
                           const LA::Vector                  &u);

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
    wrinkling_summary(const Mapping<2, 3>               &mapping,
                      const DoFHandler<2, 3>            &dof_handler,
                      const membrane::ReferenceGeometry &reference,
                      const membrane::MaterialRegions   &materials,
                      const geometry::SceneGenerator    &geometry,
                      const LA::Vector                  &u);
  } // namespace postprocess
} // namespace pneuma
