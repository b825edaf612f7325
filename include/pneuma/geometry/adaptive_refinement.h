#pragma once

/**
 * @file
 * Adaptive refinement for convergence studies: the whole load path is run,
 * the cells are ranked by Kelly's error indicator of the final displacement
 * (the jump of its surface gradient across cell edges, weighted by the edge
 * length: Kelly, Gago, Zienkiewicz, Babuska 1983), a fixed fraction is
 * refined (p4est keeps neighbours within one level, hanging nodes are
 * constrained), and the load path is run again on the new mesh. Every
 * cycle writes its own outputs (doc/user-guide.md "Adaptive refinement").
 */

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <pneuma/core/linear_algebra.h>

namespace pneuma
{
  namespace geometry
  {
    using namespace dealii;

    /// "Adaptive refinement" subsection and one refinement of the mesh.
    class AdaptiveRefinement
    {
    public:
      /// Declare the entries, bound to this object (which must outlive the
      /// parsing of @p prm).
      void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Number of refinement cycles after the first run (0: none).
      unsigned int
      cycles() const
      {
        return n_cycles;
      }

      /**
       * Mark the cells by Kelly's indicator of the displacement
       * @p displacement (ghosted) and refine (and coarsen) the fixed
       * fractions of them; cells whose indicators are equal to the
       * threshold's up to 1e-5 are refined alike (mark_fixed_number()).
       *
       * On a mesh with junction lines (geometry/junctions.h) every copy of
       * a junction edge is refined alike, so that the new vertices on it
       * exist on every side and are tied again: a refine flag on a cell at
       * a junction is given to the cells of the other copies of that edge,
       * cells at a junction are not coarsened, and after the refinement
       * (whose 2:1 balance may refine one side only) a cell whose junction
       * edge is coarser than another copy of it is refined until all
       * copies agree.
       */
      void
      refine(const Mapping<2, 3>                        &mapping,
             const DoFHandler<2, 3>                     &dof_handler,
             const LA::Vector                           &displacement,
             parallel::distributed::Triangulation<2, 3> &triangulation) const;

    private:
      /**
       * Flag the locally owned cells by the fixed numbers of the fractions:
       * the cells with the largest (smallest) @p indicators, and with them
       * every cell whose indicator is within a relative 1e-5 of the last
       * one taken (doc/theory.md §4.2), so that cells that are equal up to
       * round-off are refined alike on every machine and thread count.
       * The thresholds are exact order statistics of the indicators of all
       * ranks.
       */
      void
      mark_fixed_number(
        const Vector<float>                        &indicators,
        parallel::distributed::Triangulation<2, 3> &triangulation) const;

      /// Entries "Cycles", "Refine fraction", "Coarsen fraction".
      unsigned int n_cycles         = 0;
      double       refine_fraction  = 0.3;
      double       coarsen_fraction = 0.;
    };
  } // namespace geometry
} // namespace pneuma
