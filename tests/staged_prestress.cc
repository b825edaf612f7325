// Prestress as a load stage (doc/verification.md "Staged prestress"): a
// straight cable between two fixed ends (L = 2 m, 8 elements, EA = 7.85e6
// N) with Prestress force F = 1000 N staged by the Prestress factor
// f(t) = max(0, t - 1): nothing in stage 1 (t <= 1), tensioned in stage 2.
// The ends hold the reference length, so the stretch against the
// unstressed length is rho = 1 + f F/EA and the axial force is exactly
// f(t) F for the tension-only cable; the solid beam's nonlinear section
// law gives F to within the strain F/EA = 1.3e-4. The end reactions carry
// the force.

#include "test_tools.h"

#include <cmath>
#include <string>

namespace
{
  pneuma_test::Settings
  cable(const std::string &element, const std::string &end_time)
  {
    return {{"Geometry/Type", "none"},
            {"Cables/Number of cables", "1"},
            {"Cables/Cable 1/Element", element},
            {"Cables/Cable 1/polyline/Points", "0, 0, 0; 2, 0, 0"},
            {"Cables/Cable 1/Number of elements", "8"},
            {"Cables/Cable 1/Section semi-axes", "0.005"},
            {"Cables/Cable 1/Young's modulus", "1e11"},
            {"Cables/Cable 1/Prestress force", "1000"},
            {"Cables/Cable 1/Prestress factor/Function expression",
             "max(0, t - 1)"},
            {"Cables/Cable 1/Start support", "fixed"},
            {"Cables/Cable 1/End support", "fixed"},
            {"Load stepping/Stage end times", end_time},
            {"Load stepping/Initial increment", "0.5"}};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  bool         ok = true;
  const double F  = 1000.;
  for (const std::string element : {"cable", "solid beam"})
    {
      const double tolerance = element == "cable" ? 1e-10 : 1e-3;
      // End of stage 1: not yet tensioned.
      {
        const auto s    = pneuma_test::run(cable(element, "1"));
        const bool zero = s.exit_code == 0
                          && std::abs(s.get("cable1_max_force")) < 1e-6 * F
                          && std::abs(s.get("cable1_min_force")) < 1e-6 * F;
        if (root)
          std::printf("%s, t = 1 (f = 0): axial force %s 1e-6 F %s\n",
                      element.c_str(),
                      zero ? "<" : ">=",
                      zero ? "PASS" : "FAIL");
        ok = ok && zero;
      }
      // Half-way and end of stage 2.
      for (const double t : {1.5, 2.})
        {
          const auto s =
            pneuma_test::run(cable(element, "1, " + pneuma_test::number(t)));
          const std::string at =
            element + ", t = " + pneuma_test::number(t) + ": ";
          ok = pneuma_test::check(at + "axial force vs f(t) F",
                                  s.get("cable1_max_force"),
                                  (t - 1.) * F,
                                  tolerance)
               && ok;
          ok = pneuma_test::check(at + "smallest axial force vs f(t) F",
                                  s.get("cable1_min_force"),
                                  (t - 1.) * F,
                                  tolerance)
               && ok;
          ok = pneuma_test::check(at + "start reaction along the cable",
                                  std::abs(s.summary.get_vector(
                                    "cable1_start_reaction")[0]),
                                  (t - 1.) * F,
                                  tolerance)
               && ok;
        }
    }
  if (root)
    std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
