#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/error_estimator.h>

#include <pneuma/core/input_error.h>
#include <pneuma/geometry/adaptive_refinement.h>
#include <pneuma/geometry/junctions.h>

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <vector>

namespace pneuma
{
  namespace geometry
  {
    namespace
    {
      using Tria = parallel::distributed::Triangulation<2, 3>;

      /**
       * Indicators within this fraction of the refinement (coarsening)
       * threshold count as equal to it, and are refined (coarsened) with
       * it. Kelly's indicator is a float computed from the converged
       * displacement: cells that a symmetry makes equal (the waterbeam's
       * mirror halves) differ by the round-off of the solve, which another
       * BLAS kernel or thread count changes, or are equal floats on one
       * machine and a few units in the last place apart on another. Ranked
       * by deal.II's bisection for the threshold, which cannot split such a
       * pair, one CPU refined one cell of it and another both (4536 or
       * 4548 cells in tests/waterbeam_junctions). The band is 150 float
       * units in the last place wide, far above that round-off, and far
       * below the accuracy of any error estimate: the nearest indicator
       * that is not tied lay 2.3e-4 (relative) from the threshold in every
       * cycle of that test. A cell's value must now lie within round-off
       * of the band's edge, not of the threshold, for the decision to
       * depend on the machine.
       */
      constexpr double tie_band = 1e-5;

      /**
       * The value of rank @p k (from 0) of the indicators @p mine of all
       * ranks, sorted by @p before (std::greater: from the largest). Exact:
       * the values are gathered on rank 0, so the same indicators give the
       * same threshold on any number of ranks.
       */
      template <typename Order>
      double
      nth_indicator(const std::vector<float> &mine,
                    const std::size_t         k,
                    const Order              &before,
                    const MPI_Comm            comm)
      {
        const auto parts = Utilities::MPI::gather(comm, mine, 0);
        double     value = 0.;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            std::vector<float> all;
            for (const auto &part : parts)
              all.insert(all.end(), part.begin(), part.end());
            AssertIndexRange(k, all.size());
            std::nth_element(all.begin(), all.begin() + k, all.end(), before);
            value = all[k];
          }
        return Utilities::MPI::broadcast(comm, value, 0);
      }

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
      check_input(refine_fraction + coarsen_fraction <= 1.,
                  "Adaptive refinement/Refine fraction",
                  "plus Adaptive refinement/Coarsen fraction must be at "
                  "most 1 (a cell is refined or coarsened, not both)");
    }

    void
    AdaptiveRefinement::mark_fixed_number(
      const Vector<float>                        &indicators,
      parallel::distributed::Triangulation<2, 3> &triangulation) const
    {
      const MPI_Comm     comm = triangulation.get_communicator();
      std::vector<float> mine;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          mine.push_back(indicators[cell->active_cell_index()]);
      const auto n_cells = triangulation.n_global_active_cells();
      // The numbers of cells as deal.II's refine_and_coarsen_fixed_number
      // counts them.
      const auto n_refine = static_cast<types::global_cell_index>(
        refine_fraction * static_cast<double>(n_cells));
      const auto n_coarsen = static_cast<types::global_cell_index>(
        coarsen_fraction * static_cast<double>(n_cells));
      // The n_refine-th largest indicator; a cell at most tie_band below it
      // is refined too. A threshold of 0 (fewer nonzero indicators than
      // cells to refine) refines the nonzero ones.
      double refine_above = std::numeric_limits<double>::infinity();
      if (n_refine > 0)
        {
          const double t =
            nth_indicator(mine, n_refine - 1, std::greater<float>(), comm);
          refine_above =
            t > 0. ? (1. - tie_band) * t : std::numeric_limits<double>::min();
        }
      // The n_coarsen-th smallest; a cell at most tie_band above it is
      // coarsened too (unless it is to be refined).
      double coarsen_below = -1.;
      if (n_coarsen > 0)
        coarsen_below =
          (1. + tie_band)
          * nth_indicator(mine, n_coarsen - 1, std::less<float>(), comm);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const double eta = indicators[cell->active_cell_index()];
            if (eta >= refine_above)
              cell->set_refine_flag();
            else if (eta <= coarsen_below)
              cell->set_coarsen_flag();
          }
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
      const MPI_Comm comm = triangulation.get_communicator();
      mark_fixed_number(indicators, triangulation);
      auto junction = owned_junction_edges(triangulation);
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
