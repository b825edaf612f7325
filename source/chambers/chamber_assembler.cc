#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <pneuma/chambers/chamber_assembler.h>

#include <pneuma/chambers/free_surface_quadrature.h>
#include <pneuma/core/input_error.h>
#include <pneuma/membrane/reference_geometry.h>
#include <pneuma/membrane/surface_kinematics.h>

#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace pneuma
{
  namespace chambers
  {
    namespace
    {
      /// dof[a][c]: the cell dof of node a, component c.
      using NodeDofs =
        std::array<std::array<unsigned int, 3>, membrane::max_cell_nodes>;

      const UpdateFlags wall_flags =
        update_values | update_gradients | update_normal_vectors
        | update_quadrature_points | update_JxW_values;

      /// Where one pass over a cell's quadrature points puts its results.
      struct CellIntegrals
      {
        FullMatrix<double> *matrix   = nullptr; ///< += d(-f)/du
        Vector<double>     *residual = nullptr; ///< -= f
        Vector<double>     *q        = nullptr; ///< += dV/du (or dV_l/du)
        double volume = 0., liquid_volume = 0., free_surface = 0., wetted = 0.,
               area = 0.;
      };

      /// One quadrature point of a wall: the frame E_1, E_2 (E_1 x E_2 the
      /// normal the wall's sign refers to), the weight, the reference
      /// position, and per node the shape value N_a and the derivatives
      /// dN_a/dS_alpha along the frame.
      struct WallPoint
      {
        Tensor<1, 3>                                                E[2];
        double                                                      JxW = 0.;
        Point<3>                                                    X;
        std::array<double, membrane::max_cell_nodes>                N;
        std::array<std::array<double, 2>, membrane::max_cell_nodes> dN;
      };

      /**
       * Integrate the wall terms of one chamber over @p n_q points, the
       * point q given by @p point_at(q, point): with @p liquid the
       * hydrostatic pressure on wetted points (the points cover the wetted
       * part only), else the gas pressure and the volume.
       *
       * The element is FE_Q^3 (degree 1 or 2): every dof is a (node,
       * component) pair (@p dof) with the node's scalar shape function, so
       * the tangent is built in 3x3 node blocks, on fixed-size arrays (no
       * allocation per cell).
       */
      template <typename PointAt>
      void
      integrate(const unsigned int         n_q,
                const PointAt             &point_at,
                const NodeDofs            &dof,
                const unsigned int         n_nodes,
                const std::vector<double> &local_u,
                const double               s,
                const ChamberLoad         &load,
                const bool                 liquid,
                const Tensor<1, 3>        &unit_gravity,
                const double               g,
                CellIntegrals             &out)
      {
        const double rho_g = load.density * g;
        WallPoint    P;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            point_at(q, P);
            const auto  &N    = P.N;
            const auto  &dN   = P.dN;
            Tensor<1, 3> a[2] = {P.E[0], P.E[1]};
            Tensor<1, 3> u_q;
            for (unsigned int n = 0; n < n_nodes; ++n)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  const double uc = local_u[dof[n][c]];
                  u_q[c] += uc * N[n];
                  a[0][c] += uc * dN[n][0];
                  a[1][c] += uc * dN[n][1];
                }
            const Tensor<1, 3> av    = s * cross_product_3d(a[0], a[1]);
            const Point<3>     x     = P.X + u_q;
            const double       dA    = P.JxW;
            const double       depth = load.level + unit_gravity * x;
            double             p     = load.gas_pressure;
            if (liquid)
              {
                p = rho_g * depth;
                out.liquid_volume += depth * (unit_gravity * av) * dA;
                out.free_surface += (unit_gravity * av) * dA;
                out.wetted += av.norm() * dA;
              }
            else
              {
                out.volume += (x * av) * dA / 3.;
                out.area += av.norm() * dA;
              }

            for (unsigned int n = 0; n < n_nodes; ++n)
              for (unsigned int c = 0; c < 3; ++c)
                {
                  const double v = av[c] * N[n] * dA;
                  if (out.q)
                    (*out.q)(dof[n][c]) += v;
                  if (out.residual)
                    (*out.residual)(dof[n][c]) -= p * v;
                }
            if (!out.matrix || (p == 0. && !liquid))
              continue;
            // d(a_1 x a_2)/du_j = dN_j,1 e_cj x a_2 + dN_j,2 a_1 x e_cj,
            // so (e_cj x a_2)_ci = eps_{cj k ci} a_2,k: the skew matrices
            // [a_2]_x and [a_1]_x (times s) with
            // X[ci][cj] = (e_cj x a_2)_ci, Y[ci][cj] = (a_1 x e_cj)_ci.
            double X[3][3], Y[3][3];
            for (unsigned int cj = 0; cj < 3; ++cj)
              {
                Tensor<1, 3> e;
                e[cj]                 = 1.;
                const Tensor<1, 3> ex = s * cross_product_3d(e, a[1]);
                const Tensor<1, 3> ey = s * cross_product_3d(a[0], e);
                for (unsigned int ci = 0; ci < 3; ++ci)
                  {
                    X[ci][cj] = ex[ci];
                    Y[ci][cj] = ey[ci];
                  }
              }
            // dp/du_j = -rho g (-g_hat . e_cj) N_j on wetted points.
            double H[3][3] = {};
            if (liquid)
              for (unsigned int ci = 0; ci < 3; ++ci)
                for (unsigned int cj = 0; cj < 3; ++cj)
                  H[ci][cj] = av[ci] * rho_g * unit_gravity[cj];
            FullMatrix<double> &K = *out.matrix;
            for (unsigned int na = 0; na < n_nodes; ++na)
              {
                const double pa = p * N[na] * dA;
                for (unsigned int nb = 0; nb < n_nodes; ++nb)
                  {
                    const double d0 = pa * dN[nb][0], d1 = pa * dN[nb][1],
                                 h = N[na] * N[nb] * dA;
                    for (unsigned int ci = 0; ci < 3; ++ci)
                      for (unsigned int cj = 0; cj < 3; ++cj)
                        K(dof[na][ci], dof[nb][cj]) -=
                          d0 * X[ci][cj] + d1 * Y[ci][cj] + h * H[ci][cj];
                  }
              }
          }
      }

      /// The points of a cell in the membrane kernel's reference data.
      auto
      reference_points(const membrane::ReferenceGeometry &reference,
                       const unsigned int                 cell_index)
      {
        return [&reference, cell_index](const unsigned int q, WallPoint &P) {
          const auto   &R  = reference.point(cell_index, q);
          const double *N  = reference.shape_values(q);
          const auto   *dN = reference.shape_derivatives(cell_index, q);
          for (unsigned int d = 0; d < 3; ++d)
            {
              P.E[0][d] = R.E[0][d];
              P.E[1][d] = R.E[1][d];
              P.X[d]    = R.X[d];
            }
          P.JxW = R.JxW;
          for (unsigned int a = 0; a < reference.n_nodes(); ++a)
            {
              P.N[a]  = N[a];
              P.dN[a] = dN[a];
            }
        };
      }

      /// Mean reference position and normal E_1 x E_2 of a cell of the
      /// reference data.
      std::pair<Point<3>, Tensor<1, 3>>
      reference_centre_and_normal(const membrane::ReferenceGeometry &reference,
                                  const unsigned int                 cell_index)
      {
        Point<3>           x;
        Tensor<1, 3>       n;
        const unsigned int n_q = reference.n_q_points();
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const auto        &R = reference.point(cell_index, q);
            const Tensor<1, 3> e0({R.E[0][0], R.E[0][1], R.E[0][2]});
            const Tensor<1, 3> e1({R.E[1][0], R.E[1][1], R.E[1][2]});
            x += Point<3>(R.X[0], R.X[1], R.X[2]) / n_q;
            n += cross_product_3d(e0, e1);
          }
        return {x, n};
      }

      /// Mean reference position and normal of a cell.
      std::pair<Point<3>, Tensor<1, 3>>
      cell_centre_and_normal(const FEValues<2, 3> &fe_values)
      {
        Point<3>     x;
        Tensor<1, 3> n;
        for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
          {
            x += fe_values.quadrature_point(q) / fe_values.n_quadrature_points;
            n += fe_values.normal_vector(q);
          }
        return {x, n};
      }

      /**
       * The points of a cut cell's wetted rule @p quadrature from the
       * reference positions @p nodes of the cell's nodes, without an
       * FEValues object (whose construction per cut cell and level was
       * most of an explicit step with a liquid). The mapping is
       * MappingQ(Cache) of the element's degree (1 or 2), whose support
       * points are the element's nodes: X(xi) = sum_a X_a N_a(xi) is the
       * mapping itself, J = dX/dxi, the normal J_1 x J_2 / |J_1 x J_2|,
       * JxW = |J_1 x J_2| w and the surface gradient J (J^T J)^-1 grad_xi N
       * as FEValues forms them. The frame is turned by @p orientation
       * times the sign that makes the normals' sum point along @p normal.
       */
      class CutPoints
      {
      public:
        CutPoints(const FiniteElement<2, 3> &base,
                  const Quadrature<2>       &quadrature,
                  const Point<3>            *nodes,
                  const Tensor<1, 3>        &normal)
          : n_nodes(base.n_dofs_per_cell())
          , X(quadrature.size())
          , n(quadrature.size())
          , JxW(quadrature.size())
          , N(quadrature.size() * n_nodes)
          , grad(quadrature.size() * n_nodes)
        {
          Tensor<1, 3> sum;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Point<2> &xi = quadrature.point(q);
              Tensor<1, 3>    J[2];
              for (unsigned int a = 0; a < n_nodes; ++a)
                {
                  const double       Na = base.shape_value(a, xi);
                  const Tensor<1, 2> ga = base.shape_grad(a, xi);
                  X[q] += Na * nodes[a];
                  J[0] += ga[0] * nodes[a];
                  J[1] += ga[1] * nodes[a];
                  N[q * n_nodes + a] = Na;
                }
              const Tensor<1, 3> c   = cross_product_3d(J[0], J[1]);
              const double       det = c.norm();
              n[q]                   = c / det;
              JxW[q]                 = det * quadrature.weight(q);
              sum += n[q];
              // (J^T J)^-1, then the surface gradients.
              const double G00 = J[0] * J[0], G01 = J[0] * J[1],
                           G11 = J[1] * J[1], d = G00 * G11 - G01 * G01;
              for (unsigned int a = 0; a < n_nodes; ++a)
                {
                  const Tensor<1, 2> ga = base.shape_grad(a, xi);
                  const double       c0 = (G11 * ga[0] - G01 * ga[1]) / d,
                               c1       = (G00 * ga[1] - G01 * ga[0]) / d;
                  grad[q * n_nodes + a] = c0 * J[0] + c1 * J[1];
                }
            }
          sign = sum * normal >= 0. ? 1. : -1.;
        }

        unsigned int
        size() const
        {
          return X.size();
        }

        /// The point function for integrate().
        auto
        points() const
        {
          return [this](const unsigned int q, WallPoint &P) {
            const membrane::TangentFrame frame =
              membrane::tangent_frame(sign * n[q]);
            P.E[0] = frame.e[0];
            P.E[1] = frame.e[1];
            P.X    = X[q];
            P.JxW  = JxW[q];
            for (unsigned int a = 0; a < n_nodes; ++a)
              {
                P.N[a]     = N[q * n_nodes + a];
                P.dN[a][0] = grad[q * n_nodes + a] * frame.e[0];
                P.dN[a][1] = grad[q * n_nodes + a] * frame.e[1];
              }
          };
        }

      private:
        unsigned int              n_nodes;
        std::vector<Point<3>>     X;
        std::vector<Tensor<1, 3>> n;
        std::vector<double>       JxW, N;
        std::vector<Tensor<1, 3>> grad;
        double                    sign = 1.;
      };

      /// The hydrostatic terms of one wall over its wetted part: the whole
      /// cell (its reference points) if wet, the generated rule if cut
      /// (with the frame turned to the reference normal @p normal; from
      /// the reference positions of the cell's nodes @p nodes).
      void
      integrate_wetted(const FreeSurfaceQuadrature::Location at,
                       const FreeSurfaceQuadrature          &free_surface,
                       const DoFHandler<2, 3>::active_cell_iterator &cell,
                       const membrane::ReferenceGeometry            &reference,
                       const unsigned int                            cell_index,
                       const Tensor<1, 3>                           &normal,
                       const Point<3>                               *nodes,
                       const NodeDofs                               &dof,
                       const std::vector<double>                    &local_u,
                       const double                                  s,
                       const ChamberLoad                            &load,
                       const Tensor<1, 3> &unit_gravity,
                       const double        g,
                       CellIntegrals      &out)
      {
        const unsigned int n_nodes = reference.n_nodes();
        const auto wetted = [&](const unsigned int n_q, const auto &point_at) {
          integrate(n_q,
                    point_at,
                    dof,
                    n_nodes,
                    local_u,
                    s,
                    load,
                    true,
                    unit_gravity,
                    g,
                    out);
        };
        if (at == FreeSurfaceQuadrature::Location::wet)
          wetted(reference.n_q_points(),
                 reference_points(reference, cell_index));
        else if (at == FreeSurfaceQuadrature::Location::cut)
          {
            const CutPoints cut(cell->get_fe().base_element(0),
                                free_surface.wet_quadrature(),
                                nodes,
                                normal);
            wetted(cut.size(), cut.points());
          }
      }
    } // namespace

    ChamberAssembler::ChamberAssembler(const geometry::SceneGenerator &geometry,
                                       const ChamberParameters &parameters)
      : geometry(geometry)
      , parameters(parameters)
    {
    }

    void
    ChamberAssembler::reinit(
      const Mapping<2, 3>                                 &mapping_,
      const DoFHandler<2, 3>                              &dof_handler_,
      const unsigned int                                   degree_,
      std::function<const membrane::ReferenceGeometry &()> reference_)
    {
      reference         = std::move(reference_);
      mapping           = &mapping_;
      dof_handler       = &dof_handler_;
      degree            = degree_;
      gravity_magnitude = parameters.gravity.norm();
      unit_gravity      = gravity_magnitude > 0.
                            ? parameters.gravity / gravity_magnitude
                            : Tensor<1, 3>({0., 0., -1.});
      membership.clear();
      measure_cache   = MeasureCache();
      surface_heights = SurfaceHeights();
      for (unsigned int c = 0; c < parameters.chambers.size(); ++c)
        for (const auto &[id, sign] : parameters.chambers[c].regions)
          membership[id].emplace_back(c, sign);
    }

    const std::vector<std::pair<unsigned int, int>> &
    ChamberAssembler::walls_of(const types::material_id id) const
    {
      static const std::vector<std::pair<unsigned int, int>> none;
      const auto it = membership.find(id);
      return it == membership.end() ? none : it->second;
    }

    namespace
    {
      /// Orientation of a cell's mapping normal relative to "out of the
      /// chamber".
      double
      wall_sign(const geometry::SceneGenerator &geometry,
                const ChamberDefinition        &def,
                const int                       region_sign,
                const Point<3>                 &x,
                const Tensor<1, 3>             &n)
      {
        if (def.use_interior_point)
          return (x - def.interior_point) * n >= 0. ? 1. : -1.;
        return region_sign * geometry.orientation(x, n);
      }
    } // namespace

    /// The walls' sums over the mesh (this rank's cells): per chamber its
    /// oriented area vector, area and volume closed along gravity, per
    /// region its area and per (chamber, region) its area vector.
    struct ChamberAssembler::WallSums
    {
      std::vector<Tensor<1, 3>>            vector;
      std::vector<double>                  area, vertical_volume;
      std::map<types::material_id, double> region_area;
      std::map<std::pair<unsigned int, types::material_id>, Tensor<1, 3>>
        region_vector;
    };

    ChamberAssembler::WallSums
    ChamberAssembler::wall_sums() const
    {
      const QGauss<2>    quadrature(degree + 1);
      FEValues<2, 3>     fe_values(*mapping,
                               dof_handler->get_fe(),
                               quadrature,
                               wall_flags);
      const unsigned int n = parameters.chambers.size();
      WallSums           sums{std::vector<Tensor<1, 3>>(n),
                    std::vector<double>(n, 0.),
                    std::vector<double>(n, 0.),
                    {},
                    {}};
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto &walls = walls_of(cell->material_id());
            if (walls.empty())
              continue;
            fe_values.reinit(cell);
            const auto [x, n_mean] = cell_centre_and_normal(fe_values);
            Tensor<1, 3> cell_vector;
            double       cell_area = 0., cell_volume = 0.;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                cell_vector += fe_values.normal_vector(q) * fe_values.JxW(q);
                cell_area += fe_values.JxW(q);
                // V = -int height (g . n) dA: exact for a chamber closed
                // along gravity, whatever its vertical cuts.
                cell_volume -= height(fe_values.quadrature_point(q))
                               * (unit_gravity * fe_values.normal_vector(q))
                               * fe_values.JxW(q);
              }
            sums.region_area[cell->material_id()] += cell_area;
            for (const auto &[c, rs] : walls)
              {
                const double s =
                  wall_sign(geometry, parameters.chambers[c], rs, x, n_mean);
                sums.vector[c] += s * cell_vector;
                sums.area[c] += cell_area;
                sums.vertical_volume[c] += s * cell_volume;
                sums.region_vector[{c, cell->material_id()}] += s * cell_vector;
              }
          }
      return sums;
    }

    std::string
    ChamberAssembler::closure_error(const unsigned int  c,
                                    const Tensor<1, 3> &gap,
                                    const double        total,
                                    const WallSums     &sums) const
    {
      const auto    &def  = parameters.chambers[c];
      const MPI_Comm comm = dof_handler->get_communicator();
      // Would flipping one wall close it?
      std::string hint;
      for (const auto &[id, sign] : def.regions)
        {
          Tensor<1, 3> v;
          const auto   it = sums.region_vector.find({c, id});
          for (unsigned int d = 0; d < 3; ++d)
            v[d] = Utilities::MPI::sum(
              it == sums.region_vector.end() ? 0. : it->second[d], comm);
          if (!def.open && (gap - 2. * v).norm() <= 1e-8 * total)
            hint += (hint.empty() ? "" : " or ") + std::to_string(id);
        }
      if (!hint.empty())
        hint = " (flipping region " + hint + " closes it)";
      std::ostringstream msg;
      msg << "the oriented walls do not close the chamber: their "
             "area vectors sum to ("
          << gap[0] << ", " << gap[1] << ", " << gap[2]
          << ") m^2, |gap| = " << gap.norm() << " m^2 for " << total
          << " m^2 of wall. Add the missing regions or flip a wall "
             "with a minus sign"
          << (def.open ? " (an open tank may only lack walls "
                         "parallel to gravity)"
                       : "")
          << hint;
      return msg.str();
    }

    void
    ChamberAssembler::check_chambers()
    {
      const WallSums     sums = wall_sums();
      const unsigned int n    = parameters.chambers.size();
      const MPI_Comm     comm = dof_handler->get_communicator();
      closed_vertically.assign(n, true);
      for (unsigned int c = 0; c < n; ++c)
        {
          const auto &def = parameters.chambers[c];
          for (const auto &[id, sign] : def.regions)
            {
              const double a = Utilities::MPI::sum(sums.region_area.count(id)
                                                     ? sums.region_area.at(id)
                                                     : 0.,
                                                   comm);
              check_input(a > 0.,
                          def.path + "/Regions",
                          "the mesh has no cells in region "
                            + std::to_string(id));
            }
          Tensor<1, 3> gap;
          for (unsigned int d = 0; d < 3; ++d)
            gap[d] = Utilities::MPI::sum(sums.vector[c][d], comm);
          const double total = Utilities::MPI::sum(sums.area[c], comm);
          // An open tank's missing lid makes its walls face down along
          // gravity; a chamber that lacks only vertical walls (a slice, a
          // symmetry cut) is closed along gravity: its sum vanishes.
          const double down    = gap * unit_gravity;
          closed_vertically[c] = !def.open || std::abs(down) <= 1e-8 * total;
          if (def.open)
            {
              check_input(down > 0. || closed_vertically[c],
                          def.path + "/Regions",
                          "the walls of an open tank must face out of the "
                          "liquid, i.e. down along gravity (their area "
                          "vectors sum to "
                            + std::to_string(down)
                            + " m^2 along gravity); flip them with a minus "
                              "sign");
              gap -= down * unit_gravity;
            }
          if (gap.norm() > 1e-8 * total)
            throw InputError(def.path + "/Regions",
                             closure_error(c, gap, total, sums));
          // A slice's flux through its vertical cuts is nil in either
          // orientation: its volume tells.
          const double volume =
            Utilities::MPI::sum(sums.vertical_volume[c], comm);
          if (def.open && closed_vertically[c])
            check_input(volume > 0.,
                        def.path + "/Regions",
                        "the walls face into the chamber (the volume they "
                        "close between its vertical cuts is "
                          + std::to_string(volume)
                          + " m^3): flip the signs of its regions");
          if (def.open)
            check_input(def.filling == Filling::liquid,
                        def.path + "/Open",
                        "an open chamber must have Filling = liquid");
        }
    }

    ChamberAssembler::Pass::Scratch::Scratch(const ChamberAssembler &assembler)
      : assembler(assembler)
    {
    }

    ChamberAssembler::Pass::Scratch::Liquid &
    ChamberAssembler::Pass::Scratch::liquid()
    {
      if (!liquid_data)
        liquid_data = std::make_unique<Liquid>(assembler);
      return *liquid_data;
    }

    ChamberAssembler::Pass::Scratch::Liquid::Liquid(
      const ChamberAssembler &assembler)
      : free_surface(assembler.degree, assembler.degree + 2)
      , psi(free_surface.support_points().size())
    {
    }

    ChamberAssembler::Pass::Pass(const ChamberAssembler          &assembler,
                                 const LA::Vector                &u,
                                 const AffineConstraints<double> &constraints,
                                 const std::vector<ChamberLoad>  &loads,
                                 std::vector<ChamberMeasures>    &measures,
                                 const bool                       with_vectors)
      : assembler(assembler)
      , u(u)
      , constraints(constraints)
      , loads(loads)
      , measures(measures)
      , with_vectors(with_vectors)
      , own_scratch(assembler)
    {
      const unsigned int n    = assembler.parameters.chambers.size();
      const MPI_Comm     comm = assembler.dof_handler->get_communicator();
      measures.resize(n);
      for (const auto &l : loads)
        if (l.liquid)
          heights = &assembler.heights(u);
      // The vectors dV/du of the last pass are zeroed if they have u's
      // global partition (membrane and cable dofs) on every rank, else
      // made anew: a new Trilinos vector per chamber and pass was 2 % of
      // the waterbeam's run (Figure 11).
      const IndexSet owned      = u.locally_owned_elements();
      const auto     has_layout = [&](const LA::Vector &q) {
        return q.size() == u.size() && q.locally_owned_elements() == owned;
      };
      bool reuse = true;
      if (with_vectors)
        for (unsigned int c = 0; c < n; ++c)
          reuse = reuse && has_layout(measures[c].q)
                  && (!loads[c].liquid || has_layout(measures[c].q_liquid));
      if (with_vectors)
        reuse = Utilities::MPI::min(static_cast<unsigned int>(reuse), comm) > 0;
      for (unsigned int c = 0; c < n; ++c)
        {
          auto &m  = measures[c];
          m.volume = m.liquid_volume = m.free_surface_area = m.wetted_area =
            m.wall_area                                    = 0.;
          if (!with_vectors)
            continue;
          if (reuse)
            {
              m.q = 0.;
              if (loads[c].liquid)
                m.q_liquid = 0.;
            }
          else
            {
              m.q.reinit(owned, comm);
              if (loads[c].liquid)
                m.q_liquid.reinit(owned, comm);
            }
        }
      if (with_vectors)
        for (unsigned int c = 0; c < n; ++c)
          {
            q_owned.emplace_back(measures[c].q);
            q_liquid_owned.emplace_back(
              loads[c].liquid ? LA::OwnedValues(measures[c].q_liquid)
                              : LA::OwnedValues());
          }
    }

    void
    ChamberAssembler::Pass::add(
      const Vector<double>                       &q,
      const std::vector<types::global_dof_index> &dof_indices,
      const LA::OwnedValues                      &owned,
      LA::Vector                                 &target) const
    {
      bool direct = static_cast<bool>(owned);
      for (unsigned int i = 0; direct && i < dof_indices.size(); ++i)
        direct = owned.owns(dof_indices[i])
                 && !constraints.is_constrained(dof_indices[i]);
      if (!direct)
        constraints.distribute_local_to_global(q, dof_indices, target);
      else
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          owned[dof_indices[i]] += q[i];
    }

    void
    ChamberAssembler::Pass::cell(
      const DoFHandler<2, 3>::active_cell_iterator &cell,
      const unsigned int                            cell_index,
      const std::vector<double>                    &local_u,
      FullMatrix<double>                           *cell_matrix,
      Vector<double>                               *cell_residual,
      const std::vector<types::global_dof_index>   &dof_indices)
    {
      compute(cell,
              assembler.reference(),
              cell_index,
              local_u,
              cell_matrix,
              cell_residual,
              own_scratch,
              own_record);
      commit(own_record, dof_indices);
    }

    void
    ChamberAssembler::Pass::compute(
      const DoFHandler<2, 3>::active_cell_iterator &cell,
      const membrane::ReferenceGeometry            &reference,
      const unsigned int                            cell_index,
      const std::vector<double>                    &local_u,
      FullMatrix<double>                           *cell_matrix,
      Vector<double>                               *cell_residual,
      Scratch                                      &scratch,
      Record                                       &record) const
    {
      record.n_walls    = 0;
      const auto &walls = assembler.walls_of(cell->material_id());
      if (walls.empty())
        return;
      const unsigned int n_nodes = reference.n_nodes();
      NodeDofs           dof{};
      for (unsigned int i = 0; i < 3 * n_nodes; ++i)
        dof[reference.node(i)][reference.component(i)] = i;
      const auto [x_mean, n_mean] =
        reference_centre_and_normal(reference, cell_index);
      if (record.walls.size() < walls.size())
        {
          record.walls.resize(walls.size());
          for (auto &w : record.walls)
            {
              w.q.reinit(3 * n_nodes);
              w.q_liquid.reinit(3 * n_nodes);
            }
        }
      for (unsigned int k = 0; k < walls.size(); ++k)
        {
          const auto &[c, rs]     = walls[k];
          Wall &wall              = record.walls[k];
          wall.chamber            = c;
          const double       s    = wall_sign(assembler.geometry,
                                     assembler.parameters.chambers[c],
                                     rs,
                                     x_mean,
                                     n_mean);
          const ChamberLoad &load = loads[c];
          wall.q                  = 0;
          CellIntegrals out;
          out.matrix   = cell_matrix;
          out.residual = cell_residual;
          out.q        = with_vectors ? &wall.q : nullptr;
          // Liquid-only chambers need the gas pass (volume, q) only for
          // their measures, not in Newton's assemblies.
          if (load.gas || !with_vectors)
            integrate(reference.n_q_points(),
                      reference_points(reference, cell_index),
                      dof,
                      n_nodes,
                      local_u,
                      s,
                      load,
                      false,
                      assembler.unit_gravity,
                      assembler.gravity_magnitude,
                      out);
          wall.has_q_liquid = false;
          if (load.liquid)
            {
              auto         &liquid = scratch.liquid();
              const double *z =
                &heights->support[std::size_t(heights->first[cell_index])
                                  * heights->n_support];
              for (unsigned int i = 0; i < liquid.psi.size(); ++i)
                liquid.psi[i] = z[i] - load.level;
              wall.q_liquid = 0;
              out.q         = with_vectors ? &wall.q_liquid : nullptr;
              const auto at = liquid.free_surface.classify(liquid.psi);
              integrate_wetted(at,
                               liquid.free_surface,
                               cell,
                               reference,
                               cell_index,
                               n_mean,
                               heights->cell_nodes(cell_index),
                               dof,
                               local_u,
                               s,
                               load,
                               assembler.unit_gravity,
                               assembler.gravity_magnitude,
                               out);
              wall.has_q_liquid =
                with_vectors && at != FreeSurfaceQuadrature::Location::dry;
            }
          wall.volume        = out.volume;
          wall.area          = out.area;
          wall.liquid_volume = out.liquid_volume;
          wall.free_surface  = out.free_surface;
          wall.wetted        = out.wetted;
        }
      record.n_walls = walls.size();
    }

    void
    ChamberAssembler::Pass::commit(
      const Record                               &record,
      const std::vector<types::global_dof_index> &dof_indices)
    {
      for (unsigned int k = 0; k < record.n_walls; ++k)
        {
          const Wall &wall = record.walls[k];
          auto       &m    = measures[wall.chamber];
          if (wall.has_q_liquid)
            add(wall.q_liquid,
                dof_indices,
                q_liquid_owned[wall.chamber],
                m.q_liquid);
          m.volume += wall.volume;
          m.wall_area += wall.area;
          m.liquid_volume += wall.liquid_volume;
          m.free_surface_area += wall.free_surface;
          m.wetted_area += wall.wetted;
          if (with_vectors)
            add(wall.q, dof_indices, q_owned[wall.chamber], m.q);
        }
    }

    void
    ChamberAssembler::Pass::finish()
    {
      const MPI_Comm comm = assembler.dof_handler->get_communicator();
      // The five measures of every chamber in one reduction.
      const auto fields = [](ChamberMeasures &m) {
        return std::array<double *, 5>{{&m.volume,
                                        &m.wall_area,
                                        &m.liquid_volume,
                                        &m.free_surface_area,
                                        &m.wetted_area}};
      };
      std::vector<double> local, sums(5 * measures.size());
      for (auto &m : measures)
        for (const double *f : fields(m))
          local.push_back(*f);
      Utilities::MPI::sum(ArrayView<const double>(local),
                          comm,
                          ArrayView<double>(sums));
      for (unsigned int c = 0; c < measures.size(); ++c)
        {
          auto &m = measures[c];
          for (unsigned int k = 0; k < 5; ++k)
            *fields(m)[k] = sums[5 * c + k];
          if (with_vectors)
            {
              m.q.compress(VectorOperation::add);
              if (loads[c].liquid)
                m.q_liquid.compress(VectorOperation::add);
            }
        }
    }

    void
    ChamberAssembler::assemble(const LA::Vector                &u,
                               const AffineConstraints<double> &constraints,
                               const std::vector<ChamberLoad>  &loads,
                               LA::Vector                      *residual,
                               LA::SparseMatrix                *tangent,
                               std::vector<ChamberMeasures>    &measures,
                               const bool with_vectors) const
    {
      if (!residual && !tangent && !with_vectors
          && from_cache(u, loads, measures))
        return;
      Pass pass(*this, u, constraints, loads, measures, with_vectors);
      const unsigned int n_dofs = dof_handler->get_fe().n_dofs_per_cell();
      FullMatrix<double> cell_matrix(n_dofs, n_dofs);
      Vector<double>     cell_residual(n_dofs);
      std::vector<types::global_dof_index> dof_indices(n_dofs);
      std::vector<double>                  local_u(n_dofs);
      // u by local index where every owned cell's dofs are in its range
      // (the reference data hold the cells' dofs).
      const auto   &ref = reference();
      const double *values =
        ghosted_indices.values(u, ref.dof_indices(0), ref.n_cells(), n_dofs);
      // The index of each owned cell in the reference data.
      unsigned int cell_index = 0;
      for (const auto &cell : dof_handler->active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const unsigned int index = cell_index++;
          if (walls_of(cell->material_id()).empty())
            continue;
          const types::global_dof_index *cell_dofs = ref.dof_indices(index);
          std::copy(cell_dofs, cell_dofs + n_dofs, dof_indices.begin());
          const int *local = values ? ghosted_indices.cell(index) : nullptr;
          for (unsigned int i = 0; i < n_dofs; ++i)
            local_u[i] = local ? values[local[i]] : u[dof_indices[i]];
          cell_matrix   = 0;
          cell_residual = 0;
          pass.cell(cell,
                    index,
                    local_u,
                    tangent ? &cell_matrix : nullptr,
                    residual ? &cell_residual : nullptr,
                    dof_indices);
          if (tangent && residual)
            constraints.distribute_local_to_global(
              cell_matrix, cell_residual, dof_indices, *tangent, *residual);
          else if (tangent)
            constraints.distribute_local_to_global(cell_matrix,
                                                   dof_indices,
                                                   *tangent);
          else if (residual)
            constraints.distribute_local_to_global(cell_residual,
                                                   dof_indices,
                                                   *residual);
        }
      pass.finish();
      if (residual)
        residual->compress(VectorOperation::add);
      if (tangent)
        tangent->compress(VectorOperation::add);
      // Every pass has all measures unless it skipped a liquid-only
      // chamber's gas part (see Pass::compute()).
      bool complete = true;
      for (const auto &l : loads)
        complete = complete && (l.gas || !with_vectors);
      if (complete)
        store(u, loads, measures);
    }

    bool
    ChamberAssembler::from_cache(const LA::Vector               &u,
                                 const std::vector<ChamberLoad> &loads,
                                 std::vector<ChamberMeasures>   &measures) const
    {
      if (!cached(u, loads))
        return false;
      measures.resize(measure_cache.measures.size());
      for (unsigned int c = 0; c < measures.size(); ++c)
        {
          const auto &k       = measure_cache.measures[c];
          auto       &m       = measures[c];
          m.volume            = k[0];
          m.liquid_volume     = k[1];
          m.free_surface_area = k[2];
          m.wetted_area       = k[3];
          m.wall_area         = k[4];
        }
      return true;
    }

    bool
    ChamberAssembler::cached(const LA::Vector               &u,
                             const std::vector<ChamberLoad> &loads) const
    {
      const auto &cache = measure_cache;
      bool same = cache.u.matches(u) && cache.levels.size() == loads.size();
      for (unsigned int c = 0; same && c < loads.size(); ++c)
        same =
          cache.levels[c].first == loads[c].liquid
          && (!loads[c].liquid || cache.levels[c].second == loads[c].level);
      return Utilities::MPI::min(static_cast<unsigned int>(same),
                                 dof_handler->get_communicator())
             > 0;
    }

    void
    ChamberAssembler::store(const LA::Vector                   &u,
                            const std::vector<ChamberLoad>     &loads,
                            const std::vector<ChamberMeasures> &measures) const
    {
      auto &cache = measure_cache;
      cache.u.take(u);
      cache.levels.clear();
      for (const auto &l : loads)
        cache.levels.emplace_back(l.liquid, l.level);
      cache.measures.clear();
      for (const auto &m : measures)
        cache.measures.push_back(std::array<double, 5>{{m.volume,
                                                        m.liquid_volume,
                                                        m.free_surface_area,
                                                        m.wetted_area,
                                                        m.wall_area}});
    }


    const ChamberAssembler::SurfaceHeights &
    ChamberAssembler::heights(const LA::Vector &u) const
    {
      auto &h = surface_heights;
      if (h.u.matches(u))
        return h;
      h.u.take(u);
      h.serial                       = ++n_height_states;
      const auto                 &fe = dof_handler->get_fe();
      const FreeSurfaceQuadrature free_surface(degree, degree + 2);
      FEValues<2, 3>              support_values(*mapping,
                                    fe,
                                    Quadrature<2>(
                                      free_surface.support_points()),
                                    update_values | update_quadrature_points);
      FEValues<2, 3>              node_values(
        *mapping,
        fe,
        Quadrature<2>(fe.base_element(0).get_unit_support_points()),
        update_values | update_quadrature_points);
      const FEValuesExtractors::Vector displacement(0);
      h.n_support = support_values.n_quadrature_points;
      h.n_nodes   = node_values.n_quadrature_points;
      std::vector<Tensor<1, 3>> u_q(std::max(h.n_support, h.n_nodes));
      h.first.clear();
      h.support.clear();
      h.nodes.clear();
      h.positions.clear();
      const auto heights_at = [&](FEValues<2, 3>        &values,
                                  const auto            &cell,
                                  std::vector<double>   &out,
                                  std::vector<Point<3>> *positions) {
        values.reinit(cell);
        u_q.resize(values.n_quadrature_points);
        values[displacement].get_function_values(u, u_q);
        for (unsigned int k = 0; k < u_q.size(); ++k)
          {
            out.push_back(height(values.quadrature_point(k) + u_q[k]));
            if (positions)
              positions->push_back(values.quadrature_point(k));
          }
      };
      // A cut cell is integrated from its nodes' reference positions:
      // the mapping's support points must be the nodes (see CutPoints).
      const auto *q_mapping = dynamic_cast<const MappingQ<2, 3> *>(mapping);
      AssertThrow(q_mapping && fe.degree <= 2
                    && q_mapping->get_degree() == fe.degree,
                  ExcMessage("the free surface needs MappingQ of the "
                             "element's degree (1 or 2)"));
      for (const auto &cell : dof_handler->active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          // The walls of the chambers that hold a liquid or are connected
          // to one.
          bool wall = false;
          for (const auto &[c, rs] : walls_of(cell->material_id()))
            {
              const auto &def = parameters.chambers[c];
              wall            = wall || def.has_liquid()
                     || parameters.chambers[def.connected_to].has_liquid();
            }
          h.first.push_back(wall ? int(h.nodes.size() / h.n_nodes) : -1);
          if (!wall)
            continue;
          heights_at(support_values, cell, h.support, nullptr);
          heights_at(node_values, cell, h.nodes, &h.positions);
        }
      return h;
    }

    std::pair<double, double>
    ChamberAssembler::liquid_volume(const LA::Vector  &u,
                                    const unsigned int c,
                                    const double       level) const
    {
      const auto                        &fe     = dof_handler->get_fe();
      const unsigned int                 n_dofs = fe.n_dofs_per_cell();
      const membrane::ReferenceGeometry &ref    = reference();
      NodeDofs                           dof{};
      for (unsigned int i = 0; i < n_dofs; ++i)
        dof[ref.node(i)][ref.component(i)] = i;
      FreeSurfaceQuadrature                free_surface(degree, degree + 2);
      const SurfaceHeights                &h = heights(u);
      std::vector<double>                  psi(h.n_support);
      std::vector<types::global_dof_index> dof_indices(n_dofs);
      std::vector<double>                  local_u(n_dofs);
      ChamberLoad                          load;
      load.liquid  = true;
      load.level   = level;
      load.density = parameters.chambers[c].density;
      CellIntegrals out;

      unsigned int cell_index = 0;
      for (const auto &cell : dof_handler->active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const unsigned int index = cell_index++;
          for (const auto &[chamber, rs] : walls_of(cell->material_id()))
            {
              if (chamber != c)
                continue;
              const double *z =
                &h.support[std::size_t(h.first[index]) * h.n_support];
              for (unsigned int k = 0; k < psi.size(); ++k)
                psi[k] = z[k] - level;
              const auto at = free_surface.classify(psi);
              if (at == FreeSurfaceQuadrature::Location::dry)
                continue;
              cell->get_dof_indices(dof_indices);
              for (unsigned int i = 0; i < n_dofs; ++i)
                local_u[i] = u[dof_indices[i]];
              const auto [x_mean, n_mean] =
                reference_centre_and_normal(ref, index);
              const double s =
                wall_sign(geometry, parameters.chambers[c], rs, x_mean, n_mean);
              integrate_wetted(at,
                               free_surface,
                               cell,
                               ref,
                               index,
                               n_mean,
                               h.cell_nodes(index),
                               dof,
                               local_u,
                               s,
                               load,
                               unit_gravity,
                               gravity_magnitude,
                               out);
            }
        }
      const MPI_Comm comm = dof_handler->get_communicator();
      return {Utilities::MPI::sum(out.liquid_volume, comm),
              Utilities::MPI::sum(out.free_surface, comm)};
    }

    std::pair<double, double>
    ChamberAssembler::height_range(const LA::Vector  &u,
                                   const unsigned int c) const
    {
      const SurfaceHeights &h  = heights(u);
      double                lo = std::numeric_limits<double>::max(), hi = -lo;
      unsigned int          index = 0;
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const int first = h.first[index++];
            for (const auto &[chamber, rs] : walls_of(cell->material_id()))
              if (chamber == c)
                for (unsigned int k = 0; k < h.n_nodes; ++k)
                  {
                    const double z =
                      h.nodes[std::size_t(first) * h.n_nodes + k];
                    lo = std::min(lo, z);
                    hi = std::max(hi, z);
                  }
          }
      const MPI_Comm comm = dof_handler->get_communicator();
      return {Utilities::MPI::min(lo, comm), Utilities::MPI::max(hi, comm)};
    }

    ChamberCellData
    ChamberAssembler::cell_data(const LA::Vector               &u,
                                const std::vector<ChamberLoad> &loads) const
    {
      const auto     &fe = dof_handler->get_fe();
      const QGauss<2> quadrature(degree + 1);
      FEValues<2, 3>  fe_values(*mapping, fe, quadrature, wall_flags);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<1, 3>>        u_q(quadrature.size());
      const auto                      &tria = dof_handler->get_triangulation();
      ChamberCellData                  data;
      data.chamber.reinit(tria.n_active_cells());
      data.wetted.reinit(tria.n_active_cells());
      data.pressure.reinit(tria.n_active_cells());
      for (const auto &cell : dof_handler->active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const auto &walls = walls_of(cell->material_id());
          if (walls.empty())
            continue;
          fe_values.reinit(cell);
          fe_values[displacement].get_function_values(u, u_q);
          const auto   index          = cell->active_cell_index();
          unsigned int n_wet          = 0;
          double       p_net          = 0.;
          data.chamber[index]         = walls.front().first + 1;
          const auto [x_mean, n_mean] = cell_centre_and_normal(fe_values);
          const double s_first =
            wall_sign(geometry,
                      parameters.chambers[walls.front().first],
                      walls.front().second,
                      x_mean,
                      n_mean);
          for (const auto &[c, rs] : walls)
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double s = wall_sign(
                  geometry, parameters.chambers[c], rs, x_mean, n_mean);
                const double depth =
                  loads[c].level
                  - height(fe_values.quadrature_point(q) + u_q[q]);
                double p = loads[c].gas_pressure;
                if (loads[c].liquid && depth > 0.)
                  {
                    ++n_wet;
                    p += loads[c].density * gravity_magnitude * depth;
                  }
                // Net pressure on the side the cell's first chamber sees.
                p_net += s * s_first * p / quadrature.size();
              }
          data.wetted[index]   = double(n_wet) / quadrature.size();
          data.pressure[index] = p_net;
        }
      return data;
    }
  } // namespace chambers
} // namespace pneuma
