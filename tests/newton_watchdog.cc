// Newton's watchdog never goes on from an absurd iterate (issue "Cables
// anchored and tied, contact that holds up"): r(u) = atan(u - 1) +
// 1e11 max(0, u - 5)^2 from u = -2, where the full Newton step of atan
// (12.5) lands in the stiff wall at u = 10.5 with |r| = 3e12, 2.4e12 times
// |r_0|. A full step that raises |r| more than 1e6-fold is not watched: the
// line search backtracks from u = -2 and Newton converges to u = 1. Checked:
// the largest |r| of an iterate Newton solved from stays below 1e6 |r_0|, the
// root, and the quadratic rate at the end. (A penalty contact point thrown
// through the membrane produced such a state, with |r| = 1e78, which the
// watchdog used to take.) Also: a residual that is not finite at the
// start is a failure, not an iterate. And a failed watch resumes along the
// direction saved with its state: r(u) = atan(u) from u = 1.5, where the
// full Newton steps diverge; after the three watched steps the state
// u = 1.5 comes back and the line search backtracks along its saved
// direction from half the step, without solving at u = 1.5 again (6 linear
// solves to the root, |r(1.5)| solved from once).

#include <deal.II/base/mpi.h>

#include <pneuma/solvers/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "test_tools.h"

namespace
{
  using namespace pneuma::solvers;

  /// The scalar problem in the first field entry.
  class Wall : public NonlinearProblem
  {
  public:
    /// |r| of every iterate Newton solved from.
    std::vector<double> solved_from;
    bool                poisoned = false;

    static double
    residual(const double u)
    {
      return std::atan(u - 1.) + 1e11 * std::pow(std::max(0., u - 5.), 2);
    }

    void
    assemble(const BorderedVector &u, BorderedVector &r) override
    {
      const double v = u.field[0];
      slope = 1. / (1. + (v - 1.) * (v - 1.)) + 2e11 * std::max(0., v - 5.);
      r.field[0] =
        poisoned ? std::numeric_limits<double>::quiet_NaN() : residual(v);
      r.field.compress(dealii::VectorOperation::insert);
    }
    void
    solve_linear(const double,
                 const BorderedVector &rhs,
                 BorderedVector       &du) override
    {
      solved_from.push_back(std::abs(rhs.field[0]));
      du.field[0] = rhs.field[0] / slope;
      du.field.compress(dealii::VectorOperation::insert);
    }
    double
    initial_shift(const double) override
    {
      return 0.;
    }
    void
    laplacian_vmult(const BorderedVector &, BorderedVector &y) override
    {
      y = 0.;
    }
    double
    load_norm() override
    {
      return 0.;
    }

  protected:
    /// dr/du at the last assembled state (solve_linear() divides by it).
    double slope = 1.;
  };

  /// r(u) = atan(u): Newton's full steps diverge from |u| > 1.39.
  class Atan : public Wall
  {
  public:
    void
    assemble(const BorderedVector &u, BorderedVector &r) override
    {
      const double v = u.field[0];
      slope          = 1. / (1. + v * v);
      r.field[0]     = std::atan(v);
      r.field.compress(dealii::VectorOperation::insert);
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::IndexSet                         owned(1);
  owned.add_index(0);
  BorderedVector u;
  u.field.reinit(owned, MPI_COMM_WORLD);
  u.field[0] = -2.;
  u.field.compress(dealii::VectorOperation::insert);

  dealii::ParameterHandler prm;
  NewtonSolver             newton;
  newton.declare_parameters(prm);
  newton.parse_parameters(prm);
  const dealii::ConditionalOStream quiet(std::cout, false);

  Wall         wall;
  const double r0     = std::abs(Wall::residual(-2.));
  const auto   result = newton.solve(wall, u, quiet, false);
  bool         ok     = result.converged;
  std::printf("converged: %s (%s), %zu Newton iterations\n",
              result.converged ? "yes" : "no",
              result.convergence_test.c_str(),
              wall.solved_from.size());
  ok &= pneuma_test::check("root u = 1", u.field[0], 1., 1e-8);
  const double worst =
    *std::max_element(wall.solved_from.begin(), wall.solved_from.end());
  ok &= pneuma_test::check("largest |r| solved from / |r_0| <= 1e6",
                           worst / r0 <= 1e6 ? 1. : 0.,
                           1.,
                           0.);
  // Quadratic rate: |r_k+1| / |r_k|^2 bounded over the last iterations.
  const auto &h = result.residual_history;
  ok &= pneuma_test::check(
    "quadratic at the end: |r_k+1| <= |r_k|^2",
    h.size() >= 2 && h.back() <= h[h.size() - 2] * h[h.size() - 2] ? 1. : 0.,
    1.,
    0.);

  // Not finite at the start: a failure with its reason.
  Wall poisoned;
  poisoned.poisoned = true;
  u.field[0]        = -2.;
  u.field.compress(dealii::VectorOperation::insert);
  const auto failed = newton.solve(poisoned, u, quiet, false);
  std::printf("NaN residual: converged %s, reason \"%s\"\n",
              failed.converged ? "yes" : "no",
              failed.failure_reason.c_str());
  ok &= !failed.converged && poisoned.solved_from.empty();

  // A failed watch: back to u = 1.5, on along its saved direction.
  Atan diverging;
  u.field[0] = 1.5;
  u.field.compress(dealii::VectorOperation::insert);
  const auto   watched = newton.solve(diverging, u, quiet, false);
  const double r_start = std::atan(1.5);
  const auto   from_start =
    std::count_if(diverging.solved_from.begin(),
                  diverging.solved_from.end(),
                  [&](const double r) { return r == r_start; });
  std::printf("atan from u = 1.5: converged %s, %zu linear solves, %ld of "
              "them from u = 1.5\n",
              watched.converged ? "yes" : "no",
              diverging.solved_from.size(),
              static_cast<long>(from_start));
  ok &= watched.converged;
  ok &= pneuma_test::check("root u = 0 (|u| + 1)",
                           std::abs(u.field[0]) + 1.,
                           1.,
                           1e-8);
  ok &=
    pneuma_test::check("linear solves", diverging.solved_from.size(), 6., 0.);
  ok &= pneuma_test::check("solves from the restored state u = 1.5",
                           from_start,
                           1.,
                           0.);
  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
