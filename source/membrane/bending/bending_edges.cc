#include <deal.II/base/parsed_function.h>
#include <deal.II/base/quadrature_lib.h>

#include <pneuma/membrane/bending/bending_edges.h>
#include <pneuma/membrane/bending/point_geometry.h>
#include <pneuma/membrane/bending/sacado_energy.h>
#include <pneuma/membrane/membrane_subsystem.h>

#include <algorithm>
#include <type_traits>

namespace pneuma
{
  namespace membrane
  {
    namespace bending
    {
      namespace
      {
        using DofIndex =
          std::array<std::array<unsigned int, 3>, max_cell_nodes>;

        struct EdgeScratch : FaceTerms::Scratch
        {
          EdgeScratch(const MembraneSubsystem &membrane)
            : base(membrane.dof_handler().get_fe().base_element(0))
            , nodes{{NodePositions(membrane.mapping(), base),
                     NodePositions(membrane.mapping(), base)}}
            , dof(node_dofs(membrane.dof_handler().get_fe()))
            , degree(membrane.degree())
            , edge(degree + 1)
            , cell(degree + 1)
          {
          }
          const FiniteElement<2, 3>              &base;
          std::array<NodePositions, 2>            nodes;
          DofIndex                                dof;
          unsigned int                            degree;
          QGauss<1>                               edge;
          QGauss<2>                               cell;
          std::array<std::vector<Vec<double>>, 2> X, x;
          std::array<double, 30 * 30>             hessian;
        };

        struct EdgeRecord : FaceTerms::Record
        {
          double energy = 0.;
          /// An edge moment's load on the cell's dofs (the external
          /// force; empty without one).
          Vector<double>                       load;
          std::vector<types::global_dof_index> dofs;
          /// A clamped edge's boundary and the moment its clamp exerts
          /// (BendingEdges::clamp_moments).
          bool               clamped  = false;
          types::boundary_id boundary = 0;
          Tensor<1, 3>       clamp_moment;
        };

        Vec<double>
        warp_of(const ShellContext                           &context,
                const DoFHandler<2, 3>::active_cell_iterator &cell)
        {
          const Tensor<1, 3> w =
            context.membrane->material_regions()[cell->material_id()].warp(
              context.membrane->geometry(), cell);
          return {{w[0], w[1], w[2]}};
        }

        /// Area of the cell with nodes @p X over the length of its face
        /// @p face: the cell's size across the edge.
        double
        size_across(const EdgeScratch              &s,
                    const std::vector<Vec<double>> &X,
                    const unsigned int              face)
        {
          double area = 0., length = 0., G[15];
          for (unsigned int q = 0; q < s.cell.size(); ++q)
            {
              point_derivatives(X,
                                shape_derivatives(s.base, s.cell.point(q)),
                                G);
              const Vec<double> m = cross(part(G, 0), part(G, 1));
              area += std::sqrt(dot(m, m)) * s.cell.weight(q);
            }
          const auto t = face_direction(face);
          for (unsigned int q = 0; q < s.edge.size(); ++q)
            {
              point_derivatives(
                X,
                shape_derivatives(s.base, face_point(face, s.edge.point(q)[0])),
                G);
              Vec<double> T;
              for (unsigned int c = 0; c < 3; ++c)
                T[c] = t[0] * G[c] + t[1] * G[3 + c];
              length += std::sqrt(dot(T, T)) * s.edge.weight(q);
            }
          return area / length;
        }

        /**
         * The reference data of edge point @p xi0 on face @p face of the
         * first cell (nodes s.X[0], stiffness k0): its frame, the edge's
         * oriented parametric direction, conormal and weight; the second
         * side's part is filled by the caller. Returns the point's
         * reference normal.
         */
        Vec<double>
        first_side(const EdgeScratch      &s,
                   const unsigned int      face,
                   const double            weight,
                   const ShapeDerivatives &shape,
                   const Vec<double>      &warp,
                   const RegionStiffness  &k0,
                   EdgeFrame              &e,
                   Vec<double>            &nu,
                   Vec<double>            &T)
        {
          double G[15];
          point_derivatives(s.X[0], shape, G);
          const ReferencePoint ref = reference_point(G, warp, k0.D, 1.);
          const auto           t   = face_direction(face);
          const auto           o   = face_outward(face);
          Vec<double>          out;
          for (unsigned int c = 0; c < 3; ++c)
            {
              T[c]   = t[0] * G[c] + t[1] * G[3 + c];
              out[c] = o[0] * G[c] + o[1] * G[3 + c];
            }
          nu = normalized(cross(T, ref.N));
          if (dot(nu, out) < 0.)
            for (auto &v : nu)
              v = -v;
          const double sigma = dot(cross(nu, ref.N), T) > 0. ? 1. : -1.;
          e.tangent[0]       = sigma * t[0];
          e.tangent[1]       = sigma * t[1];
          for (unsigned int c = 0; c < 3; ++c)
            T[c] *= sigma;
          e.side[0]  = ref.frame;
          e.nu[0][0] = dot(nu, ref.E1);
          e.nu[0][1] = dot(nu, ref.E2);
          e.JxW      = std::sqrt(dot(T, T)) * weight;
          return ref.N;
        }

        /// Gather the current nodes of side @p side from @p local_u.
        void
        current_nodes(EdgeScratch               &s,
                      const unsigned int         side,
                      const DofIndex            &index,
                      const std::vector<double> &local_u)
        {
          s.x[side] = s.X[side];
          for (unsigned int a = 0; a < s.x[side].size(); ++a)
            for (unsigned int c = 0; c < 3; ++c)
              s.x[side][a][c] += local_u[index[a][c]];
        }

        /**
         * The edge moment m(X, t) at edge point @p xi (its @p shape, frame
         * @p e, reference normal @p N and tangent @p T, current point
         * derivatives @p g): its residual and load stiffness, and its
         * external force (minus the residual) into @p load.
         */
        void
        add_edge_moment(EdgeScratch                        &s,
                        const Point<2>                     &xi,
                        const ShapeDerivatives             &shape,
                        const EdgeFrame                    &e,
                        const Vec<double>                  &N,
                        const Vec<double>                  &T,
                        const double                       *g,
                        FullMatrix<double>                 *matrix,
                        Vector<double>                     *residual,
                        Vector<double>                     &load,
                        const Functions::ParsedFunction<3> &moment)
        {
          const Vec<double> X      = position(s.base, s.X[0], xi);
          const double      m      = moment.value(Point<3>(X[0], X[1], X[2]));
          const Vec<double> A      = normalized(T);
          const auto        energy = [&](auto *v) {
            using Number = std::decay_t<decltype(*v)>;
            Number en    = edge_moment_energy(v, e, N, A, m);
            return en;
          };
          double gradient[15];
          differentiate<15>(g,
                            energy,
                            gradient,
                            matrix ? s.hessian.data() : nullptr);
          add_point_terms(
            1, &shape, &s.dof, gradient, s.hessian.data(), residual, matrix);
          for (unsigned int i = 0; i < 15; ++i)
            gradient[i] = -gradient[i];
          add_point_terms(1, &shape, &s.dof, gradient, nullptr, &load, nullptr);
        }

        /**
         * The interior edge energy e = ({m} delta + gamma D/(2h) delta^2)
         * JxW at the 30 point derivatives @p g of both cells: its value,
         * gradient and (if @p hessian) Hessian, assembled from the kink's
         * derivatives in the 12 first derivatives and each side's moment's
         * in its 15 (Sacado at 12 and 15 variables instead of 30: the
         * Hessian's cost falls about fourfold),
         *   de  = delta/2 (dm- + dm+) + ({m} + p delta) d delta,
         *   d2e = delta/2 (d2m- + d2m+) + ({m} + p delta) d2 delta
         *         + p d delta d delta + (dm d delta + d delta dm)/2.
         */
        double
        interior_point(const double    *g,
                       const EdgeFrame &e,
                       double          *gradient,
                       double          *hessian)
        {
          const auto at = [](const unsigned int k) { // kink variable -> g
            return k < 6 ? k : k + 9;
          };
          double v[12], gd[12], hd[144];
          for (unsigned int k = 0; k < 12; ++k)
            v[k] = g[at(k)];
          const double delta = differentiate<12>(
            v,
            [&](auto *x) { return edge_kink(x, e); },
            gd,
            hessian ? hd : nullptr);
          double m[2], gm[2][15], hm[2][225];
          for (unsigned int side = 0; side < 2; ++side)
            m[side] = differentiate<15>(
              g + 15 * side,
              [&](auto *x) { return side_moment(x, e, side); },
              gm[side],
              hessian ? hm[side] : nullptr);
          const double w = e.JxW, p = e.penalty, mean = 0.5 * (m[0] + m[1]);
          const double c = mean + p * delta;
          for (unsigned int side = 0; side < 2; ++side)
            for (unsigned int k = 0; k < 15; ++k)
              gradient[15 * side + k] = 0.5 * delta * gm[side][k] * w;
          for (unsigned int k = 0; k < 12; ++k)
            gradient[at(k)] += c * gd[k] * w;
          if (hessian)
            {
              std::fill(hessian, hessian + 900, 0.);
              for (unsigned int side = 0; side < 2; ++side)
                for (unsigned int k = 0; k < 15; ++k)
                  {
                    const unsigned int i = 15 * side + k;
                    for (unsigned int l = 0; l < 15; ++l)
                      hessian[i * 30 + 15 * side + l] +=
                        0.5 * delta * hm[side][k * 15 + l] * w;
                    for (unsigned int l = 0; l < 12; ++l)
                      {
                        const double a = 0.5 * gm[side][k] * gd[l] * w;
                        hessian[i * 30 + at(l)] += a;
                        hessian[at(l) * 30 + i] += a;
                      }
                  }
              for (unsigned int k = 0; k < 12; ++k)
                for (unsigned int l = 0; l < 12; ++l)
                  hessian[at(k) * 30 + at(l)] +=
                    (c * hd[k * 12 + l] + p * gd[k] * gd[l]) * w;
            }
          return (mean * delta + 0.5 * p * delta * delta) * w;
        }
      } // namespace

      BendingEdges::BendingEdges(const ShellContext &context)
        : context(context)
      {
      }

      unsigned int
      BendingEdges::n_quadrature_points() const
      {
        return context.membrane->degree() + 1;
      }

      void
      BendingEdges::begin(const Assembly &a)
      {
        sum = 0.;
        clamp_moment.clear();
        external =
          context.parameters.moment_edges.empty() ? nullptr : a.external;
        constraints = a.constraints;
        if (!context.parameters.moment_edges.empty())
          context.parameters.moment->set_time(a.time);
      }

      std::unique_ptr<FaceTerms::Scratch>
      BendingEdges::new_scratch() const
      {
        return std::make_unique<EdgeScratch>(*context.membrane);
      }

      std::unique_ptr<FaceTerms::Record>
      BendingEdges::new_record() const
      {
        return std::make_unique<EdgeRecord>();
      }

      void
      BendingEdges::interior_face(const FEInterfaceValues<2, 3> &fiv,
                                  const std::vector<double>     &local_u,
                                  FullMatrix<double>            *matrix,
                                  Vector<double>                *residual,
                                  FaceTerms::Scratch            &scratch_data,
                                  FaceTerms::Record &record_data) const
      {
        auto &record   = static_cast<EdgeRecord &>(record_data);
        record.energy  = 0.;
        record.clamped = false;
        // (A record is reused from face to face: an edge moment's load of
        // an earlier boundary face must not be committed again.)
        record.load.reinit(0);
        std::array<DoFHandler<2, 3>::active_cell_iterator, 2> cell;
        std::array<unsigned int, 2>                           face;
        std::array<const RegionStiffness *, 2>                k;
        for (unsigned int i = 0; i < 2; ++i)
          {
            const auto &fv = fiv.get_fe_face_values(i);
            cell[i]        = DoFHandler<2, 3>::active_cell_iterator(
              &context.membrane->triangulation(),
              fv.get_cell()->level(),
              fv.get_cell()->index(),
              &context.membrane->dof_handler());
            face[i] = fv.get_face_number();
            k[i]    = context.of(cell[i]->material_id());
          }
        if (!k[0] || !k[1])
          return;
        auto                   &s  = static_cast<EdgeScratch &>(scratch_data);
        const auto             &fe = context.membrane->dof_handler().get_fe();
        std::array<DofIndex, 2> index{};
        for (unsigned int i = 0; i < fiv.n_current_interface_dofs(); ++i)
          {
            const auto local = fiv.interface_dof_to_dof_indices(i);
            for (unsigned int side = 0; side < 2; ++side)
              if (local[side] != numbers::invalid_unsigned_int)
                {
                  const auto [c, a] = fe.system_to_component_index(local[side]);
                  index[side][a][c] = i;
                }
          }
        std::array<Vec<double>, 2> warp;
        for (unsigned int side = 0; side < 2; ++side)
          {
            s.X[side] = s.nodes[side].of(cell[side]);
            current_nodes(s, side, index[side], local_u);
            warp[side] = warp_of(context, cell[side]);
          }
        const double h = std::min(size_across(s, s.X[0], face[0]),
                                  size_across(s, s.X[1], face[1]));
        EdgeFrame    e;
        e.penalty = context.parameters.gamma(s.degree)
                    * std::max(k[0]->largest, k[1]->largest) / h;
        for (unsigned int q = 0; q < s.edge.size(); ++q)
          {
            std::array<ShapeDerivatives, 2> shape;
            shape[0] =
              shape_derivatives(s.base,
                                face_point(face[0], s.edge.point(q)[0]));
            Vec<double>       nu, T;
            const Vec<double> N0 = first_side(
              s, face[0], s.edge.weight(q), shape[0], warp[0], *k[0], e, nu, T);
            // The same point on the second cell's face.
            const Point<2> xi1 =
              locate_on_face(s.base,
                             s.X[1],
                             face[1],
                             position(s.base,
                                      s.X[0],
                                      face_point(face[0], s.edge.point(q)[0])));
            shape[1] = shape_derivatives(s.base, xi1);
            double G1[15];
            point_derivatives(s.X[1], shape[1], G1);
            // The second cell's normal on the first one's side.
            const Vec<double>    N1   = unit_normal(G1);
            const double         sign = dot(N0, N1) >= 0. ? 1. : -1.;
            const ReferencePoint ref1 =
              reference_point(G1, warp[1], k[1]->D, sign);
            e.side[1]             = ref1.frame;
            const Vec<double> nu1 = normalized(cross(T, ref1.N));
            e.nu[1][0]            = dot(nu1, ref1.E1);
            e.nu[1][1]            = dot(nu1, ref1.E2);
            Vec<double> N1s;
            for (unsigned int c = 0; c < 3; ++c)
              N1s[c] = sign * N1[c];
            e.Theta = turn_angle(N0, N1s, normalized(T));
            double g[30], gradient[30];
            point_derivatives(s.x[0], shape[0], g);
            point_derivatives(s.x[1], shape[1], g + 15);
            record.energy += interior_point(
              g, e, gradient, matrix ? s.hessian.data() : nullptr);
            add_point_terms(2,
                            shape.data(),
                            index.data(),
                            gradient,
                            s.hessian.data(),
                            residual,
                            matrix);
          }
      }

      void
      BendingEdges::boundary_face(
        const DoFHandler<2, 3>::active_cell_iterator &cell,
        const unsigned int                            face,
        const FEFaceValues<2, 3> &,
        const std::vector<double> &local_u,
        FullMatrix<double>        *matrix,
        Vector<double>            *residual,
        FaceTerms::Scratch        &scratch_data,
        FaceTerms::Record         &record_data) const
      {
        auto &record             = static_cast<EdgeRecord &>(record_data);
        record.energy            = 0.;
        record.clamped           = false;
        const RegionStiffness *k = context.of(cell->material_id());
        record.load.reinit(0);
        const types::boundary_id id = cell->face(face)->boundary_id();
        const bool clamped          = context.parameters.clamped.count(id) > 0;
        const bool loaded = context.parameters.moment_edges.count(id) > 0;
        if (!k || !(clamped || loaded))
          return;
        auto &s = static_cast<EdgeScratch &>(scratch_data);
        s.X[0]  = s.nodes[0].of(cell);
        current_nodes(s, 0, s.dof, local_u);
        const Vec<double> warp = warp_of(context, cell);
        EdgeFrame         e;
        Vector<double>    clamp_force;
        if (clamped)
          {
            e.penalty = context.parameters.gamma(s.degree) * k->largest
                        / size_across(s, s.X[0], face);
            clamp_force.reinit(local_u.size());
          }
        if (loaded)
          {
            record.load.reinit(local_u.size());
            record.dofs.resize(local_u.size());
            cell->get_dof_indices(record.dofs);
          }
        for (unsigned int q = 0; q < s.edge.size(); ++q)
          {
            const Point<2>         xi    = face_point(face, s.edge.point(q)[0]);
            const ShapeDerivatives shape = shape_derivatives(s.base, xi);
            Vec<double>            nu, T;
            const Vec<double>      N =
              first_side(s, face, s.edge.weight(q), shape, warp, *k, e, nu, T);
            double g[15], gradient[15];
            point_derivatives(s.x[0], shape, g);
            if (clamped)
              {
                const auto energy = [&](auto *v) {
                  using Number = std::decay_t<decltype(*v)>;
                  Number en    = clamped_edge_energy(v, e, N);
                  return en;
                };
                record.energy += differentiate<15>(
                  g, energy, gradient, matrix ? s.hessian.data() : nullptr);
                add_point_terms(1,
                                &shape,
                                &s.dof,
                                gradient,
                                s.hessian.data(),
                                residual,
                                matrix);
                add_point_terms(
                  1, &shape, &s.dof, gradient, nullptr, &clamp_force, nullptr);
              }
            if (loaded)
              add_edge_moment(s,
                              xi,
                              shape,
                              e,
                              N,
                              T,
                              g,
                              matrix,
                              residual,
                              record.load,
                              *context.parameters.moment);
          }
        if (clamped)
          {
            record.clamped      = true;
            record.boundary     = id;
            record.clamp_moment = 0;
            for (unsigned int a = 0; a < s.x[0].size(); ++a)
              {
                Tensor<1, 3> x, f;
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    x[c] = s.x[0][a][c];
                    f[c] = clamp_force[s.dof[a][c]];
                  }
                record.clamp_moment -= cross_product_3d(x, f);
              }
          }
      }

      void
      BendingEdges::end()
      {
        if (external)
          external->compress(VectorOperation::add);
        external = nullptr;
      }

      void
      BendingEdges::commit(const FaceTerms::Record &record_data)
      {
        const auto &record = static_cast<const EdgeRecord &>(record_data);
        sum += record.energy;
        if (record.clamped)
          clamp_moment[record.boundary] += record.clamp_moment;
        if (external && record.load.size() > 0)
          constraints->distribute_local_to_global(record.load,
                                                  record.dofs,
                                                  *external);
      }
    } // namespace bending
  }   // namespace membrane
} // namespace pneuma
