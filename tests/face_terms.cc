// The membrane's face-term hook (membrane/face_terms.h,
// membrane/face_assembly.h): a term on the interior edges of the
// membrane's cells, the kink energy
//   E = k/2 sum_edges int_e |n_1 x n_2|^2 ds_0
// (n_1, n_2 the current unit normals of the two cells at the edge), with
// its residual and tangent by automatic differentiation (Sacado through
// deal.II's Differentiation::AD::EnergyFunctional, step-72), is added to
// the membrane's assembly of a flat square (side 1, 8 x 8 cells).
// - Energy against the exact value: the square bent into w = c x^2; on Q1
//   cells the interpolant is a ruled surface of flat strips whose slopes
//   s_i = c (x_i + x_{i+1}) give E = k/2 sum_i sin^2(atan s_i -
//   atan s_{i-1}) over the interior edges x = x_i (each of length 1); on
//   Q2 cells the interpolant is exact and smooth, E = 0.
// - The term's residual against differences of its energy, E(u + h d) -
//   E(u - h d) = 2 h r . d.
// - The assembled tangent of the whole model (membrane and face term,
//   through the sparsity couplings of the edges) against finite
//   differences of the residual (Simulator::check_tangent).
// The same on 1 and 2 MPI ranks (edges between the ranks' cells visited
// once).

#include <deal.II/differentiation/ad.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_interface_values.h>

#include <pneuma/core/model.h>
#include <pneuma/membrane/face_terms.h>
#include <pneuma/membrane/membrane_subsystem.h>

#include "test_tools.h"

#include <cmath>
#include <cstdio>
#include <numeric>

using namespace dealii;

namespace
{
  using ADHelper = Differentiation::AD::EnergyFunctional<
    Differentiation::AD::NumberTypes::sacado_dfad_dfad,
    double>;
  using ADNumber = typename ADHelper::ad_type;

  /// The kink energy on the interior edges (see above).
  class KinkEnergy : public pneuma::membrane::FaceTerms
  {
  public:
    explicit KinkEnergy(const double k)
      : k(k)
    {
    }
    struct Record : FaceTerms::Record
    {
      double energy = 0.;
    };
    unsigned int
    n_quadrature_points() const override
    {
      return 3;
    }
    UpdateFlags
    update_flags() const override
    {
      return update_values | update_gradients | update_jacobians
             | update_JxW_values;
    }
    std::unique_ptr<Scratch>
    new_scratch() const override
    {
      return std::make_unique<Scratch>();
    }
    std::unique_ptr<FaceTerms::Record>
    new_record() const override
    {
      return std::make_unique<Record>();
    }
    void
    begin(const pneuma::Assembly &) override
    {
      energy = 0.;
    }
    void
    interior_face(const FEInterfaceValues<2, 3> &fiv,
                  const std::vector<double>     &local_u,
                  FullMatrix<double>            *matrix,
                  Vector<double>                *residual,
                  Scratch &,
                  FaceTerms::Record &record) const override
    {
      if (!active)
        return;
      const unsigned int                   n = local_u.size();
      ADHelper                             ad(n);
      std::vector<types::global_dof_index> index(n);
      std::iota(index.begin(), index.end(), 0);
      ad.register_dof_values(Vector<double>(local_u.begin(), local_u.end()),
                             index);
      const std::vector<ADNumber> &u = ad.get_sensitive_dof_values();
      ADNumber                     e = 0.;
      for (unsigned int q = 0; q < fiv.n_quadrature_points; ++q)
        {
          std::array<Tensor<1, 3, ADNumber>, 2> normal;
          for (unsigned int s = 0; s < 2; ++s)
            {
              const auto &fv = fiv.get_fe_face_values(s);
              const auto &fe = fv.get_fe();
              // a_alpha = J_alpha + (grad_S u) J_alpha.
              std::array<Tensor<1, 3, ADNumber>, 2> a;
              for (unsigned int alpha = 0; alpha < 2; ++alpha)
                for (unsigned int d = 0; d < 3; ++d)
                  a[alpha][d] = fv.jacobian(q)[d][alpha];
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int local =
                    fiv.interface_dof_to_dof_indices(i)[s];
                  if (local == numbers::invalid_unsigned_int)
                    continue;
                  const unsigned int c =
                    fe.system_to_component_index(local).first;
                  const Tensor<1, 3> g = fv.shape_grad_component(local, q, c);
                  for (unsigned int alpha = 0; alpha < 2; ++alpha)
                    {
                      double dxi = 0.;
                      for (unsigned int d = 0; d < 3; ++d)
                        dxi += g[d] * fv.jacobian(q)[d][alpha];
                      a[alpha][c] += u[i] * dxi;
                    }
                }
              const Tensor<1, 3, ADNumber> m    = cross_product_3d(a[0], a[1]);
              const ADNumber               norm = std::sqrt(m * m);
              normal[s]                         = m / norm;
            }
          const Tensor<1, 3, ADNumber> x =
            cross_product_3d(normal[0], normal[1]);
          e += 0.5 * k * (x * x) * fiv.JxW(q);
        }
      ad.register_energy_functional(e);
      static_cast<Record &>(record).energy = ad.compute_energy();
      if (residual)
        ad.compute_residual(*residual);
      if (matrix)
        ad.compute_linearization(*matrix);
    }
    void
    commit(const FaceTerms::Record &record) override
    {
      energy += static_cast<const Record &>(record).energy;
    }
    /// The energy of the last assembly on this rank's edges.
    double energy = 0.;
    /// Off: the term adds nothing (its couplings stay in the pattern).
    bool active = true;

  private:
    double k;
  };

  /// A flat square of side 1 on 3 refinements with the kink term, set up.
  std::unique_ptr<pneuma::Simulator>
  square(const unsigned int degree, KinkEnergy &term)
  {
    std::vector<std::string> overrides = {
      "Output/Directory=run-output",
      "Output/Quiet=true",
      "Output/Write VTU=false",
      "Geometry/Type=square",
      "Geometry/square/Side length=1",
      "Geometry/Global refinements=3",
      "Discretisation/Polynomial degree=" + std::to_string(degree),
      "Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus=1e6",
      "Boundary conditions/Prescribed displacement boundaries=0, 1, 2, 3"};
    const auto layout = pneuma::InputLayout::from_text("", overrides);
    auto sim = std::make_unique<pneuma::Simulator>(MPI_COMM_WORLD, layout);
    ParameterHandler prm;
    sim->declare_parameters(prm);
    pneuma::parse_input_text(prm, "", overrides);
    sim->parse_parameters(prm);
    sim->model().find<pneuma::membrane::MembraneSubsystem>()->add_face_terms(
      term);
    sim->setup();
    return sim;
  }

  /// The field of w = c (x + 1/2)^2 (x from 0 at the square's edge).
  pneuma::solvers::BorderedVector
  bent(pneuma::Model &model, const double c)
  {
    const auto &membrane = *model.find<pneuma::membrane::MembraneSubsystem>();
    const auto &dofs     = membrane.dof_handler();
    std::map<types::global_dof_index, Point<3>> points;
    DoFTools::map_dofs_to_support_points(membrane.mapping(), dofs, points);
    pneuma::solvers::BorderedVector u;
    u.field = model.make_field();
    u.border.reinit(model.n_border());
    std::vector<types::global_dof_index> cell_dofs(
      dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            if (dofs.get_fe().system_to_component_index(i).first == 2
                && model.locally_owned().is_element(cell_dofs[i]))
              {
                const double x        = points.at(cell_dofs[i])[0] + 0.5;
                u.field[cell_dofs[i]] = c * x * x;
              }
        }
    u.field.compress(VectorOperation::insert);
    return u;
  }


  /// The term's energy over all ranks after an assembly at @p u.
  double
  energy_at(pneuma::Model                         &model,
            KinkEnergy                            &term,
            const pneuma::solvers::BorderedVector &u)
  {
    pneuma::solvers::BorderedVector r(u);
    model.assemble(u, 0., r);
    return Utilities::MPI::sum(term.energy, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = true;
  const double                     k = 10., c = 0.3;
  // Q1: the exact energy of the ruled surface of flat strips.
  {
    KinkEnergy         term(k);
    auto               sim       = square(1, term);
    pneuma::Model     &model     = sim->model();
    const auto         u         = bent(model, c);
    const unsigned int M         = 8;
    double             reference = 0.;
    for (unsigned int i = 1; i < M; ++i)
      {
        const double h = 1. / M, x = i * h;
        const double s0 = c * (2. * x - h), s1 = c * (2. * x + h);
        reference +=
          0.5 * k * std::pow(std::sin(std::atan(s1) - std::atan(s0)), 2);
      }
    ok = pneuma_test::check("Q1 kink energy of w = c x^2 [J]",
                            energy_at(model, term, u),
                            reference,
                            1e-12)
         && ok;
    // The term's residual against differences of its energy along a
    // smooth direction d (the z components of the bent field).
    pneuma::solvers::BorderedVector r_on(u), r_off(u), d = bent(model, 1.);
    // Only the free dofs move (the residual has no rows at held ones).
    model.constraints().set_zero(d.field);
    model.assemble(u, 0., r_on);
    term.active = false;
    model.assemble(u, 0., r_off);
    term.active = true;
    r_on.field -= r_off.field;
    const double                    h = 1e-6;
    pneuma::solvers::BorderedVector up(u), um(u);
    up.field.add(h, d.field);
    um.field.add(-h, d.field);
    const double fd =
      (energy_at(model, term, up) - energy_at(model, term, um)) / (2. * h);
    ok = pneuma_test::check("Q1 face residual . d against energy differences",
                            r_on.field * d.field,
                            fd,
                            1e-6)
         && ok;
    // The whole tangent against differences of the residual.
    const double error = sim->check_tangent(0., 0.01, 1e-6).first;
    if (pneuma_test::root())
      std::printf("Q1 tangent with the face term vs finite differences: %s\n",
                  error < 1e-6 ? "relative error < 1e-6" : "FAIL");
    ok = error < 1e-6 && ok;
  }
  // Q2: the interpolant of w = c x^2 is exact and smooth: no kinks.
  {
    KinkEnergy     term(k);
    auto           sim   = square(2, term);
    pneuma::Model &model = sim->model();
    const double   e     = energy_at(model, term, bent(model, c));
    const bool     zero  = std::abs(e) < 1e-20;
    if (pneuma_test::root())
      std::printf("Q2 kink energy of w = c x^2: %s\n",
                  zero ? "zero (< 1e-20)" : "FAIL");
    if (!zero && pneuma_test::root())
      std::printf("  energy %.3e\n", e);
    ok                 = zero && ok;
    const double error = sim->check_tangent(0., 0.01, 1e-6).first;
    if (pneuma_test::root())
      std::printf("Q2 tangent with the face term vs finite differences: %s\n",
                  error < 1e-6 ? "relative error < 1e-6" : "FAIL");
    if (error >= 1e-6 && pneuma_test::root())
      std::printf("  relative error %.3e\n", error);
    ok = error < 1e-6 && ok;
  }
  return ok ? 0 : 1;
}
