#include <pneuma/core/capabilities.h>
#include <pneuma/core/model.h>
#include <pneuma/strategies/dynamic_relaxation/dynamic_relaxation.h>
#include <pneuma/strategies/gershgorin.h>

namespace pneuma
{
  namespace strategies
  {
    using namespace dealii;

    LA::Vector
    relaxation_mass(const Model &model, const double safety)
    {
      LA::Vector m = stiffness_row_sums(model);
      for (const auto *i : model.with<Inertia>())
        i->largest_per_node(m);
      // A free dof without any stiffness yet (nothing holds it) moves
      // with the largest mass; a constrained one does not move.
      const double largest = m.linfty_norm();
      const auto  &c       = model.constraints();
      for (const auto row : model.locally_owned())
        {
          const double s = m[row];
          m[row]         = c.is_constrained(row) ? 1.
                           : s > 0.              ? 0.25 * safety * s
                                                 : 0.25 * safety * largest;
        }
      m.compress(VectorOperation::insert);
      AssertThrow(largest > 0.,
                  ExcMessage("dynamic relaxation: the tangent is zero, so "
                             "no fictitious mass can be chosen"));
      return m;
    }
  } // namespace strategies
} // namespace pneuma
