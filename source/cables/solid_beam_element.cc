#include <pneuma/cables/solid_beam_element.h>
#include <pneuma/cables/solid_beam_section.h>

#include <cmath>

namespace pneuma
{
  namespace cables
  {
    SolidBeamElement::SolidBeamElement(const BeamMaterial &material,
                                       const double        length_ratio)
      : section(std::make_unique<SolidBeamSection>(material))
      , rho(length_ratio)
    {
    }

    SolidBeamElement::~SolidBeamElement() = default;

    std::vector<std::string>
    SolidBeamElement::output_names()
    {
      return {"axial_force",
              "bending_moment_1",
              "bending_moment_2",
              "torsion_moment",
              "section_stretch_1",
              "section_stretch_2"};
    }

    void
    SolidBeamElement::cell_terms(const FEValues<1, 3> &fe_values,
                                 const Tensor<1, 3>   &tangent,
                                 const Vector<double> &local_reference,
                                 const Vector<double> &local_u,
                                 FullMatrix<double>   *cell_matrix,
                                 Vector<double>       *cell_residual,
                                 std::vector<double>  *output) const
    {
      const FiniteElement<1, 3> &fe = fe_values.get_fe();
      const unsigned int         n  = fe.n_dofs_per_cell();
      // For dof i: the gradient index of its value and of its derivative.
      std::vector<unsigned int> value_index(n), derivative_index(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int c = fe.system_to_component_index(i).first;
          value_index[i]       = 3 * (2 * (c / 3)) + c % 3;
          derivative_index[i]  = 3 * (2 * (c / 3) + 1) + c % 3;
        }
      if (output)
        std::fill(output->begin(), output->end(), 0.);
      std::vector<double>        N(n), dN(n);
      SolidBeamSection::Gradient gradient;
      FullMatrix<double>         hessian;
      const unsigned int         n_q = fe_values.n_quadrature_points;
      for (unsigned int q = 0; q < n_q; ++q)
        {
          SolidBeamSection::State Q, x;
          for (unsigned int i = 0; i < n; ++i)
            {
              N[i]                 = fe_values.shape_value(i, q);
              dN[i]                = fe_values.shape_grad(i, q) * tangent;
              const unsigned int c = fe.system_to_component_index(i).first;
              const unsigned int b = 2 * (c / 3), d = c % 3;
              Q[b][d] += local_reference[i] * N[i];
              Q[b + 1][d] += local_reference[i] * dN[i];
              x[b][d] += (local_reference[i] + local_u[i]) * N[i];
              x[b + 1][d] += (local_reference[i] + local_u[i]) * dN[i];
            }
          // Prestress: the unstressed mid-line is shorter by 1/rho.
          Q[1] /= rho;
          const double JxW = fe_values.JxW(q);
          if (cell_matrix || cell_residual)
            {
              double w = 0.;
              if (cell_matrix)
                section->evaluate(Q, x, w, gradient, hessian);
              else
                section->evaluate(Q, x, w, gradient);
              for (unsigned int i = 0; i < n; ++i)
                {
                  if (cell_residual)
                    (*cell_residual)(i) +=
                      (gradient[value_index[i]] * N[i]
                       + gradient[derivative_index[i]] * dN[i])
                      * JxW;
                  if (cell_matrix)
                    for (unsigned int j = 0; j < n; ++j)
                      (*cell_matrix)(i, j) +=
                        (N[i] * N[j] * hessian(value_index[i], value_index[j])
                         + N[i] * dN[j]
                             * hessian(value_index[i], derivative_index[j])
                         + dN[i] * N[j]
                             * hessian(derivative_index[i], value_index[j])
                         + dN[i] * dN[j]
                             * hessian(derivative_index[i],
                                       derivative_index[j]))
                        * JxW;
                }
            }
          if (output)
            {
              const SectionResultants r         = section->resultants(Q, x);
              const double            values[6] = {r.axial_force,
                                                   r.bending_moment_1,
                                                   r.bending_moment_2,
                                                   r.torsion_moment,
                                                   r.stretch_1,
                                                   r.stretch_2};
              for (unsigned int k = 0; k < 6 && k < output->size(); ++k)
                (*output)[k] += values[k] / n_q;
            }
        }
    }

    namespace
    {
      std::array<double, 2>
      moment_weights(const Tensor<1, 3>                &m,
                     const std::array<Tensor<1, 3>, 2> &A)
      {
        std::array<double, 2> w;
        for (unsigned int k = 0; k < 2; ++k)
          w[k] = cross_product_3d(A[k], m).norm_square() / A[k].norm_square();
        const double sum = w[0] + w[1];
        w[0] /= sum;
        w[1] /= sum;
        return w;
      }
    } // namespace

    double
    SolidBeamElement::section_rotation(const Tensor<1, 3> &moment,
                                       const std::array<Tensor<1, 3>, 2> &A,
                                       const std::array<double, 2>       &theta)
    {
      if (moment.norm() == 0.)
        return 0.;
      const auto w = moment_weights(moment / moment.norm(), A);
      return w[0] * theta[0] + w[1] * theta[1];
    }

    void
    SolidBeamElement::end_moment_terms(
      const Tensor<1, 3>                &moment,
      const std::array<Tensor<1, 3>, 2> &A,
      const std::array<Tensor<1, 3>, 2> &a,
      const std::array<Tensor<1, 3>, 2> &a_previous,
      const std::array<double, 2>       &theta_previous,
      FullMatrix<double>                *node_matrix,
      Vector<double>                    *node_residual,
      std::array<double, 2>             *theta)
    {
      const double M = moment.norm();
      if (M == 0.)
        return;
      const Tensor<1, 3> m      = moment / M;
      const auto         weight = moment_weights(m, A);
      for (unsigned int k = 0; k < 2; ++k)
        {
          if (weight[k] < 1e-12)
            {
              if (theta)
                (*theta)[k] = theta_previous[k];
              continue;
            }
          const double        Mk = M * weight[k];
          const Tensor<1, 3> &d  = a[k];
          const Tensor<1, 3>  d_ref =
            a_previous[k].norm() > 0. ? a_previous[k] : A[k];
          const unsigned int offset = 3 + 3 * k;
          // theta_k = theta_previous + the angle from d_ref to d about m,
          // both projected on the plane normal to m.
          const Tensor<1, 3> p     = d - (d * m) * m;
          const Tensor<1, 3> p_ref = d_ref - (d_ref * m) * m;
          const double       s     = p * p;
          if (theta)
            (*theta)[k] =
              theta_previous[k]
              + std::atan2(cross_product_3d(p_ref, p) * m, p_ref * p);
          // dtheta/dd = (m x p)/|p|^2; its derivative
          // [m x]/|p|^2 - 2 (m x p) (x) p / |p|^4.
          const Tensor<1, 3> w = cross_product_3d(m, p);
          for (unsigned int i = 0; i < 3; ++i)
            {
              if (node_residual)
                (*node_residual)(offset + i) -= Mk * w[i] / s;
              if (node_matrix)
                for (unsigned int j = 0; j < 3; ++j)
                  {
                    Tensor<1, 3> e_j;
                    e_j[j]               = 1.;
                    const double skew_ij = cross_product_3d(m, e_j)[i];
                    (*node_matrix)(offset + i, offset + j) -=
                      Mk * (skew_ij / s - 2. * w[i] * p[j] / (s * s));
                  }
            }
        }
    }
  } // namespace cables
} // namespace pneuma
