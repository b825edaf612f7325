#include <pneuma/contact/derived_penalty.h>
#include <pneuma/contact/obstacles/obstacle_contact.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      /// Cell dof of component c at node a: dof[a][c].
      using NodeDofs =
        std::array<std::array<unsigned int, 3>, membrane::max_cell_nodes>;

      NodeDofs
      node_dofs(const membrane::ReferenceGeometry &reference)
      {
        NodeDofs dof{};
        for (unsigned int i = 0; i < 3 * reference.n_nodes(); ++i)
          dof[reference.node(i)][reference.component(i)] = i;
        return dof;
      }

      /// Current position and area stretch J = |a_1 x a_2| at point q.
      Point<3>
      current_point(const membrane::ReferenceGeometry &reference,
                    const unsigned int                 cell_index,
                    const unsigned int                 q,
                    const NodeDofs                    &dof,
                    const std::vector<double>         &local_u,
                    double                            *area_stretch)
      {
        const auto   &p  = reference.point(cell_index, q);
        const double *N  = reference.shape_values(q);
        const auto   *dN = reference.shape_derivatives(cell_index, q);
        Point<3>      x(p.X[0], p.X[1], p.X[2]);
        Tensor<1, 3>  a[2];
        for (unsigned int alpha = 0; alpha < 2; ++alpha)
          for (unsigned int c = 0; c < 3; ++c)
            a[alpha][c] = p.E[alpha][c];
        for (unsigned int n = 0; n < reference.n_nodes(); ++n)
          for (unsigned int c = 0; c < 3; ++c)
            {
              const double u = local_u[dof[n][c]];
              x[c] += N[n] * u;
              a[0][c] += dN[n][0] * u;
              a[1][c] += dN[n][1] * u;
            }
        if (area_stretch != nullptr)
          *area_stretch = cross_product_3d(a[0], a[1]).norm();
        return x;
      }

      /**
       * The terms of one point in contact (gap @p g < 0, penalty @p eps,
       * weight @p w, shape values @p N of its @p n nodes): -p n N_a into
       * @p residual and eps N_a N_b (n n + g d(n)/dx) into @p matrix (either
       * may be nullptr).
       */
      void
      add_point_terms(const SignedDistance &s,
                      const double          g,
                      const double          eps,
                      const double         *N,
                      const double          w,
                      const unsigned int    n,
                      const NodeDofs       &dof,
                      FullMatrix<double>   *matrix,
                      Vector<double>       *residual)
      {
        if (residual != nullptr)
          for (unsigned int a = 0; a < n; ++a)
            for (unsigned int c = 0; c < 3; ++c)
              (*residual)[dof[a][c]] += eps * g * s.normal[c] * N[a] * w;
        if (matrix == nullptr)
          return;
        Tensor<2, 3> D; // d(eps g n)/dx
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int e = 0; e < 3; ++e)
            D[c][e] = eps * (s.normal[c] * s.normal[e] + g * s.hessian[c][e]);
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            {
              const double NN = N[a] * N[b] * w;
              for (unsigned int c = 0; c < 3; ++c)
                for (unsigned int e = 0; e < 3; ++e)
                  (*matrix)(dof[a][c], dof[b][e]) += NN * D[c][e];
            }
      }

      /// The friction traction of one point and whether it slips.
      struct Traction
      {
        Tensor<1, 3> t;
        bool         slip = false;
        /// At Coulomb's limit (to round-off): slipping, or an accepted
        /// slip whose anchor was just dragged.
        bool at_limit = false;
      };

      /**
       * Coulomb friction of one point in contact (doc/theory.md §19): at
       * @p x_rel = x - d with its @p anchor, nominal pressure @p p, normal
       * and tangential penalties @p eps, @p eps_t and coefficient @p mu,
       * the traction t on the membrane; -t N_a into @p residual and
       * -N_a N_b dt/dx into @p matrix (either may be nullptr).
       */
      Traction
      add_friction_terms(const SignedDistance &s,
                         const Tensor<1, 3>   &x_rel,
                         const Tensor<1, 3>   &anchor,
                         const double          p,
                         const double          eps,
                         const double          eps_t,
                         const double          mu,
                         const double         *N,
                         const double          w,
                         const unsigned int    n,
                         const NodeDofs       &dof,
                         FullMatrix<double>   *matrix,
                         Vector<double>       *residual)
      {
        const Tensor<1, 3> v    = x_rel - anchor;
        const double       vn   = v * s.normal;
        const Tensor<1, 3> t_tr = -eps_t * (v - vn * s.normal);
        const double       norm = t_tr.norm();
        Traction           r;
        r.slip     = norm > mu * p;
        r.at_limit = norm >= mu * p * (1. - 1e-9);
        r.t        = r.slip ? (mu * p / norm) * t_tr : t_tr;
        if (residual != nullptr)
          for (unsigned int a = 0; a < n; ++a)
            for (unsigned int c = 0; c < 3; ++c)
              (*residual)[dof[a][c]] -= r.t[c] * N[a] * w;
        if (matrix == nullptr)
          return r;
        // d t_tr/dx = -eps_t (P - (v.n) H - n (H v)^T), H = d n/dx.
        const Tensor<1, 3> Hv = s.hessian * v;
        Tensor<2, 3>       D;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            D[i][j] = -eps_t
                      * ((i == j ? 1. : 0.) - s.normal[i] * s.normal[j]
                         - vn * s.hessian[i][j] - s.normal[i] * Hv[j]);
        if (r.slip)
          {
            // t = mu p e, e = t_tr/|t_tr|, dp/dx = -eps n.
            const Tensor<1, 3> e = t_tr / norm;
            Tensor<2, 3>       slip;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                {
                  double projected = 0.;
                  for (unsigned int k = 0; k < 3; ++k)
                    projected += ((i == k ? 1. : 0.) - e[i] * e[k]) * D[k][j];
                  slip[i][j] =
                    -mu * eps * e[i] * s.normal[j] + mu * p / norm * projected;
                }
            D = slip;
          }
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            {
              const double NN = N[a] * N[b] * w;
              for (unsigned int c = 0; c < 3; ++c)
                for (unsigned int e = 0; e < 3; ++e)
                  (*matrix)(dof[a][c], dof[b][e]) -= NN * D[c][e];
            }
        return r;
      }
    } // namespace

    void
    ObstacleSums::add(const ObstacleSums &other)
    {
      force += other.force;
      energy += other.energy;
      area += other.area;
      penetration = std::max(penetration, other.penetration);
      points += other.points;
      friction_force += other.friction_force;
      slip_points += other.slip_points;
    }

    bool
    ObstacleContact::has_friction() const
    {
      for (const auto &def : obstacles)
        if (def.friction > 0.)
          return true;
      return false;
    }

    ObstacleContact::ObstacleContact(
      const std::vector<ObstacleDefinition> &obstacles,
      const membrane::MaterialRegions       &materials)
      : obstacles(obstacles)
      , materials(materials)
    {
    }

    std::vector<Tensor<1, 3>>
    ObstacleContact::translations(const double t) const
    {
      std::vector<Tensor<1, 3>> d(obstacles.size());
      for (unsigned int k = 0; k < obstacles.size(); ++k)
        {
          auto &f = *obstacles[k].displacement;
          f.set_time(t);
          for (unsigned int c = 0; c < 3; ++c)
            d[k][c] = f.value(Point<3>(), c);
          if (k < positions.size())
            d[k] += positions[k] * obstacles[k].force_direction;
        }
      return d;
    }

    double
    ObstacleContact::penalty(const unsigned int       k,
                             const types::material_id id,
                             const double             area,
                             const unsigned int       degree) const
    {
      const auto &def = obstacles[k];
      if (def.penalty > 0.)
        return def.penalty;
      return derived_penalty(materials[id], area, degree, def.penalty_factor);
    }

    void
    ObstacleContact::cell(const types::material_id           id,
                          const membrane::ReferenceGeometry &reference,
                          const unsigned int                 cell_index,
                          const std::vector<double>         &local_u,
                          const std::vector<Tensor<1, 3>>   &translations,
                          FullMatrix<double>                *matrix,
                          Vector<double>                    *residual,
                          std::vector<ObstacleSums>         &sums,
                          const bool                         with_area,
                          ObstacleCellOutput                *output,
                          const PointFriction               *anchors,
                          PointFriction                     *accepted,
                          const std::vector<Sink>           *own) const
    {
      const unsigned int n_q = reference.n_q_points(), n = reference.n_nodes();
      const NodeDofs     dof  = node_dofs(reference);
      const double       area = cell_area(reference, cell_index);
      // Each obstacle's penalty on this cell (0: it does not act here).
      std::array<double, max_obstacles> eps{};
      for (unsigned int k = 0; k < obstacles.size(); ++k)
        if (obstacles[k].touches(id))
          eps[k] = penalty(k, id, area, element_degree(reference));
      const double offset  = 0.5 * materials[id].thickness;
      const bool   stretch = with_area || output != nullptr;
      // For the output: the contact force and the current area.
      double force = 0., current_area = 0.;
      for (unsigned int q = 0; q < n_q; ++q)
        {
          double         J = 1.;
          const Point<3> x = current_point(
            reference, cell_index, q, dof, local_u, stretch ? &J : nullptr);
          const double  w = reference.point(cell_index, q).JxW;
          const double *N = reference.shape_values(q);
          current_area += J * w;
          for (unsigned int k = 0; k < obstacles.size(); ++k)
            {
              const unsigned int qk = q * obstacles.size() + k;
              if (accepted != nullptr)
                accepted[qk] = PointFriction();
              const Tensor<1, 3>   x_rel = x - translations[k];
              const SignedDistance s =
                obstacles[k].shape->distance(Point<3>(x_rel));
              const double g = s.phi - offset;
              if (output != nullptr)
                output->gap = std::min(output->gap, g);
              if (eps[k] == 0. || g >= 0.)
                continue;
              const double  p   = -eps[k] * g; // nominal pressure
              ObstacleSums &sum = sums[k];
              sum.force -= p * w * s.normal;
              sum.energy += 0.5 * eps[k] * g * g * w;
              sum.penetration = std::max(sum.penetration, -g);
              ++sum.points;
              if (with_area)
                sum.area += J * w;
              force += p * w;
              FullMatrix<double> *matrix_k   = matrix;
              Vector<double>     *residual_k = residual;
              if (own != nullptr && (*own)[k].residual != nullptr)
                {
                  matrix_k   = (*own)[k].matrix;
                  residual_k = (*own)[k].residual;
                }
              add_point_terms(s, g, eps[k], N, w, n, dof, matrix_k, residual_k);
              const auto &def = obstacles[k];
              if (anchors == nullptr || def.friction == 0.)
                continue;
              const double eps_t =
                def.tangential_penalty > 0. ? def.tangential_penalty : eps[k];
              const PointFriction &f = anchors[qk];
              Traction             r;
              if (f.active)
                {
                  r = add_friction_terms(s,
                                         x_rel,
                                         f.anchor,
                                         p,
                                         eps[k],
                                         eps_t,
                                         def.friction,
                                         N,
                                         w,
                                         n,
                                         dof,
                                         matrix_k,
                                         residual_k);
                  sum.force -= w * r.t;
                  sum.friction_force += r.t.norm() * w;
                  sum.slip_points += r.at_limit ? 1 : 0;
                }
              // Accepted: a sticking point keeps its anchor, a slipping
              // one is dragged to where its traction is mu p, a new one
              // sticks where it is.
              if (accepted != nullptr)
                accepted[qk] = {!f.active ? x_rel
                                : r.slip  ? x_rel + r.t / eps_t
                                          : f.anchor,
                                true};
            }
        }
      if (output != nullptr && current_area > 0.)
        output->pressure = force / current_area;
    }

    double
    cell_area(const membrane::ReferenceGeometry &reference,
              const unsigned int                 cell_index)
    {
      double area = 0.;
      for (unsigned int q = 0; q < reference.n_q_points(); ++q)
        area += reference.point(cell_index, q).JxW;
      return area;
    }

    unsigned int
    element_degree(const membrane::ReferenceGeometry &reference)
    {
      return reference.n_nodes() == 4 ? 1 : 2;
    }
  } // namespace contact
} // namespace pneuma
