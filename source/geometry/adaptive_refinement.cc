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
      prm.declare_entry("Cycles",
                        "0",
                        Patterns::Integer(0, 20),
                        "Refinement cycles after the first run: each ranks "
                        "the cells by Kelly's indicator of the final "
                        "displacement, refines a fraction of them and runs "
                        "the load path again. Outputs go to "
                        "Output/Directory/cycle-<k>, a table of all cycles "
                        "to Output/Directory/refinement.csv.");
      prm.declare_entry("Refine fraction",
                        "0.3",
                        Patterns::Double(0., 1.),
                        "Fraction of the cells (largest indicators) refined "
                        "in each cycle.");
      prm.declare_entry("Coarsen fraction",
                        "0",
                        Patterns::Double(0., 1.),
                        "Fraction of the cells (smallest indicators) "
                        "coarsened in each cycle.");
      prm.leave_subsection();
    }

    void
    AdaptiveRefinement::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Adaptive refinement");
      n_cycles         = prm.get_integer("Cycles");
      refine_fraction  = prm.get_double("Refine fraction");
      coarsen_fraction = prm.get_double("Coarsen fraction");
      prm.leave_subsection();
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
