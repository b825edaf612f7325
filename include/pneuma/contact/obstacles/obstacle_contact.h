#pragma once

/**
 * @file
 * The penalty contact of the membrane with rigid obstacles at the
 * membrane's quadrature points (doc/theory.md "Rigid obstacles").
 *
 * At a point of the mid-surface x = X + u, the gap to obstacle k, moved
 * by its rigid translation d_k(t), is
 * \f$g = \varphi_k(x - d_k) - t/2\f$ (the half thickness t/2 of the
 * point's region as the offset). The penalty energy
 * \f$\Pi = \int_{\Omega_0} \tfrac12 \epsilon \langle -g\rangle^2\,dA\f$
 * (over the reference surface, \f$\epsilon\f$ [Pa/m]) gives the residual
 * \f$r_{ai} = \int \epsilon\, g\, n_i N_a\,dA\f$ where g < 0 and the
 * symmetric tangent
 * \f$K_{ai,bj} = \int \epsilon N_a N_b (n_i n_j + g\,\varphi_{,ij})\,dA\f$.
 * The nominal contact pressure is \f$p = \epsilon\langle -g\rangle\f$ per
 * reference area, the true one p/J with J = |a_1 x a_2| the area stretch.
 *
 * The default penalty of a cell is \f$\epsilon = f\,E t/h^2\f$: E t = 3 mu t
 * of its region (mu the law's initial shear modulus), h its node spacing
 * (sqrt of its area over the degree). The gap it leaves under a pressure
 * p is p h^2/(f E t): it falls with the mesh as h^2, like the geometric
 * error of the discrete surface, and stays below it for f = 10 at the
 * membrane strains of inflated structures.
 *
 * Coulomb friction (doc/theory.md §19, "Friction"): a point in contact
 * keeps an anchor xi on the obstacle (in its reference position) from
 * the last accepted state; the trial traction on the membrane is
 * \f$t^{tr} = -\epsilon_T P (x - d - \xi)\f$ with P = I - n n, and the
 * traction \f$t = t^{tr}\f$ while \f$|t^{tr}| \le \mu p\f$ (stick),
 * else \f$t = \mu p\, t^{tr}/|t^{tr}|\f$ (slip), p the nominal contact
 * pressure. Its tangent is exact and not symmetric. A point takes its
 * anchor where it is in contact in an accepted state: the step in which
 * it first touches is frictionless for it.
 */

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <pneuma/contact/obstacles/obstacle_parameters.h>
#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/membrane/reference_geometry.h>

#include <limits>
#include <vector>

namespace pneuma
{
  namespace contact
  {
    using namespace dealii;

    /// What the contact with one obstacle adds up over points.
    struct ObstacleSums
    {
      /// Force on the obstacle [N].
      Tensor<1, 3> force;
      /// Penalty energy [J].
      double energy = 0.;
      /// Current area of the points in contact [m^2] (if asked for).
      double area = 0.;
      /// Largest penetration -g [m].
      double penetration = 0.;
      /// Points in contact.
      unsigned int points = 0;
      /// Friction: the sum of |t| w [N] and the points at Coulomb's limit
      /// (slipping).
      double       friction_force = 0.;
      unsigned int slip_points    = 0;

      /// Add @p other (sums, and the larger penetration).
      void
      add(const ObstacleSums &other);
    };

    /// The friction state of one point against one obstacle.
    struct PointFriction
    {
      /// The stick position on the obstacle in its reference position.
      Tensor<1, 3> anchor;
      /// Whether the point has an anchor (it was in contact).
      bool active = false;
    };

    /// Per-cell values for output.
    struct ObstacleCellOutput
    {
      /// Mean true contact pressure over the cell's points [Pa].
      double pressure = 0.;
      /// Smallest gap at the cell's points to any obstacle [m].
      double gap = std::numeric_limits<double>::max();
    };

    /// The reference area of the owned cell @p cell_index.
    double
    cell_area(const membrane::ReferenceGeometry &reference,
              const unsigned int                 cell_index);

    /// The element degree of the cells of @p reference (Q1 or Q2).
    unsigned int
    element_degree(const membrane::ReferenceGeometry &reference);

    /// The contact terms of all obstacles on one membrane cell.
    class ObstacleContact
    {
    public:
      ObstacleContact(const std::vector<ObstacleDefinition> &obstacles,
                      const membrane::MaterialRegions       &materials);

      /// The obstacles' translations d_k(t) + s_k e_k (not concurrently:
      /// it sets the time of their functions), with s_k the positions of
      /// the force-controlled obstacles (set_positions; 0 for the others).
      std::vector<Tensor<1, 3>>
      translations(const double t) const;

      /// The force-controlled obstacles' positions s_k along their Force
      /// direction [m] (one per obstacle).
      void
      set_positions(const std::vector<double> &s)
      {
        positions = s;
      }
      const std::vector<double> &
      get_positions() const
      {
        return positions;
      }

      /// Where the terms of one obstacle go instead of the cell's matrix
      /// and residual (a force-controlled obstacle's own, for its border
      /// couplings).
      struct Sink
      {
        FullMatrix<double> *matrix   = nullptr;
        Vector<double>     *residual = nullptr;
      };

      /// Penalty of obstacle @p k on a cell of region @p id with
      /// reference area @p area and element degree @p degree [Pa/m].
      double
      penalty(const unsigned int       k,
              const types::material_id id,
              const double             area,
              const unsigned int       degree) const;

      /**
       * The contact terms of the cell @p cell_index of @p reference, of
       * region @p id, at its displacement @p local_u, with the obstacles
       * at @p translations: add the residual and
       * tangent to @p residual and @p matrix (either may be nullptr), the
       * sums per obstacle to @p sums (one per obstacle; the areas only if
       * @p with_area) and, if given, the cell's output values. With
       * friction, @p anchors holds the cell's friction state (point q,
       * obstacle k at q * size() + k; nullptr: frictionless), and
       * @p accepted, if given, receives the state this one leaves when it
       * is accepted. With @p own, the terms of obstacle k go to
       * (*own)[k] where its residual is given. May run concurrently on
       * other cells.
       */
      void
      cell(const types::material_id           id,
           const membrane::ReferenceGeometry &reference,
           const unsigned int                 cell_index,
           const std::vector<double>         &local_u,
           const std::vector<Tensor<1, 3>>   &translations,
           FullMatrix<double>                *matrix,
           Vector<double>                    *residual,
           std::vector<ObstacleSums>         &sums,
           const bool                         with_area,
           ObstacleCellOutput                *output   = nullptr,
           const PointFriction               *anchors  = nullptr,
           PointFriction                     *accepted = nullptr,
           const std::vector<Sink>           *own      = nullptr) const;

      /// Does any obstacle have friction?
      bool
      has_friction() const;

      /// Number of obstacles.
      unsigned int
      size() const
      {
        return obstacles.size();
      }

    private:
      const std::vector<ObstacleDefinition> &obstacles;
      const membrane::MaterialRegions       &materials;
      std::vector<double>                    positions;
    };
  } // namespace contact
} // namespace pneuma
