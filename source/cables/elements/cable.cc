/**
 * @file
 * The element "cable": the tension-only truss of Irvine's elastic cable
 * (doc/theory.md §8.1; kernel TensionOnlyCable in tension_only_cable.h).
 * Displacements of the mid-line only. With the stretch lambda = rho |x'|
 * against the unstressed length, the axial force is
 * N = EA_eff (lambda - 1), EA_eff = EA in tension and r EA (the Slack
 * stiffness ratio r) in compression, and the internal virtual work of a
 * cell is \f$\int N\,e\cdot\delta x'\,dS\f$ with e = x'/|x'|:
 * \f$r_i = \int N_i'\,(N e)_{c_i}\,dS\f$ and
 * \f$K_{ij} = \int N_i'\,\partial(N e)/\partial x'_{c_i c_j}\,N_j'\,dS\f$.
 * The strain is constant on a linear cell, so one Gauss point is exact.
 */

#include <deal.II/base/quadrature_lib.h>

#include <pneuma/cables/cable_element.h>
#include <pneuma/cables/cable_parameters.h>
#include <pneuma/cables/tension_only_cable.h>
#include <pneuma/core/input_error.h>

#include <memory>

namespace pneuma
{
  namespace cables
  {
    namespace
    {
      class Cable : public CableElement
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter(
            "Slack stiffness ratio",
            slack_ratio,
            "Axial stiffness in compression relative to EA. A slack cable "
            "then carries (almost) nothing, yet the matrix stays regular; it "
            "has no effect on a taut cable.",
            Patterns::Double(0., 1.));
        }

        void
        parse_parameters(ParameterHandler &, const std::string &) override
        {
        }

        unsigned int
        n_components() const override
        {
          return 3;
        }

        std::vector<std::string>
        component_names() const override
        {
          return std::vector<std::string>(3, "displacement");
        }

        std::vector<std::string>
        output_names() const override
        {
          return {"axial_force", "stretch"};
        }

        Quadrature<1>
        quadrature() const override
        {
          return QGauss<1>(1);
        }

        void
        setup(const CableDefinition &cable, const double length_ratio) override
        {
          EA = cable.youngs_modulus * cable.area();
          law =
            std::make_unique<TensionOnlyCable>(EA, length_ratio, slack_ratio);
        }

        void
        set_length_ratio(const double length_ratio) override
        {
          law =
            std::make_unique<TensionOnlyCable>(EA, length_ratio, slack_ratio);
        }

        void
        cell_terms(const FEValues<1, 3> &fe_values,
                   const Tensor<1, 3>   &tangent,
                   const Vector<double> &local_reference,
                   const Vector<double> &local_u,
                   FullMatrix<double>   *cell_matrix,
                   Vector<double>       *cell_residual,
                   CableCellOutput      *output) const override
        {
          const FiniteElement<1, 3> &fe = fe_values.get_fe();
          const unsigned int         n  = fe.n_dofs_per_cell();
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              std::vector<double> g(n);
              Tensor<1, 3>        dx;
              for (unsigned int i = 0; i < n; ++i)
                {
                  g[i] = fe_values.shape_grad(i, q) * tangent;
                  dx[fe.system_to_component_index(i).first] +=
                    (local_reference[i] + local_u[i]) * g[i];
                }
              const CablePoint p   = law->evaluate(dx);
              const double     JxW = fe_values.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int ci = fe.system_to_component_index(i).first;
                  if (cell_residual)
                    (*cell_residual)(i) += p.force_vector[ci] * g[i] * JxW;
                  if (cell_matrix)
                    for (unsigned int j = 0; j < n; ++j)
                      (*cell_matrix)(i, j) +=
                        g[i]
                        * p.tangent[ci][fe.system_to_component_index(j).first]
                        * g[j] * JxW;
                }
              if (output)
                {
                  output->values      = {p.force, p.stretch};
                  output->axial_force = p.force;
                }
            }
        }

      private:
        double slack_ratio = 1e-6;
        /// The axial stiffness of setup().
        double                            EA = 0.;
        std::unique_ptr<TensionOnlyCable> law;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(CableElement,
                            Cable,
                            "cable",
                            "tension-only truss (displacements only)")
  } // namespace cables
} // namespace pneuma
