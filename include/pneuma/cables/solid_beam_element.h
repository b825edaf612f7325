#pragma once

/**
 * @file
 * The source paper's solid-beam element on a cable mesh (doc/theory.md
 * §8.2): the per-point section energy of SolidBeamSection chained with the
 * 1D shape functions, and the conservative end moment.
 *
 * Unknowns per node (components): 0-2 the displacement of the mid-line,
 * 3-5 and 6-8 the changes of the section semi-axis vectors a1, a2. At a
 * point, q = (x0, x0', a1, a1', a2, a2') with ' = d/dS along the reference
 * mid-line, so q depends linearly on the nodal values through N_i and
 * N_i'. One Gauss point per linear element along S (reduced integration)
 * keeps the transverse shear free of locking.
 */

#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace pneuma
{
  namespace cables
  {
    using namespace dealii;

    class SolidBeamSection;
    struct BeamMaterial;

    /// The solid-beam terms of one cable.
    class SolidBeamElement
    {
    public:
      /// The element of @p material; @p length_ratio: reference over
      /// unstressed length (prestress).
      SolidBeamElement(const BeamMaterial &material, const double length_ratio);
      ~SolidBeamElement();

      /// A new reference over unstressed length (a staged prestress).
      void
      set_length_ratio(const double length_ratio)
      {
        rho = length_ratio;
      }

      /**
       * Internal forces and tangent of one cell. @p fe_values is reinit'ed
       * on the cell; @p tangent is the unit reference tangent of the cell;
       * @p local_reference and @p local_u the reference values (position,
       * semi-axis vectors) and the unknowns at the cell dofs. @p output, if
       * given, receives the cell averages of output_names().
       */
      void
      cell_terms(const FEValues<1, 3> &fe_values,
                 const Tensor<1, 3>   &tangent,
                 const Vector<double> &local_reference,
                 const Vector<double> &local_u,
                 FullMatrix<double>   *cell_matrix,
                 Vector<double>       *cell_residual,
                 std::vector<double>  *output) const;

      /// Cell fields written to the VTU (axial force, moments, stretches).
      static std::vector<std::string>
      output_names();

      /**
       * A conservative couple M about the fixed axis m = M/|M| on the end
       * section: potential -|M| (w1 theta1 + w2 theta2), theta_k the
       * rotation about m of the semi-axis vector a_k (projected normal to
       * m), tracked continuously from @p theta_previous at
       * @p a_previous (last converged step; zero vectors: from the
       * reference), with weights w_k = sin^2(A_k, m) / sum: a twisting
       * moment acts on both axes, a bending moment on the axis normal to
       * it, so the section is not sheared by the load. Adds to the
       * residual (9 end-node values, components 0-8) and the tangent.
       * @p theta receives the two angles; the section rotation is
       * sum w_k theta_k (section_rotation()).
       */
      static void
      end_moment_terms(const Tensor<1, 3>                &moment,
                       const std::array<Tensor<1, 3>, 2> &A,
                       const std::array<Tensor<1, 3>, 2> &a,
                       const std::array<Tensor<1, 3>, 2> &a_previous,
                       const std::array<double, 2>       &theta_previous,
                       FullMatrix<double>                *node_matrix,
                       Vector<double>                    *node_residual,
                       std::array<double, 2>             *theta);

      /// The weighted section rotation sum w_k theta_k about @p moment.
      static double
      section_rotation(const Tensor<1, 3>                &moment,
                       const std::array<Tensor<1, 3>, 2> &A,
                       const std::array<double, 2>       &theta);

    private:
      std::unique_ptr<SolidBeamSection> section;
      double                            rho;
    };
  } // namespace cables
} // namespace pneuma
