#pragma once

/**
 * @file
 * Prescribed displacements of the membrane: clamped edges and symmetry
 * planes (fixed components on boundary ids), supports at points (fixed
 * components at the mesh vertex nearest to a given point), fixed rigid
 * regions (every node of a material region held), and a prescribed
 * displacement function of (x, y, z, t) on boundary ids.
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <pneuma/core/linear_algebra.h>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <vector>

namespace pneuma
{
  namespace loads
  {
    using namespace dealii;

    /// "Boundary conditions" subsection.
    class BoundaryConditions
    {
    public:
      BoundaryConditions();

      /// Declare the entries, bound to this object (which must outlive the
      /// parsing of @p prm).
      void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Add the constraints for Newton updates (homogeneous: the update is
       * zero on every prescribed component) to @p constraints.
       */
      void
      add_update_constraints(
        const DoFHandler<2, 3>                     &dof_handler,
        const std::set<types::global_dof_index>    &rigid_slaves,
        const std::vector<types::global_dof_index> &rigid_masters,
        const std::set<types::global_dof_index>    &junction_copies,
        AffineConstraints<double>                  &constraints) const;

      /**
       * Write the prescribed values at pseudo time @p t into the owned
       * entries of @p solution (zero on fixed components).
       */
      void
      set_prescribed_values(const Mapping<2, 3>    &mapping,
                            const DoFHandler<2, 3> &dof_handler,
                            const double            t,
                            LA::Vector             &solution) const;

      /// Check that every named boundary or region exists in the mesh.
      void
      check_against_mesh(const DoFHandler<2, 3> &dof_handler) const;

      /// Material ids whose nodes are prescribed in every component (fixed
      /// or displaced).
      std::set<types::material_id>
      prescribed_regions() const
      {
        auto ids = displaced_regions;
        for (const auto &[id, mask] : fixed_regions)
          if (mask[0] && mask[1] && mask[2])
            ids.insert(id);
        return ids;
      }

      /// Boundary ids with a fixed or prescribed component.
      std::set<types::boundary_id>
      supported_boundaries() const
      {
        auto ids = displaced_boundaries;
        for (const auto &[id, mask] : fixed_boundaries)
          ids.insert(id);
        return ids;
      }

    private:
      /// Map of (prescribed dof, value at t) on the locally relevant dofs.
      std::map<types::global_dof_index, double>
      prescribed_dofs(const Mapping<2, 3>    &mapping,
                      const DoFHandler<2, 3> &dof_handler,
                      const double            t) const;

      /// The entries as given: "Fixed boundaries", "Fixed points", "Fixed
      /// regions", "Prescribed displacement boundaries" and "Prescribed
      /// displacement regions" (all empty by default).
      struct Text
      {
        std::string fixed_boundaries, fixed_points, fixed_regions,
          displaced_boundaries, displaced_regions;
      } text;
      /// What they hold.
      std::map<types::boundary_id, std::array<bool, 3>>     fixed_boundaries;
      std::vector<std::pair<Point<3>, std::array<bool, 3>>> fixed_points;
      std::map<types::material_id, std::array<bool, 3>>     fixed_regions;
      std::set<types::material_id>                          displaced_regions;
      std::set<types::boundary_id>                  displaced_boundaries;
      std::unique_ptr<Functions::ParsedFunction<3>> displacement_function;

      /**
       * Without prescribed displacements the supports hold the same dofs
       * at zero at every time: the owned ones are kept for the dof
       * numbering (number of dofs and cells) they were found for (finding
       * them searches every cell per fixed point: 4 % of an explicit
       * step). add_update_constraints() (a new mesh) forgets them.
       */
      struct HeldDofs
      {
        const DoFHandler<2, 3>              *dof_handler = nullptr;
        types::global_dof_index              n_dofs      = 0;
        types::global_cell_index             n_cells     = 0;
        std::vector<types::global_dof_index> owned;
      };
      mutable HeldDofs held;
    };
  } // namespace loads
} // namespace pneuma
