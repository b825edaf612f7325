#pragma once

/**
 * @file
 * Residual and consistent tangent of the finite-strain membrane with its
 * loads (doc/theory.md, sections "Weak form" and "Follower pressure").
 *
 * Residual: \f$r_i = \int_{\Omega_0} H S_{\alpha\beta}\, a_\alpha\cdot
 * \partial_\beta N_i\,dA - \int p\,(a_1\times a_2)\cdot N_i\,dA
 * - \int (\rho H g + t_0)\cdot N_i\,dA - \int_{\Gamma} q_0\cdot N_i\,dL\f$.
 * Tangent: material part \f$B_i:\mathbb{D}:B_j\f$ with
 * \f$B_i = \mathrm{sym}(a_\alpha\cdot\partial_\beta N_i)\f$, geometric
 * part \f$\partial_\alpha N_i\,S_{\alpha\beta}\,\partial_\beta N_j\f$, and
 * the follower-pressure load stiffness
 * \f$-p N_i\,(\partial_1 N_j\times a_2 + a_1\times\partial_2 N_j)\f$.
 */

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/core/local_access.h>
#include <pneuma/core/matrix_positions.h>
#include <pneuma/geometry/scene_generator.h>
#include <pneuma/loads/loads.h>
#include <pneuma/membrane/cell_terms.h>
#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/membrane/reference_geometry.h>

#include <map>
#include <memory>
#include <vector>

namespace pneuma
{
  namespace membrane
  {
    using namespace dealii;

    /// What the caller wants from one pass over the cells.
    struct AssemblyRequest
    {
      /// Pseudo time at which loads are evaluated.
      double time = 0.;
      /// Residual r = f_int - f_ext (owned, compressed), or nullptr.
      LA::Vector *residual = nullptr;
      /// Tangent dr/du, or nullptr.
      LA::SparseMatrix *tangent = nullptr;
      /// External load vector f_ext (owned), or nullptr.
      LA::Vector *external = nullptr;
      /**
       * Further terms of the same cells (the chambers' wall loads), added
       * to the cell matrix and residual before they are distributed once,
       * in this order.
       */
      std::vector<CellTerms *> cell_terms;
    };

    /// Assembles the membrane with its loads on a distributed mesh.
    class MembraneAssembler
    {
    public:
      MembraneAssembler(const geometry::SceneGenerator &geometry,
                        const MaterialRegions          &materials,
                        const loads::Loads             &loads);

      /// Set the discretisation used by all later calls.
      void
      reinit(const Mapping<2, 3>    &mapping,
             const DoFHandler<2, 3> &dof_handler,
             const unsigned int      degree);

      /// Add the terms at the ghosted displacement @p u to the targets of
      /// @p request (the caller zeroes them).
      void
      assemble(const LA::Vector                &u,
               const AffineConstraints<double> &constraints,
               const AssemblyRequest           &request) const;

      /**
       * Vector surface Laplacian L_ij = int grad_S N_i . grad_S N_j dA (same
       * component), the geometric stiffness of a unit isotropic prestress;
       * Newton's regularisation.
       */
      void
      surface_laplacian(const AffineConstraints<double> &constraints,
                        LA::SparseMatrix                &L) const;

      /**
       * Consistent mass M_ij = int rho h N_i . N_j dA over the reference
       * surface (rho and h of each cell's material region), the membrane's
       * part of the eigen analysis' mass matrix.
       */
      void
      mass_matrix(const AffineConstraints<double> &constraints,
                  LA::SparseMatrix                &M) const;
      /// The lumped mass: the row sums of mass_matrix() into @p m (added,
      /// owned entries; no constraints).
      void
      lumped_mass(LA::Vector &m) const;

      /// Volume enclosed by the current surface, V = 1/3 int x.n da.
      double
      enclosed_volume(const LA::Vector &u) const;

      /// Area of the deformed surface at @p u (ghosted), over the ranks.
      double
      surface_area(const LA::Vector &u) const;

      /**
       * Form finding (strategies/form_finding/form_finding.h): the laws of @p
       * laws replace the regions' and no load acts; an empty map restores the
       * analysis.
       */
      void
      set_form_finding(std::map<types::material_id, RegionMaterial> laws)
      {
        form_finding_laws = std::move(laws);
      }

      /**
       * The materials of @p laws (each region's with its plain law, no
       * tension field: a slack or wrinkled point as stiff as a taut one)
       * replace the regions' while loads act as usual; an empty map
       * restores them. For dynamic relaxation's mass.
       */
      void
      set_plain_laws(std::map<types::material_id, RegionMaterial> laws)
      {
        plain_laws = std::move(laws);
      }

      /// The reference data of the current mesh (built at first use; the
      /// chambers integrate their wall terms on it).
      const ReferenceGeometry &
      reference_geometry() const;

    private:
      /// The material a cell of material @p id is assembled with: the
      /// form finding's (not @p loaded), the region's, or its plain law
      /// (set_plain_laws()).
      const RegionMaterial &
      cell_material(const types::material_id id, const bool loaded) const;

      const geometry::SceneGenerator              &geometry;
      const MaterialRegions                       &materials;
      const loads::Loads                          &loads;
      const Mapping<2, 3>                         *mapping     = nullptr;
      const DoFHandler<2, 3>                      *dof_handler = nullptr;
      unsigned int                                 degree      = 1;
      std::map<types::material_id, RegionMaterial> form_finding_laws;
      std::map<types::material_id, RegionMaterial> plain_laws;
      mutable std::unique_ptr<ReferenceGeometry>   reference;
      mutable LA::MatrixPositions                  positions;
      /// Local indices of the cells' dofs in the ghosted displacement.
      mutable LA::GhostedIndices ghosted_indices;
    };
  } // namespace membrane
} // namespace pneuma
