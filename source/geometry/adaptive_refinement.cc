#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/error_estimator.h>

#include <pneuma/geometry/adaptive_refinement.h>

namespace pneuma
{
  namespace geometry
  {
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
      triangulation.execute_coarsening_and_refinement();
    }
  } // namespace geometry
} // namespace pneuma
