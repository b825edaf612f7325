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
    } // namespace

    void
    ObstacleSums::add(const ObstacleSums &other)
    {
      force += other.force;
      energy += other.energy;
      area += other.area;
      penetration = std::max(penetration, other.penetration);
      points += other.points;
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
                          ObstacleCellOutput                *output) const
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
              const SignedDistance s =
                obstacles[k].shape->distance(x - translations[k]);
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
              add_point_terms(s, g, eps[k], N, w, n, dof, matrix, residual);
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
