// What the Model offers strategies without a matrix (core/model.h,
// core/capabilities.h), checked against references:
// - the lumped mass (row sums of the consistent mass, dependent dofs
//   condensed): its total per direction is the structure's mass, rho H A
//   of the liquid-and-gas tube's walls with their rigid steel end plates
//   (Q1 and Q2), and of the V5 tank's disc, whose every free dof has a
//   positive mass (Q2);
// - a model set up without a matrix (Model::set_matrix_free, for
//   strategies that assemble no tangent) holds no tangent and assembles
//   the same residual, bit for bit, as one with a matrix;
// - the border for a given field (BorderFromField): at the converged state
//   of a run it reproduces the border Newton found, for the gas and liquid
//   of the liquid-and-gas tube (gas amount control, liquid volume control)
//   and for the gas of the neo-Hookean balloon under gas-amount control.

#include <pneuma/core/model.h>
#include <pneuma/solvers/bordered_vector.h>

#include "test_tools.h"
#include "v5_tank_scene.h"

#include <cmath>
#include <cstdio>

namespace
{
  /// The largest |a - b| / |b| over the border unknowns.
  double
  border_difference(const dealii::Vector<double> &a,
                    const dealii::Vector<double> &b)
  {
    double d = 0.;
    for (unsigned int i = 0; i < b.size(); ++i)
      d = std::max(d, std::abs(a[i] - b[i]) / std::max(std::abs(b[i]), 1e-300));
    return d;
  }

  /// Run @p settings and compare Model::border_for at the final state with
  /// its border.
  bool
  border_at_end(const std::string &name, pneuma_test::Settings settings)
  {
    auto all = pneuma_test::quiet();
    all.insert(all.end(), settings.begin(), settings.end());
    auto                         sim    = pneuma_test::make(all);
    const auto                   result = sim->run();
    const auto                  &state  = sim->final_state();
    const dealii::Vector<double> b =
      sim->model().border_for(state.field, result.get("final_time"));
    const double d  = border_difference(b, state.border);
    const bool   ok = result.exit_code == 0 && b.size() > 0 && d < 1e-6;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%s: %u border unknowns from the field %s\n",
                  name.c_str(),
                  b.size(),
                  ok ? "agree with Newton's to 1e-6" : "DIFFER (FAIL)");
    if (!ok && dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("  exit %d, largest relative difference %.3e\n",
                  result.exit_code,
                  d);
    return ok;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  // The tube's walls: 1 mm membrane (density 1000) and 10 mm end plates
  // (density 7850), rigid.
  for (const unsigned int degree : {1u, 2u})
    {
      auto s = pneuma_test::liquid_gas_tube();
      s.push_back({"Discretisation/Polynomial degree", std::to_string(degree)});
      s.push_back({"Materials/Region 0/Density", "1000"});
      s.push_back({"Materials/Region 1/Density", "7850"});
      s.push_back({"Materials/Region 2/Density", "7850"});
      auto all = pneuma_test::quiet();
      all.insert(all.end(), s.begin(), s.end());
      auto                  sim   = pneuma_test::make(all);
      pneuma::Model        &model = sim->model();
      const auto            m     = model.lumped_mass();
      std::array<double, 3> total{};
      for (unsigned int c = 0; c < 3; ++c)
        total[c] = model.rigid_translation(c) * m;
      const double R = 0.23, L = 2.;
      const double reference =
        1000. * 1e-3 * 2. * M_PI * R * L + 2. * 7850. * 1e-2 * M_PI * R * R;
      for (unsigned int c = 0; c < 3; ++c)
        {
          // Q1: the faceted tube's smaller area.
          ok =
            pneuma_test::check("Q" + std::to_string(degree)
                                 + " lumped mass along " + "xyz"[c] + " [kg]",
                               total[c],
                               reference,
                               degree == 1 ? 1e-2 : 1e-5)
            && ok;
        }
    }
  {
    // The disc (Q2): its mass and positive entries.
    auto s = pneuma_test::quiet();
    for (const auto &e : pneuma_test::v5_tank({}, "run-output"))
      s.push_back(e);
    s.push_back({"Materials/Region 0/Density", "1000"});
    auto           sim      = pneuma_test::make(s);
    pneuma::Model &model    = sim->model();
    const auto     m        = model.lumped_mass();
    const double   total    = model.rigid_translation(2) * m;
    double         smallest = 1e300;
    for (const auto i : model.locally_owned())
      if (!model.constraints().is_constrained(i))
        smallest = std::min(smallest, m[i]);
    smallest = dealii::Utilities::MPI::min(smallest, MPI_COMM_WORLD);
    ok       = pneuma_test::check("Q2 disc lumped mass along z [kg]",
                            total,
                            1000. * 1e-3 * M_PI * 0.25,
                            1e-3)
         && ok;
    const bool positive = smallest > 0.;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("Q2 disc lumped mass of every free dof: %s\n",
                  positive ? "positive" : "NOT POSITIVE (FAIL)");
    ok = positive && ok;
  }
  // Without a matrix: the same residual at a smooth state.
  {
    auto s = pneuma_test::liquid_gas_tube();
    s.push_back({"Load stepping/Initial increment", "0.25"});
    auto all = pneuma_test::quiet();
    all.insert(all.end(), s.begin(), s.end());
    std::vector<std::string> overrides;
    for (const auto &e : all)
      overrides.push_back(e.first + "=" + e.second);
    const auto layout = pneuma::InputLayout::from_text("", overrides);
    std::array<std::unique_ptr<pneuma::Simulator>, 2> sims;
    std::array<pneuma::solvers::BorderedVector, 2>    r;
    for (unsigned int k = 0; k < 2; ++k)
      {
        sims[k] = std::make_unique<pneuma::Simulator>(MPI_COMM_WORLD, layout);
        dealii::ParameterHandler prm;
        sims[k]->declare_parameters(prm);
        pneuma::parse_input_text(prm, "", overrides);
        sims[k]->parse_parameters(prm);
        sims[k]->model().set_matrix_free(k == 1);
        sims[k]->setup();
        pneuma::Model                  &model = sims[k]->model();
        pneuma::solvers::BorderedVector u     = model.initial_state();
        for (const auto i : model.locally_owned())
          u.field[i] += 1e-3 * std::sin(0.37 * i);
        u.field.compress(dealii::VectorOperation::insert);
        r[k] = u;
        model.assemble_residual(u, 0.5, r[k]);
      }
    r[1].field -= r[0].field;
    const bool same = r[1].field.linfty_norm() == 0.
                      && sims[1]->model().tangent_matrix().m() == 0
                      && sims[0]->model().tangent_matrix().m() > 0;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("without a matrix: no tangent, the same residual: %s\n",
                  same ? "yes" : "NO (FAIL)");
    ok = same && ok;
  }
  // The border for the converged field.
  {
    auto s = pneuma_test::liquid_gas_tube();
    s.push_back({"Load stepping/Initial increment", "0.25"});
    ok = border_at_end("liquid-and-gas tube", s) && ok;
  }
  {
    auto s = pneuma_test::neo_hookean_sphere_chamber();
    s.push_back({"Chambers/Chamber 1/Gas/Control", "gas amount"});
    s.push_back({"Chambers/Chamber 1/Gas/Gas amount/Function expression",
                 pneuma_test::balloon_gas_amount()});
    s.push_back({"Load stepping/Stage end times", "1"});
    ok = border_at_end("neo-Hookean balloon", s) && ok;
  }
  return ok ? 0 : 1;
}
