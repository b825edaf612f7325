#pragma once

/**
 * @file
 * Assumed membrane strains of a Q2 cell (MITC9 in-plane tying, Bucalem &
 * Bathe, Int. J. Numer. Meth. Engng 36 (1993) 3729-3754), the remedy of
 * membrane locking on curved shells (doc/theory.md §21.6).
 *
 * On a curved Q2 cell the inextensional bending modes of the surface are
 * not in the space of displacements with zero membrane strain, so the
 * stiff membrane energy keeps a coarse shell from bending (the
 * Scordelis-Lo roof reaches 0.83 of its deflection on 8 x 8 cells). The
 * assumed strains relax that constraint: the covariant Green-Lagrange
 * strains
 * \f[ E_{ij} = \tfrac12 (g_i\cdot g_j - G_i\cdot G_j),\qquad
 *     g_i = G_i + \partial u/\partial\xi_i \f]
 * are sampled at tying points in the unit cell's coordinates
 * \f$(r, s)\f$ on \f$[-1, 1]^2\f$ and interpolated:
 * - E_rr at r = ±a, s ∈ {-b, 0, b}: linear in r, quadratic in s;
 * - E_ss at r ∈ {-b, 0, b}, s = ±a: quadratic in r, linear in s;
 * - E_rs at r, s = ±a: bilinear;
 *
 * with a = 1/sqrt(3), b = sqrt(3/5). The strain of the material frame
 * (E_1, E_2) at a Gauss point is \f$E_{\alpha\beta} = c_{\alpha i}
 * c_{\beta j} E_{ij}\f$ with \f$c_{\alpha i} = E_\alpha\cdot G^i\f$ (the
 * contravariant base vectors). The interpolation reproduces covariant
 * strains that are linear in the direction sampled at two points and
 * quadratic across it, so a constant strain on a parallelogram cell is
 * exact; the tangent follows from these strains exactly (the geometric
 * part through the tying points' second derivatives).
 *
 * The class holds what is the same on every cell (the tying points, the
 * shape functions' derivatives there, the interpolation weights at the
 * Gauss points); TyingGeometry holds a cell's reference vectors.
 */

#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>

#include <array>
#include <vector>

namespace pneuma
{
  namespace membrane
  {
    using namespace dealii;

    /// A cell's reference data for assumed strains: the covariant base
    /// vectors G_i at the tying points and c_{alpha i} = E_alpha . G^i at
    /// the Gauss points (unit-cell coordinates xi in [0, 1]).
    struct TyingGeometry
    {
      static constexpr unsigned int n_tying = 16, n_q = 9;
      double                        G[n_tying][2][3];
      double                        c[n_q][2][2];
    };

    /// The current state of a cell's tying points: the covariant strains
    /// and the deformed base vectors g_i.
    struct TyingState
    {
      double       E[TyingGeometry::n_tying];
      Tensor<1, 3> g[TyingGeometry::n_tying][2];
    };

    class AssumedStrains
    {
    public:
      static constexpr unsigned int n_tying = TyingGeometry::n_tying;
      static constexpr unsigned int n_q     = TyingGeometry::n_q;
      static constexpr unsigned int n_node  = 9;

      /// For the scalar base of a Q2 FESystem @p fe (node a = base
      /// function a) and the Gauss rule QGauss<2>(3).
      explicit AssumedStrains(const FiniteElement<2, 3> &fe);

      /// The tying points (for an FEValues with update_jacobians).
      const Quadrature<2> &
      tying_points() const
      {
        return tying;
      }

      /// A cell's TyingGeometry from the jacobians at the tying points
      /// (@p at_tying), the inverse jacobians at the Gauss points
      /// (@p at_gauss) and the material frame E_alpha[q][alpha][d].
      void
      reference(const FEValues<2, 3> &at_tying,
                const FEValues<2, 3> &at_gauss,
                const double (*frame)[2][3],
                TyingGeometry &cell) const;

      /// The tying points' strains and base vectors from the nodal
      /// displacements u_node[a][d]; E = 1/2 (G.w + w.G + w.w) with
      /// w = du/dxi, without the cancellation of g.g - G.G.
      void
      state(const TyingGeometry                      &cell,
            const std::vector<std::array<double, 3>> &u_node,
            TyingState                               &s) const;

      /// The assumed strain of the material frame at Gauss point @p q.
      SymmetricTensor<2, 2>
      strain(const TyingGeometry &cell,
             const TyingState    &s,
             const unsigned int   q) const;

      /// C = I + 2 E of the assumed strain at Gauss point @p q, as the
      /// laws take it.
      SymmetricTensor<2, 2>
      right_cauchy_green(const TyingGeometry &cell,
                         const TyingState    &s,
                         const unsigned int   q) const
      {
        return unit_symmetric_tensor<2>() + 2. * strain(cell, s, q);
      }

      /// The derivatives of the tying strains by the nodal displacements,
      /// node-major (dof 3 a + d): dE[t][3 a + d].
      void
      strain_derivatives(const TyingState &s, double (*dE)[3 * n_node]) const;

      /// Adds the weights of a Gauss point's stress S (material frame) to
      /// @p w: w_t += HdA L_t(q) S^ij (twice for E_rs), S^ij = c_ai c_bj
      /// S_ab the contravariant stress; the internal force is then
      /// sum_t w_t dE_t/du.
      void
      add_stress_weights(const TyingGeometry         &cell,
                         const unsigned int           q,
                         const SymmetricTensor<2, 2> &S,
                         const double                 HdA,
                         double                      *w) const;

      /// f[3 a + d] += sum_t w_t dE_t/du_ad.
      void
      add_forces(const double (*dE)[3 * n_node],
                 const double *w,
                 double       *f) const;

      /// The material stiffness HdA B^T D B of Gauss point q into the
      /// upper node blocks (node b >= a) of the node-major K (27 x 27),
      /// B the derivative of the assumed strain (E_11, E_22, 2 E_12) and
      /// Dv the law's tangent in that Voigt order.
      void
      add_material_stiffness(const TyingGeometry &cell,
                             const unsigned int   q,
                             const double (*dE)[3 * n_node],
                             const double (*Dv)[3],
                             const double HdA,
                             double      *K) const;

      /// The geometric stiffness sum_t w_t d2E_t/du du into the upper
      /// node blocks of K.
      void
      add_geometric_stiffness(const double *w, double *K) const;

      /// Component (0: rr, 1: ss, 2: rs) sampled at tying point t.
      unsigned int
      component(const unsigned int t) const
      {
        return t < 6 ? 0 : (t < 12 ? 1 : 2);
      }
      /// The interpolation weight of tying point t at Gauss point q.
      double
      weight(const unsigned int q, const unsigned int t) const
      {
        return L[q][t];
      }
      /// dN_a/dxi_i at tying point t: [a][i].
      const std::array<double, 2> *
      derivatives(const unsigned int t) const
      {
        return dN[t].data();
      }

    private:
      Quadrature<2>                                                  tying;
      std::array<std::array<double, n_tying>, n_q>                   L;
      std::array<std::array<std::array<double, 2>, n_node>, n_tying> dN;
    };
  } // namespace membrane
} // namespace pneuma
