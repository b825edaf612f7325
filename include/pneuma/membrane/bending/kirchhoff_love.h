#pragma once

/**
 * @file
 * The kinematics and energies of a Kirchhoff-Love shell on the membrane's
 * surface (doc/theory.md §21 "Shells with bending"), written for any
 * number type so that Sacado's forward-over-forward numbers give their
 * exact gradient and Hessian (deal.II step-72 takes the same route).
 *
 * A point of a cell is described by the parametric derivatives of its
 * position, g = (x_,1, x_,2, x_,11, x_,12, x_,22) (15 numbers; x_,alpha =
 * dx/dxi_alpha on the unit square). The unit normal is n = x_,1 x x_,2 /
 * |x_,1 x x_,2|, the second fundamental form b_ab = x_,ab . n. With the
 * reference's material frame (E_1, E_2) and G = J^-1, J_ia = E_i . X_,a,
 * the change of curvature in that frame is
 *   kappa_ij = G_ai G_bj (x_,ab . n) - B_ij,   B_ij = G_ai G_bj (X_,ab . N)
 * (the tangential parts of x_,ab drop out of b_ab, so no derivative of G
 * enters). The bending energy per reference area is
 *   w = 1/2 kappa : D_b : kappa,   D_b = t^3/12 dS/dE (at E = 0),
 * the bending moments m = D_b : kappa.
 *
 * Across an interior edge (C0 interior penalty, deal.II step-47 on the
 * surface, made geometrically exact): theta is the angle that turns the
 * normal n- of the edge's first cell into the normal n+ of the second,
 * about the current edge tangent a oriented as nu- x n- (nu- the first
 * cell's outward conormal), Theta the same angle in the reference, and
 * delta = theta - Theta the change of the kink (for a plate, the jump of
 * the slope dw/dnu). The edge energy per reference length is
 *   e = {m_nunu} delta + 1/2 (gamma D / h) delta^2,
 * with the mean of both cells' moment normal to the edge. At a clamped
 * edge delta is the rotation of n away from the reference normal N about
 * the edge, and e = -m_nunu delta + 1/2 (gamma D / h) delta^2.
 */

#include <deal.II/base/symmetric_tensor.h>

#include <array>
#include <cmath>

namespace pneuma
{
  namespace membrane
  {
    namespace bending
    {
      /// A 3-vector of numbers.
      template <typename T>
      using Vec = std::array<T, 3>;

      // (Results are stored as T: Sacado's expression templates must not
      // outlive their operands.)
      template <typename T>
      T
      dot(const Vec<T> &a, const Vec<T> &b)
      {
        T r = a[0] * b[0];
        r += a[1] * b[1];
        r += a[2] * b[2];
        return r;
      }

      template <typename T>
      Vec<T>
      cross(const Vec<T> &a, const Vec<T> &b)
      {
        Vec<T> r;
        r[0] = a[1] * b[2] - a[2] * b[1];
        r[1] = a[2] * b[0] - a[0] * b[2];
        r[2] = a[0] * b[1] - a[1] * b[0];
        return r;
      }

      template <typename T>
      Vec<T>
      normalized(const Vec<T> &a)
      {
        using std::sqrt;
        const T norm = sqrt(dot(a, a));
        Vec<T>  r;
        for (unsigned int d = 0; d < 3; ++d)
          r[d] = a[d] / norm;
        return r;
      }

      /// The slot of g holding x_,alpha beta (x_,alpha is slot alpha).
      inline unsigned int
      slot(const unsigned int alpha, const unsigned int beta)
      {
        return 2 + alpha + beta;
      }

      /// Vector slot @p s (0..4) of the point derivatives @p g.
      template <typename T>
      Vec<T>
      part(const T *g, const unsigned int s)
      {
        return {{g[3 * s], g[3 * s + 1], g[3 * s + 2]}};
      }

      /// What a point needs of the reference: the frame map G, the
      /// reference curvature B in the frame, the bending stiffness D_b
      /// (frame components) and the orientation sign of its normal.
      struct PointFrame
      {
        double G[2][2];
        double B[2][2];
        double D[2][2][2][2];
        double sign = 1.;
      };

      /// The unit normal of the point derivatives @p g.
      template <typename T>
      Vec<T>
      unit_normal(const T *g)
      {
        return normalized(cross(part(g, 0), part(g, 1)));
      }

      /// The change of curvature kappa (frame components) at @p g, with
      /// its unit normal @p n (times the frame's sign).
      template <typename T>
      void
      curvature_change(const T          *g,
                       const PointFrame &f,
                       T                 kappa[2][2],
                       Vec<T>           &n)
      {
        n = unit_normal(g);
        for (unsigned int d = 0; d < 3; ++d)
          n[d] *= f.sign;
        T b[2][2];
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int c = a; c < 2; ++c)
            b[a][c] = dot(part(g, slot(a, c)), n);
        b[1][0] = b[0][1];
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            {
              T k = -f.B[i][j];
              for (unsigned int a = 0; a < 2; ++a)
                for (unsigned int c = 0; c < 2; ++c)
                  k += f.G[a][i] * f.G[c][j] * b[a][c];
              kappa[i][j] = k;
            }
      }

      /// The moments m = D_b : kappa.
      template <typename T>
      void
      moments(const T kappa[2][2], const PointFrame &f, T m[2][2])
      {
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            {
              T s = 0. * kappa[0][0];
              for (unsigned int k = 0; k < 2; ++k)
                for (unsigned int l = 0; l < 2; ++l)
                  s += f.D[i][j][k][l] * kappa[k][l];
              m[i][j] = s;
            }
      }

      /// The bending energy per reference area at @p g.
      template <typename T>
      T
      cell_energy(const T *g, const PointFrame &f)
      {
        T      kappa[2][2], m[2][2];
        Vec<T> n;
        curvature_change(g, f, kappa, n);
        moments(kappa, f, m);
        T w = 0. * kappa[0][0];
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            w += 0.5 * m[i][j] * kappa[i][j];
        return w;
      }

      /// The moment normal to an edge with unit conormal @p nu (frame
      /// components) at @p g, and the point's normal @p n.
      template <typename T>
      T
      normal_moment(const T          *g,
                    const PointFrame &f,
                    const double      nu[2],
                    Vec<T>           &n)
      {
        T kappa[2][2], m[2][2];
        curvature_change(g, f, kappa, n);
        moments(kappa, f, m);
        T s = 0. * kappa[0][0];
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            s += nu[i] * nu[j] * m[i][j];
        return s;
      }

      /// What an edge point needs of the reference besides its cells'
      /// frames: the conormal nu- in each cell's frame, the parametric
      /// direction of the edge in the first cell (oriented as nu- x n-),
      /// the reference kink Theta, the penalty gamma D / h and the weight.
      struct EdgeFrame
      {
        PointFrame side[2];
        double     nu[2][2];
        double     tangent[2];
        double     Theta   = 0.;
        double     penalty = 0.;
        double     JxW     = 0.;
      };

      /// The signed angle turning @p from into @p to about @p axis.
      template <typename T>
      T
      turn_angle(const Vec<T> &from, const Vec<T> &to, const Vec<T> &axis)
      {
        using std::atan2;
        const T sine = dot(cross(from, to), axis), cosine = dot(from, to);
        return atan2(sine, cosine);
      }

      /// The current unit edge tangent from the first cell's @p g.
      template <typename T>
      Vec<T>
      edge_tangent(const T *g, const double t[2])
      {
        Vec<T> a;
        for (unsigned int d = 0; d < 3; ++d)
          a[d] = t[0] * g[d] + t[1] * g[3 + d];
        return normalized(a);
      }

      /**
       * The change delta = theta - Theta of the kink at the first
       * derivatives @p v of both cells (12 numbers: x_,1 and x_,2 of the
       * first cell, then of the second): theta turns n- into n+ about the
       * current edge tangent.
       */
      template <typename T>
      T
      edge_kink(const T *v, const EdgeFrame &e)
      {
        Vec<T> n0 = unit_normal(v), n1 = unit_normal(v + 6);
        for (unsigned int d = 0; d < 3; ++d)
          {
            n0[d] *= e.side[0].sign;
            n1[d] *= e.side[1].sign;
          }
        return turn_angle(n0, n1, edge_tangent(v, e.tangent)) - e.Theta;
      }

      /// The moment normal to the edge on side @p side at its point
      /// derivatives @p g (15 numbers).
      template <typename T>
      T
      side_moment(const T *g, const EdgeFrame &e, const unsigned int side)
      {
        Vec<T> n;
        return normal_moment(g, e.side[side], e.nu[side], n);
      }

      /// The clamped edge energy (times its weight) at @p g, the
      /// reference normal @p N (times the frame's sign).
      template <typename T>
      T
      clamped_edge_energy(const T *g, const EdgeFrame &e, const Vec<double> &N)
      {
        Vec<T>  n;
        const T m = normal_moment(g, e.side[0], e.nu[0], n);
        Vec<T>  Nt;
        for (unsigned int d = 0; d < 3; ++d)
          Nt[d] = N[d] + 0. * g[0];
        const T delta = turn_angle(Nt, n, edge_tangent(g, e.tangent));
        return (-m * delta + 0.5 * e.penalty * delta * delta) * e.JxW;
      }

      /**
       * The potential (times its weight) of an applied edge moment @p m
       * [N m/m] at @p g, the reference normal @p N (times the frame's
       * sign) and the reference edge tangent @p A: -m theta, theta the
       * turn of the normal from N about the fixed axis A (an axial
       * moment: conservative, and blind to the normal's tilt along A).
       * atan2 jumps by 2 pi where the normal turns through pi, its
       * gradient and Hessian do not: the residual and the tangent hold for
       * any angle.
       */
      template <typename T>
      T
      edge_moment_energy(const T           *g,
                         const EdgeFrame   &e,
                         const Vec<double> &N,
                         const Vec<double> &A,
                         const double       m)
      {
        Vec<T> Nt, At;
        for (unsigned int d = 0; d < 3; ++d)
          {
            Nt[d] = N[d] + 0. * g[0];
            At[d] = A[d] + 0. * g[0];
          }
        return -m * turn_angle(Nt, unit_normal(g), At) * e.JxW;
      }
    } // namespace bending
  }   // namespace membrane
} // namespace pneuma
