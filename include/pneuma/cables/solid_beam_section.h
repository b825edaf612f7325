#pragma once

/**
 * @file
 * The section kernel of the source paper's solid-beam element (section 3.1
 * "Solid-beam finite element", after Konyukhov & Schweizerhof; both cited in
 * doc/references.md): the hyperelastic energy per unit
 * reference length of a beam with an elliptic cross-section, its exact
 * gradient and Hessian (consistent tangent) with respect to the 18
 * kinematic numbers of one mid-line point, and the section resultants.
 *
 * <h3>Kinematics</h3>
 * Let S be the reference arc length along the beam axis, ' = d/dS. The
 * reference configuration at S is given by the mid-line position X0(S) and
 * the two semi-axis vectors A1(S), A2(S) of the elliptic cross-section
 * (from the mid-line node to the ends of the ellipse axes, the paper's
 * node pairs 1-3 and 1-4; |A1| = a and |A2| = b are the semi-axes). The
 * current configuration likewise by x0, a1, a2. A material point is
 * \f[
 *   X(S,z_1,z_2) = X_0(S) + z_1 A_1(S) + z_2 A_2(S),\qquad
 *   x = x_0 + z_1 a_1 + z_2 a_2,\qquad z_1^2 + z_2^2 \le 1,
 * \f]
 * which maps the unit disc exactly (iso-geometrically) onto the ellipse.
 * The covariant bases are the columns
 * \f$G = [X_0' + z_1 A_1' + z_2 A_2',\ A_1,\ A_2]\f$ and
 * \f$g = [x_0' + z_1 a_1' + z_2 a_2',\ a_1,\ a_2]\f$, the deformation
 * gradient is \f$F = g\,G^{-1}\f$ and the reference volume element is
 * \f$dV = \det G\, dS\, dz_1\, dz_2\f$. The energy per unit reference
 * length is
 * \f[
 *   w = \int_{z_1^2+z_2^2\le 1} \Psi(F)\,\det G\; dz_1\, dz_2 .
 * \f]
 * The section field is linear in (z1, z2): the section may stretch, shear
 * and rotate, and its normal may tilt against the mid-line (transverse
 * shear), but it stays plane and elliptic.
 *
 * <h3>Laws</h3>
 * St. Venant-Kirchhoff \f$\Psi = \tfrac{\lambda}{2}(\mathrm{tr}E)^2 + \mu
 * E:E\f$, \f$E = \tfrac12(F^TF - I)\f$, or compressible neo-Hookean
 * \f$\Psi = \tfrac{\mu}{2}(\mathrm{tr}C - 3) - \mu\ln J +
 * \tfrac{\lambda}{2}(\ln J)^2\f$, \f$J = \det F\f$, with the Lamé constants
 * \f$\lambda = E\nu/((1+\nu)(1-2\nu))\f$, \f$\mu = E/(2(1+\nu))\f$.
 *
 * <h3>Unknowns</h3>
 * Per mid-line point the 18 numbers q = (x0, x0', a1, a1', a2, a2'), each
 * a 3-vector; gradient and Hessian index 3*block + component with the
 * blocks in this order (enum SolidBeamSection::Block). The reference Q is
 * ordered the same way. The element assembler chains q with the 1D shape
 * functions N_i(S), N_i'(S) of any degree. w does not depend on x0
 * (translation invariance), so the first three rows of the gradient and of
 * the Hessian are zero.
 *
 * <h3>Quadrature over the section</h3>
 * A polar product rule on the unit disc: n_r Gauss-Legendre points in r on
 * [0,1] with the weight r dr, times n_theta equally spaced angles (exact
 * for trigonometric polynomials of degree < n_theta). A monomial of degree
 * d in (z1, z2) becomes r^(d+1) times a trigonometric polynomial of degree
 * d, so the rule is exact for polynomials of degree min(2 n_r - 2,
 * n_theta - 1). For a prismatic beam (straight, untwisted reference, A'
 * = 0) G is constant and F is linear in z, so the St. Venant-Kirchhoff
 * integrand is a polynomial of degree 4. (3, 5) is the smallest rule that
 * integrates it exactly; the defaults n_r = 3, n_theta = 6 (18 points) add
 * the symmetries z1 -> -z1 and z2 -> -z2 of the section, so that all odd
 * terms vanish exactly also for non-polynomial integrands (neo-Hookean
 * prismatic energy about 300 times more accurate than with 5 angles).
 * Cost (Release, one core): about 35-40 microseconds per evaluate() with
 * the Hessian, 3 without, 0.5 for energy().
 *
 * <h3>Derivatives</h3>
 * g is linear in q: its first column is x0' + z1 a1' + z2 a2', the others
 * a1 and a2. At each section point Psi(F) is differentiated twice with
 * respect to the 9 entries of F by forward automatic differentiation with
 * Trilinos Sacado (the library behind deal.II's Differentiation::AD Sacado
 * types), using statically sized nested numbers SFad<SFad<double,9>,9>:
 * no allocation in the section loop, about 7 times faster than deal.II's
 * dynamically sized sacado_dfad_dfad. P = dPsi/dF and A = d2Psi/dF2 are
 * then chained exactly through the linear maps F = g G^{-1} and g(q):
 * dPsi/dg_a = P G^a (G^a the rows of G^{-1}). Gradient and Hessian are
 * exact to round-off; the Hessian is symmetrised (it is symmetric up to
 * round-off).
 *
 * <h3>Known limitations (documented behaviour, not bugs)</h3>
 * - Poisson-thickness locking: the lateral strains are constant over the
 *   section (a1, a2 do not vary with z), so the section cannot show the
 *   linear-in-z anticlastic lateral contraction of bending. For nu > 0 the
 *   bending stiffness is too large by the factor
 *   (1 - nu)/((1 + nu)(1 - 2 nu)) (1.346 for nu = 0.3) while the axial
 *   stiffness relaxes correctly to E A through the uniform section stretch.
 *   Bending verification therefore uses nu = 0 (tests/solid_beam_section.cc
 *   prints the locking factor). Torsion of a circular section has no
 *   lateral strain and is not affected.
 * - Transverse shear locking of low-order elements along S: the section
 *   directors and the mid-line are interpolated independently, so with
 *   full integration along S a linear element locks in bending; reduced
 *   integration along S (1 Gauss point for linear elements, p points for
 *   degree p) avoids it. That is the assembler's choice; this kernel works
 *   at one point along S.
 * - Neo-Hookean at J <= 0 (or a non-finite state): w, gradient and Hessian
 *   are quiet NaN, so that the Newton solver cuts the step back. A reference
 *   state with det G <= 0 at a section point throws.
 *
 * Reference: A. Konyukhov, K. Schweizerhof, solid-beam element with an
 * exact elliptic cross-section (ref. [5] of the source paper), and the
 * source paper, section 3.1.
 */

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <vector>

namespace pneuma
{
  namespace cables
  {
    using namespace dealii;

    /// Hyperelastic law of the solid-beam continuum.
    enum class BeamLaw
    {
      /// \f$\Psi = \tfrac{\lambda}{2}(\mathrm{tr}E)^2 + \mu E:E\f$.
      saint_venant_kirchhoff,
      /// \f$\Psi = \tfrac{\mu}{2}(\mathrm{tr}C-3) - \mu\ln J +
      /// \tfrac{\lambda}{2}(\ln J)^2\f$.
      neo_hookean
    };

    /// Law and elastic constants of a solid beam.
    struct BeamMaterial
    {
      BeamLaw law            = BeamLaw::saint_venant_kirchhoff;
      double  youngs_modulus = 2e11;
      double  poisson_ratio  = 0.3;

      /// Lamé's first constant E nu / ((1 + nu)(1 - 2 nu)).
      double
      lambda() const;
      /// Shear modulus E / (2 (1 + nu)).
      double
      mu() const;
    };

    /**
     * Stress resultants of the section at one mid-line point, in the
     * current configuration. With the reference area vector of the section
     * \f$N\,dA = (A_1\times A_2)\,dz_1 dz_2 = \det G\, G^1\, dz_1 dz_2\f$
     * (\f$G^1\f$ the first row of \f$G^{-1}\f$, pointing to increasing S)
     * and the first Piola-Kirchhoff stress \f$P = \partial\Psi/\partial
     * F\f$:
     * - force \f$f = \int P\,N\,dA\f$, the force that the part of the beam
     *   beyond S exerts on the part before S (equal to \f$\partial
     *   w/\partial x_0'\f$);
     * - moment \f$m = \int (x - x_0)\times P\,N\,dA\f$ about the current
     *   mid-line point (equal to \f$a_1\times\partial w/\partial a_1' +
     *   a_2\times\partial w/\partial a_2'\f$);
     * - the current frame: \f$t = x_0'/|x_0'|\f$, \f$d_1\f$ the unit part
     *   of \f$a_1\f$ normal to t, \f$d_2 = t\times d_1\f$;
     * - axial force N = f.t (positive in tension), bending moments
     *   M1 = m.d1 (about the a1 axis: bending in the t-a2 plane, stiffness
     *   E pi a b^3/4) and M2 = m.d2 (about the axis normal to a1: bending in
     *   the t-a1 plane, stiffness E pi a^3 b/4), torsion moment T = m.t;
     *   in the linear range m = E I k for a curvature vector k (the rate
     *   of rotation of the section along S, right-hand rule) and
     *   T = G J theta for a twist rate theta;
     * - section stretches |a1|/|A1| and |a2|/|A2|.
     */
    struct SectionResultants
    {
      double       axial_force      = 0.;
      double       bending_moment_1 = 0.;
      double       bending_moment_2 = 0.;
      double       torsion_moment   = 0.;
      double       stretch_1        = 1.;
      double       stretch_2        = 1.;
      Tensor<1, 3> force;
      Tensor<1, 3> moment;
    };

    /**
     * The per-point section kernel of the solid-beam element: energy per
     * unit reference length, its gradient and Hessian with respect to
     * q = (x0, x0', a1, a1', a2, a2'), and the section resultants. See the
     * file documentation for the formulas. The object is immutable after
     * construction and may be shared by threads.
     */
    class SolidBeamSection
    {
    public:
      /// Number of kinematic numbers per point.
      static constexpr unsigned int n_variables = 18;

      /// The six 3-vectors of a point, in the order of Block.
      using State = std::array<Tensor<1, 3>, 6>;

      /// Gradient of w with respect to q, index 3*block + component.
      using Gradient = std::array<double, n_variables>;

      /// Blocks of q (and of Q): 3 components each.
      enum Block : unsigned int
      {
        position               = 0, ///< x0
        position_derivative    = 1, ///< x0'
        semi_axis_1            = 2, ///< a1
        semi_axis_1_derivative = 3, ///< a1'
        semi_axis_2            = 4, ///< a2
        semi_axis_2_derivative = 5  ///< a2'
      };

      /**
       * @p n_r Gauss points in the radius and @p n_theta equally spaced
       * angles over the unit disc (see the file documentation; the
       * defaults integrate the St. Venant-Kirchhoff energy of a prismatic
       * beam exactly).
       */
      explicit SolidBeamSection(const BeamMaterial &material,
                                const unsigned int  n_r     = 3,
                                const unsigned int  n_theta = 6);

      /// Energy per unit reference length w(Q; q).
      double
      energy(const State &Q, const State &q) const;

      /**
       * Energy @p w, its gradient and its Hessian (consistent tangent,
       * symmetric, reinit'ed to 18 x 18) with respect to q.
       */
      void
      evaluate(const State        &Q,
               const State        &q,
               double             &w,
               Gradient           &gradient,
               FullMatrix<double> &hessian) const;

      /// Energy and gradient only (residual assembly), cheaper.
      void
      evaluate(const State &Q,
               const State &q,
               double      &w,
               Gradient    &gradient) const;

      /// Stress resultants of the section (see SectionResultants).
      SectionResultants
      resultants(const State &Q, const State &q) const;

      /// Strain energy per unit reference volume Psi(F) of the law.
      double
      strain_energy_density(const Tensor<2, 3> &F) const;

      /// The material.
      const BeamMaterial &
      get_material() const
      {
        return material;
      }

      /// Points (z1, z2) and weights of the section rule (weights sum to pi).
      const std::vector<std::array<double, 3>> &
      quadrature() const
      {
        return points;
      }

    private:
      BeamMaterial material;
      double       lambda, mu;
      /// (z1, z2, weight) of the polar rule on the unit disc.
      std::vector<std::array<double, 3>> points;
    };
  } // namespace cables
} // namespace pneuma
