#pragma once

/**
 * @file
 * One contact point of the curve-to-surface penalty contact (source paper
 * section 3.2, equations 7-9; doc/theory.md §10).
 *
 * The slave is a point of the cable mid-line, x_s = (1 - eta) x_0 + eta x_1
 * on a linear cable element; the master is a membrane cell in its current
 * configuration, the tensor-product Lagrange patch
 * \f$\rho(\xi) = \sum_{ij} l_i(\xi^1) l_j(\xi^2)\, y_{ij}\f$ of degree 1 or
 * 2 through the current positions y of the cell's support points. The
 * closest point \f$\xi^*\f$ minimises \f$|x_s - \rho(\xi)|\f$ (Newton on the
 * two convective coordinates); with the unit normal
 * \f$n = \sigma\,\rho_{,1}\times\rho_{,2}/|\rho_{,1}\times\rho_{,2}|\f$
 * (sigma = +-1 turns it towards the contact side) the gap is
 * \f[ \xi^3 = (x_s - \rho(\xi^*))\cdot n - R , \f]
 * and for \f$\xi^3 < 0\f$ the penalty potential per point is
 * \f$\Pi = w\,\tfrac{\varepsilon_N}{2}(\xi^3)^2\f$ (w: the integration
 * weight, a length), so that the contact line load is
 * \f$N = \varepsilon_N \xi^3\f$ (paper eq. 9). Its gradient and Hessian with
 * respect to the slave and master node positions are exact. The gradient
 * is known in closed form at the closest point (envelope theorem: the
 * projection is stationary and \f$x_s - \rho \parallel n\f$, so the
 * variation of n does not enter):
 * \f$\partial\Pi/\partial x_b = w\varepsilon_N\xi^3 N_b(\eta)\,n\f$,
 * \f$\partial\Pi/\partial y_a = -w\varepsilon_N\xi^3\phi_a(\xi^*)\,n\f$.
 * The Hessian is its Jacobian, evaluated with first-order forward automatic
 * differentiation (Trilinos Sacado, statically sized) after two Newton
 * steps of the projection taken in the differentiated numbers from the
 * converged \f$\xi^*\f$; they carry \f$d\xi^{*}\!/dv\f$ (implicit function
 * theorem), i.e. the variation of the normal and of the projection point.
 */

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <utility>
#include <vector>

namespace pneuma
{
  namespace contact
  {
    using namespace dealii;

    /// The current master patch: degree and node positions in lattice
    /// order a = i + (degree + 1) j (node (i, j) at xi = (i, j)/degree).
    struct MasterPatch
    {
      unsigned int              degree = 1;
      std::vector<Tensor<1, 3>> nodes;
      /// +1 or -1: turns rho_1 x rho_2 towards the contact side.
      double sign = 1.;
      /**
       * Smoothed normal field (empty: the facet normal): unit nodal
       * normals nbar_a in lattice order, already turned to the contact
       * side. The gap is then measured along
       * \f$n(\xi) = N/|N|,\ N = \sum_a \phi_a(\xi)\,\bar n_a\f$:
       * the projection solves \f$x_s = \rho(\xi) + g\,n(\xi)\f$ for
       * (xi, g), and the nodal normals are variables of the contact terms
       * (after the master nodes), to be chained to the node positions they
       * come from (NodalNormals).
       */
      std::vector<Tensor<1, 3>> normals;
    };

    /**
     * The current elliptic section of a solid-beam slave: its semi-axis
     * vectors at the two nodes of the cable element. The gap then uses the
     * section's extent along the normal, h(n) = sqrt((a1.n)^2 + (a2.n)^2)
     * (the support function of the ellipse), instead of a fixed radius,
     * and the section unknowns become variables of the contact terms.
     */
    struct SlaveSection
    {
      std::array<Tensor<1, 3>, 2> a1, a2;
    };

    /// Result of a closest-point projection.
    struct Projection
    {
      /// True if the iteration converged with xi inside the cell (within
      /// a small tolerance).
      bool     inside = false;
      Point<2> xi;
      /// |x_s - rho(xi)|, and the gap (x_s - rho).n - R.
      double       distance = 0., gap = 0.;
      Tensor<1, 3> normal;
    };

    /// The point rho(xi) of @p patch.
    Tensor<1, 3>
    position(const MasterPatch &patch, const Point<2> &xi);

    /// The patch's shape functions phi_a(xi) of @p degree (1 or 2), in
    /// lattice order: rho(xi) = sum_a phi_a(xi) y_a.
    std::vector<double>
    shape_values(const unsigned int degree, const Point<2> &xi);

    /// The area element |rho_1 x rho_2| of @p patch at @p xi.
    double
    area_element(const MasterPatch &patch, const Point<2> &xi);

    /// The axis-aligned box (lower, upper corner) of the patch's nodes.
    std::pair<Tensor<1, 3>, Tensor<1, 3>>
    bounding_box(const MasterPatch &patch);

    /// Closest point of @p x on @p patch, starting from @p xi_start.
    Projection
    project(const MasterPatch  &patch,
            const Tensor<1, 3> &x,
            const double        radius,
            const Point<2>     &xi_start = Point<2>(0.5, 0.5));

    /**
     * Penalty energy of one point and, if requested, its gradient and
     * Hessian. Variables: slave node 0 (xyz), slave node 1 (xyz), with a
     * @p section its a1, a2 at node 0 and at node 1 (12), then the master
     * nodes (xyz each, lattice order), then with a smoothed normal field
     * the nodal normals (xyz each, lattice order). @p xi is the converged
     * projection.
     *
     * Smoothed normals: with F = x_s - rho(xi) - g n(xi) = 0, the tangents
     * t_a = rho_a + g n_a of the offset surface and the dual basis
     * m^1, m^2, m (m^a.t_b = delta_ab, m^a.n = 0, m.t_a = 0, m.n = 1), a
     * variation of the variables at fixed (xi, g), dF, moves the solution
     * by dg = m.dF, dxi^a = m^a.dF. The gradient of
     * Pi = w eps_N/2 (g - h(n))^2 is formed from these in closed form and
     * its Jacobian (the Hessian) by first-order Sacado numbers through two
     * Newton steps of the projection.
     */
    double
    penalty_terms(const MasterPatch                 &patch,
                  const std::array<Tensor<1, 3>, 2> &slave,
                  const double                       eta,
                  const double                       radius,
                  const double                       penalty,
                  const double                       weight,
                  const Point<2>                    &xi,
                  Vector<double>                    *gradient,
                  FullMatrix<double>                *hessian,
                  const SlaveSection                *section = nullptr);

    /// Result of the friction law at one point.
    struct FrictionState
    {
      bool slip = false;
      /// Tangential force on the cable per length [N/m] (vector).
      Tensor<1, 3> traction;
      /// Where the stick anchor goes if this state is accepted: the
      /// current anchor (stick) or the point a slip has dragged it to.
      Tensor<1, 3> anchor_target;
    };

    /**
     * Regularised Coulomb friction of one point (doc/theory.md §10.2): the
     * slave sticks elastically (tangential penalty eps_T) to the material
     * point y_a = sum phi_a(xi_a) z_a of an anchor cell (nodes z, fixed
     * convective coordinates xi_a); the trial traction
     * t = -eps_T (I - n n)(x_s - y_a) is limited to |t| <= mu N with
     * N = -eps_N xi3 (slip: t = mu N t/|t|). The force w t acts on the
     * cable point and -w t on the master at the contact point xi.
     * Adds to @p residual (r = f_int - f_ext) and @p jacobian (not
     * symmetric in slip) over the variables of penalty_terms(); the anchor
     * is a material point of the same master cell.
     */
    FrictionState
    friction_terms(const MasterPatch                 &patch,
                   const Point<2>                    &xi_anchor,
                   const std::array<Tensor<1, 3>, 2> &slave,
                   const double                       eta,
                   const double                       radius,
                   const double                       penalty,
                   const double                       tangential_penalty,
                   const double                       mu,
                   const double                       weight,
                   const Point<2>                    &xi,
                   Vector<double>                    *residual,
                   FullMatrix<double>                *jacobian,
                   const SlaveSection                *section = nullptr);
  } // namespace contact
} // namespace pneuma
