#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/error_estimator.h>

#include <pneuma/geometry/adaptive_refinement.h>
#include <pneuma/geometry/junctions.h>

#include <array>
#include <vector>

namespace pneuma
{
  namespace geometry
  {
    namespace
    {
      using Tria = parallel::distributed::Triangulation<2, 3>;

      /// The junction edges of the locally owned active cells: the cell and
      /// the edge's two vertices.
      struct JunctionEdge
      {
        Tria::active_cell_iterator cell;
        Point<3>                   a, b;
      };

      std::vector<JunctionEdge>
      owned_junction_edges(const Tria &triangulation)
      {
        std::vector<JunctionEdge> edges;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary()
                  && cell->face(f)->boundary_id() == junction_boundary_id)
                edges.push_back(
                  {cell, cell->face(f)->vertex(0), cell->face(f)->vertex(1)});
        return edges;
      }

      /// The edges @p mine of every rank, as 6 numbers each.
      std::vector<std::array<Point<3>, 2>>
      gather(const std::vector<JunctionEdge> &mine, const MPI_Comm comm)
      {
        std::vector<double> local;
        for (const auto &e : mine)
          local.insert(local.end(),
                       {e.a[0], e.a[1], e.a[2], e.b[0], e.b[1], e.b[2]});
        std::vector<std::array<Point<3>, 2>> all;
        for (const auto &part : Utilities::MPI::all_gather(comm, local))
          for (unsigned int k = 0; k + 5 < part.size(); k += 6)
            all.push_back({{Point<3>(part[k], part[k + 1], part[k + 2]),
                            Point<3>(part[k + 3], part[k + 4], part[k + 5])}});
        return all;
      }

      /// True if @p g is a piece of a finer copy of the edge (@p a, @p b):
      /// it starts at a or b, is at most 3/4 as long and runs along it
      /// (within 18 degrees: a child's chord on a curved line turns by a
      /// quarter of the parent's arc).
      bool
      finer_copy(const Point<3>                &a,
                 const Point<3>                &b,
                 const std::array<Point<3>, 2> &g,
                 const double                   tolerance)
      {
        const double length = a.distance(b);
        for (const auto &[p, q] : {std::make_pair(a, b), std::make_pair(b, a)})
          for (unsigned int k = 0; k < 2; ++k)
            if (g[k].distance(p) <= tolerance)
              {
                const Tensor<1, 3> child  = g[1 - k] - p;
                const Tensor<1, 3> parent = q - p;
                if (child.norm() <= 0.75 * length
                    && child * parent >= 0.95 * child.norm() * parent.norm())
                  return true;
              }
        return false;
      }
    } // namespace

    void
    AdaptiveRefinement::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Adaptive refinement");
      prm.add_parameter("Cycles",
                        n_cycles,
                        "Refinement cycles after the first run: each ranks "
                        "the cells by Kelly's indicator of the final "
                        "displacement, refines a fraction of them and runs "
                        "the load path again. Outputs go to "
                        "Output/Directory/cycle-<k>, a table of all cycles "
                        "to Output/Directory/refinement.csv.",
                        Patterns::Integer(0, 20));
      prm.add_parameter("Refine fraction",
                        refine_fraction,
                        "Fraction of the cells (largest indicators) refined "
                        "in each cycle.",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Coarsen fraction",
                        coarsen_fraction,
                        "Fraction of the cells (smallest indicators) "
                        "coarsened in each cycle.",
                        Patterns::Double(0., 1.));
      prm.leave_subsection();
    }

    void
    AdaptiveRefinement::parse_parameters(ParameterHandler &)
    {
      // Every entry is bound by declare_parameters().
    }

    void
    AdaptiveRefinement::refine(
      const Mapping<2, 3>                        &mapping,
      const DoFHandler<2, 3>                     &dof_handler,
      const LA::Vector                           &displacement,
      parallel::distributed::Triangulation<2, 3> &triangulation) const
    {
      Vector<float> indicators(triangulation.n_active_cells());
      KellyErrorEstimator<2, 3>::estimate(mapping,
                                          dof_handler,
                                          QGauss<1>(dof_handler.get_fe().degree
                                                    + 1),
                                          {},
                                          displacement,
                                          indicators);
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        triangulation, indicators, refine_fraction, coarsen_fraction);
      const MPI_Comm comm     = triangulation.get_communicator();
      auto           junction = owned_junction_edges(triangulation);
      if (Utilities::MPI::sum(junction.size(), comm) == 0)
        {
          triangulation.execute_coarsening_and_refinement();
          return;
        }
      double size = 0.;
      for (const auto &e : junction)
        size = std::max(size, e.a.distance(e.b));
      const double tolerance = 1e-8 * Utilities::MPI::max(size, comm);
      // Cells at a junction keep their level unless all copies refine.
      std::vector<JunctionEdge> flagged;
      for (const auto &e : junction)
        {
          e.cell->clear_coarsen_flag();
          if (e.cell->refine_flag_set())
            flagged.push_back(e);
        }
      const auto to_refine = gather(flagged, comm);
      for (const auto &e : junction)
        for (const auto &g : to_refine)
          if ((g[0].distance(e.a) <= tolerance
               && g[1].distance(e.b) <= tolerance)
              || (g[0].distance(e.b) <= tolerance
                  && g[1].distance(e.a) <= tolerance))
            e.cell->set_refine_flag();
      triangulation.execute_coarsening_and_refinement();
      // p4est's 2:1 balance may have refined one copy only: refine the
      // coarser copies until every copy of every junction edge agrees
      // (each pass refines, so it ends; a level per pass at most).
      for (unsigned int pass = 0; pass < 32; ++pass)
        {
          junction         = owned_junction_edges(triangulation);
          const auto   all = gather(junction, comm);
          unsigned int n   = 0;
          for (const auto &e : junction)
            for (const auto &g : all)
              if (finer_copy(e.a, e.b, g, tolerance))
                {
                  e.cell->set_refine_flag();
                  ++n;
                  break;
                }
          if (Utilities::MPI::sum(n, comm) == 0)
            return;
          triangulation.execute_coarsening_and_refinement();
        }
      AssertThrow(false,
                  ExcMessage("the junction copies could not be refined alike"));
    }
  } // namespace geometry
} // namespace pneuma
