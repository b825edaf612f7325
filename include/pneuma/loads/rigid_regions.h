#pragma once

/**
 * @file
 * Rigid plates: a planar region of the membrane mesh (such as a steel end
 * plate) whose points follow the motion of three of its nodes A, B, C,
 * \f$u(X) = w_A(X)\,u_A + w_B(X)\,u_B + w_C(X)\,u_C\f$ with the barycentric
 * weights of X in the reference triangle ABC. Because X is an affine
 * combination of A, B, C in the plate plane, this is exact for rigid-body
 * motions of any size (large rotations) and keeps the plate planar; the
 * remaining in-plane stretch of ABC is resisted by the plate's own material
 * (a steel plate is practically rigid). The constraints are linear in u, so
 * they are fixed AffineConstraints. A is the vertex nearest the plate
 * centroid (supports go there), B the vertex farthest from A, C the vertex
 * that makes ABC largest. Pressure on the plate reaches A, B, C.
 */

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <set>
#include <vector>

namespace pneuma
{
  namespace loads
  {
    using namespace dealii;

    /// "Boundary conditions/Rigid regions".
    class RigidRegions
    {
    public:
      /// Declare the entry, bound to this object (which must outlive the
      /// parsing of @p prm).
      void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// True if no region is rigid (nothing to do).
      bool
      empty() const
      {
        return region_ids.empty();
      }

      /**
       * The dofs of the master nodes of all plates; every rank must treat
       * them as locally relevant.
       */
      IndexSet
      master_dofs(const Mapping<2, 3>    &mapping,
                  const DoFHandler<2, 3> &dof_handler);

      /// Add the plate constraints (call master_dofs() first).
      void
      add_constraints(const Mapping<2, 3>       &mapping,
                      const DoFHandler<2, 3>    &dof_handler,
                      AffineConstraints<double> &constraints) const;

      /// Material ids of all rigid regions.
      std::set<types::material_id>
      all_ids() const
      {
        std::set<types::material_id> ids;
        for (const auto &plate : region_ids)
          ids.insert(plate.begin(), plate.end());
        return ids;
      }

      /// The master dofs of all plates (the same list on every rank).
      std::vector<types::global_dof_index>
      plate_master_dofs() const
      {
        std::vector<types::global_dof_index> result;
        for (const auto &plate : plates)
          result.insert(result.end(),
                        plate.master_dofs.begin(),
                        plate.master_dofs.end());
        return result;
      }

      /// The slave dofs added by add_constraints (locally relevant ones).
      const std::set<types::global_dof_index> &
      slave_dofs() const
      {
        return slaves;
      }

    private:
      struct Plate
      {
        std::set<types::material_id>           ids;
        std::array<Point<3>, 3>                masters;
        std::array<types::global_dof_index, 9> master_dofs;
      };
      /// Entry "Rigid regions" as given (empty by default).
      std::string                               text;
      std::vector<std::set<types::material_id>> region_ids;
      std::vector<Plate>                        plates;
      mutable std::set<types::global_dof_index> slaves;
    };
  } // namespace loads
} // namespace pneuma
