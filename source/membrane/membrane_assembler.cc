#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <pneuma/membrane/membrane_assembler.h>
#include <pneuma/membrane/surface_kinematics.h>

#include <algorithm>
#include <array>

namespace pneuma
{
  namespace membrane
  {
    namespace
    {
      /// Cells a thread takes at a time: a Q1 cell costs a few
      /// microseconds, so smaller chunks would spend their time in the
      /// pipeline's hand-over.
      constexpr unsigned int cells_per_task = 32;
    } // namespace

    MembraneAssembler::MembraneAssembler(
      const geometry::SceneGenerator &geometry,
      const MaterialRegions          &materials,
      const loads::Loads             &loads)
      : geometry(geometry)
      , materials(materials)
      , loads(loads)
    {
    }

    void
    MembraneAssembler::reinit(const Mapping<2, 3>    &mapping_,
                              const DoFHandler<2, 3> &dof_handler_,
                              const unsigned int      degree_)
    {
      mapping     = &mapping_;
      dof_handler = &dof_handler_;
      degree      = degree_;
      reference.reset();
    }

    const ReferenceGeometry &
    MembraneAssembler::reference_geometry() const
    {
      if (!reference)
        reference = std::make_unique<ReferenceGeometry>(
          geometry, materials, *mapping, *dof_handler, degree);
      return *reference;
    }

    namespace
    {
      /// One thread's working memory of the cell loop.
      struct CellScratch
      {
        CellScratch(const Mapping<2, 3>            &mapping,
                    const FiniteElement<2, 3>      &fe,
                    const Quadrature<1>            &face_quadrature,
                    const unsigned int              n_node,
                    const std::vector<CellTerms *> &terms)
          : fe_face_values(mapping,
                           fe,
                           face_quadrature,
                           update_values | update_quadrature_points
                             | update_JxW_values)
          , u_node(n_node)
          , DP(n_node)
          , DQ(n_node)
          , tau(n_node)
          , K_node(fe.n_dofs_per_cell() * fe.n_dofs_per_cell(), 0.)
          , P_node(fe.n_dofs_per_cell() * fe.n_dofs_per_cell(), 0.)
          , term_list(&terms)
        {
          for (const auto *t : terms)
            this->terms.push_back(t->new_scratch());
        }

        CellScratch(const CellScratch &other)
          : CellScratch(other.fe_face_values.get_mapping(),
                        other.fe_face_values.get_fe(),
                        other.fe_face_values.get_quadrature(),
                        other.u_node.size(),
                        *other.term_list)
        {
        }

        FEFaceValues<2, 3>                 fe_face_values;
        std::vector<std::array<double, 3>> u_node, DP, DQ;
        std::vector<std::array<double, 2>> tau;
        std::vector<double>                K_node, P_node;
        /// Assumed strains: the tying points' state, the strains'
        /// derivatives and the stress weights there.
        TyingState tying;
        double     dE[TyingGeometry::n_tying][3 * AssumedStrains::n_node];
        double     w[TyingGeometry::n_tying];
        const std::vector<CellTerms *>                  *term_list;
        std::vector<std::unique_ptr<CellTerms::Scratch>> terms;
      };

      /// What the cell loop hands from a thread to the sequential copier.
      struct CellCopy
      {
        CellCopy(const unsigned int n_dofs, const std::vector<CellTerms *> &t)
          : dof_indices(n_dofs)
          , local_u(n_dofs)
          , matrix(n_dofs, n_dofs)
          , residual(n_dofs)
          , external(n_dofs)
          , term_list(&t)
        {
          for (const auto *term : t)
            records.push_back(term->new_record());
        }

        CellCopy(const CellCopy &other)
          : CellCopy(other.dof_indices.size(), *other.term_list)
        {
        }

        /// (WorkStream sets its buffers from the sample: the sizes and
        /// fresh records.)
        CellCopy &
        operator=(const CellCopy &other)
        {
          if (this != &other)
            {
              cell_index  = other.cell_index;
              fast        = other.fast;
              condensed   = other.condensed;
              owned       = other.owned;
              dof_indices = other.dof_indices;
              local_u     = other.local_u;
              matrix      = other.matrix;
              residual    = other.residual;
              external    = other.external;
              term_list   = other.term_list;
              records.clear();
              for (const auto *term : *term_list)
                records.push_back(term->new_record());
            }
          return *this;
        }

        unsigned int cell_index = 0;
        bool         fast       = false;
        bool         condensed  = false;
        /// No matrix and no constrained dof: the vectors by local index
        /// where their rows are owned.
        bool                                            owned = false;
        std::vector<types::global_dof_index>            dof_indices;
        std::vector<double>                             local_u;
        FullMatrix<double>                              matrix;
        Vector<double>                                  residual, external;
        const std::vector<CellTerms *>                 *term_list;
        std::vector<std::unique_ptr<CellTerms::Record>> records;
      };
    } // namespace

    namespace
    {
      /// What every cell of one assembly shares.
      struct CellContext
      {
        const ReferenceGeometry &ref;
        const loads::Loads      &loads;
        unsigned int             n_node, n_dofs, n_q;
        /// dof_of[a][c]: the cell dof of node a, component c.
        std::vector<std::array<unsigned int, 3>> dof_of;
        /// Form finding: the form-finding laws, and no load.
        bool         loaded;
        bool         want_matrix, want_vector, want_stress;
        double       t;
        Tensor<1, 3> g;
        /// A pressure that does not depend on the position is evaluated
        /// once.
        bool   uniform_pressure;
        double pressure_value;
        /// The displacement's values by local index (nullptr: by global
        /// index), and the local index of each cell dof.
        const double             *u_values  = nullptr;
        const LA::GhostedIndices *u_indices = nullptr;
      };

      /// The shared data of an assembly at time @p t (loaded: the loads
      /// act; false in form finding).
      CellContext
      make_context(const ReferenceGeometry &ref,
                   const loads::Loads      &loads,
                   const bool               loaded,
                   const AssemblyRequest   &request,
                   const unsigned int       n_q,
                   const unsigned int       n_dofs)
      {
        const double t           = request.time;
        const bool   want_matrix = request.tangent != nullptr;
        const bool   uniform     = loaded && loads.pressure_is_uniform();
        CellContext  ctx{ref,
                        loads,
                        ref.n_nodes(),
                        n_dofs,
                        n_q,
                        std::vector<std::array<unsigned int, 3>>(ref.n_nodes()),
                        loaded,
                        want_matrix,
                        request.residual != nullptr
                          || request.external != nullptr,
                        // The applied loads alone (the reactions' statistics)
                        // need no stresses.
                        want_matrix || request.residual != nullptr,
                        t,
                        loaded && loads.has_gravity() ? loads.gravity(t)
                                                       : Tensor<1, 3>(),
                        uniform,
                        uniform ? loads.pressure(Point<3>(), t) : 0.};
        for (unsigned int i = 0; i < n_dofs; ++i)
          ctx.dof_of[ref.node(i)][ref.component(i)] = i;
        return ctx;
      }

      /// A cell's dofs and nodal displacements into @p copy and @p scratch;
      /// its matrix and vectors cleared.
      void
      gather_cell_values(const CellContext &ctx,
                         const LA::Vector  &u,
                         const unsigned int cell_index,
                         CellScratch       &scratch,
                         CellCopy          &copy)
      {
        const types::global_dof_index *cell_dofs =
          ctx.ref.dof_indices(cell_index);
        copy.cell_index = cell_index;
        std::copy(cell_dofs, cell_dofs + ctx.n_dofs, copy.dof_indices.begin());
        const int *local =
          ctx.u_values ? ctx.u_indices->cell(cell_index) : nullptr;
        for (unsigned int i = 0; i < ctx.n_dofs; ++i)
          {
            copy.local_u[i] =
              local ? ctx.u_values[local[i]] : u[copy.dof_indices[i]];
            scratch.u_node[ctx.ref.node(i)][ctx.ref.component(i)] =
              copy.local_u[i];
          }
        copy.matrix   = 0;
        copy.residual = 0;
        copy.external = 0;
      }

      /// The state of one quadrature point of a cell.
      struct PointState
      {
        /// a_alpha = E_alpha + sum_a u_a dN_a/dS_alpha.
        Tensor<1, 3>          a0, a1;
        SymmetricTensor<2, 2> S;
        SymmetricTensor<4, 2> D;
        double                dA, HdA, p;
      };

      /// The base vectors a_0, a_1 at a point from the nodal displacements.
      void
      base_vectors(const CellContext                        &ctx,
                   const ReferenceGeometry::Point           &P,
                   const std::array<double, 2>              *dN,
                   const std::vector<std::array<double, 3>> &u_node,
                   PointState                               &s)
      {
        for (unsigned int d = 0; d < 3; ++d)
          {
            s.a0[d] = P.E[0][d];
            s.a1[d] = P.E[1][d];
          }
        for (unsigned int a = 0; a < ctx.n_node; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            {
              s.a0[d] += u_node[a][d] * dN[a][0];
              s.a1[d] += u_node[a][d] * dN[a][1];
            }
      }

      /// The internal and external forces of a point: the internal force
      /// of node a is H (tau_a0 a_0 + tau_a1 a_1) dA with
      /// tau_a = S grad_S N_a.
      void
      add_point_forces(const CellContext  &ctx,
                       const PointState   &s,
                       const double       *N,
                       const Tensor<1, 3> &dead_load,
                       const bool          internal,
                       CellScratch        &scratch,
                       CellCopy           &copy)
      {
        const Tensor<1, 3> area_vector = cross_product_3d(s.a0, s.a1);
        for (unsigned int a = 0; a < ctx.n_node; ++a)
          for (unsigned int c = 0; c < 3; ++c)
            {
              const unsigned int i = ctx.dof_of[a][c];
              const double       f_ext =
                (s.p * area_vector[c] + dead_load[c]) * N[a] * s.dA;
              copy.residual(i) += internal
                                    ? s.HdA
                                          * (scratch.tau[a][0] * s.a0[c]
                                             + scratch.tau[a][1] * s.a1[c])
                                        - f_ext
                                    : -f_ext;
              copy.external(i) += f_ext;
            }
      }

      /// The law's tangent in Voigt form: rows S_11, S_22, S_12, columns
      /// E_11, E_22, 2 E_12.
      void
      voigt(const SymmetricTensor<4, 2> &D, double (*Dv)[3])
      {
        for (unsigned int r = 0; r < 3; ++r)
          {
            const unsigned int i = r == 1 ? 1 : 0, j = r == 0 ? 0 : 1;
            Dv[r][0] = D[i][j][0][0];
            Dv[r][1] = D[i][j][1][1];
            Dv[r][2] = D[i][j][0][1];
          }
      }

      /**
       * The material and geometric stiffness of a point into the upper
       * node blocks (b >= a; both parts are symmetric). Material part in
       * Voigt form: the strain of dof (a, c) is a0[c] P_a + a1[c] Q_a with
       * P_a = (dN_a0, 0, dN_a1) and Q_a = (0, dN_a1, dN_a0) (components
       * E11, E22, 2 E12).
       */
      void
      add_point_stiffness(const CellContext           &ctx,
                          const PointState            &s,
                          const std::array<double, 2> *dN,
                          CellScratch                 &scratch)
      {
        const auto &D      = s.D;
        auto       &DP     = scratch.DP;
        auto       &DQ     = scratch.DQ;
        const auto &tau    = scratch.tau;
        const auto  n_node = ctx.n_node;
        const auto  n_dofs = ctx.n_dofs;
        double      Dv[3][3];
        voigt(D, Dv);
        for (unsigned int b = 0; b < n_node; ++b)
          for (unsigned int r = 0; r < 3; ++r)
            {
              DP[b][r] = Dv[r][0] * dN[b][0] + Dv[r][2] * dN[b][1];
              DQ[b][r] = Dv[r][1] * dN[b][1] + Dv[r][2] * dN[b][0];
            }
        for (unsigned int a = 0; a < n_node; ++a)
          for (unsigned int b = a; b < n_node; ++b)
            {
              // P_a . D P_b etc.
              const double m00 = dN[a][0] * DP[b][0] + dN[a][1] * DP[b][2];
              const double m01 = dN[a][0] * DQ[b][0] + dN[a][1] * DQ[b][2];
              const double m10 = dN[a][1] * DP[b][1] + dN[a][0] * DP[b][2];
              const double m11 = dN[a][1] * DQ[b][1] + dN[a][0] * DQ[b][2];
              const double geometric =
                s.HdA * (dN[a][0] * tau[b][0] + dN[a][1] * tau[b][1]);
              for (unsigned int c = 0; c < 3; ++c)
                {
                  const double x0 = s.HdA * (s.a0[c] * m00 + s.a1[c] * m10);
                  const double x1 = s.HdA * (s.a0[c] * m01 + s.a1[c] * m11);
                  double *row = &scratch.K_node[(3 * a + c) * n_dofs + 3 * b];
                  for (unsigned int d = 0; d < 3; ++d)
                    row[d] += x0 * s.a0[d] + x1 * s.a1[d];
                  row[c] += geometric;
                }
            }
      }

      /// The follower pressure's stiffness of a point:
      /// -p N_a eps_cdk w_k with w = dN_b0 a_1 - dN_b1 a_0.
      void
      add_pressure_stiffness(const CellContext           &ctx,
                             const PointState            &s,
                             const double                *N,
                             const std::array<double, 2> *dN,
                             CellScratch                 &scratch)
      {
        for (unsigned int a = 0; a < ctx.n_node; ++a)
          {
            const double f = s.p * N[a] * s.dA;
            for (unsigned int b = 0; b < ctx.n_node; ++b)
              {
                const Tensor<1, 3> w = f * (dN[b][0] * s.a1 - dN[b][1] * s.a0);
                double *r0 = &scratch.P_node[(3 * a) * ctx.n_dofs + 3 * b];
                double *r1 = r0 + ctx.n_dofs, *r2 = r1 + ctx.n_dofs;
                r0[1] -= w[2];
                r0[2] += w[1];
                r1[0] += w[2];
                r1[2] -= w[0];
                r2[0] -= w[1];
                r2[1] += w[0];
              }
          }
      }

      /// The cell matrix from the upper node blocks, mirrored, and the
      /// pressure part, in the cell's dof order; the blocks are cleared.
      void
      gather_cell_matrix(const CellContext &ctx,
                         CellScratch       &scratch,
                         CellCopy          &copy)
      {
        const auto &K = scratch.K_node;
        const auto &P = scratch.P_node;
        const auto  n = ctx.n_dofs;
        for (unsigned int a = 0; a < ctx.n_node; ++a)
          for (unsigned int b = 0; b < ctx.n_node; ++b)
            for (unsigned int c = 0; c < 3; ++c)
              for (unsigned int d = 0; d < 3; ++d)
                copy.matrix(ctx.dof_of[a][c], ctx.dof_of[b][d]) =
                  (b >= a ? K[(3 * a + c) * n + 3 * b + d]
                          : K[(3 * b + d) * n + 3 * a + c])
                  + P[(3 * a + c) * n + 3 * b + d];
        std::fill(scratch.K_node.begin(), scratch.K_node.end(), 0.);
        std::fill(scratch.P_node.begin(), scratch.P_node.end(), 0.);
      }

      /// The point's pressure and dead load (weight, surface load).
      Tensor<1, 3>
      point_loads(const CellContext              &ctx,
                  const RegionMaterial           &material,
                  const bool                      pressurised,
                  const bool                      surface_loaded,
                  const ReferenceGeometry::Point &P,
                  PointState                     &s)
      {
        const Point<3> X(P.X[0], P.X[1], P.X[2]);
        s.p                    = !pressurised           ? 0.
                                 : ctx.uniform_pressure ? ctx.pressure_value
                                                        : ctx.loads.pressure(X, ctx.t);
        Tensor<1, 3> dead_load = material.density * material.thickness * ctx.g;
        if (surface_loaded)
          dead_load += ctx.loads.surface_load(X, ctx.t);
        return dead_load;
      }

      /// The strains' derivatives at the tying points of a cell with
      /// assumed strains, and its stress weights cleared.
      void
      start_assumed_cell(const CellContext   &ctx,
                         const TyingGeometry &tying,
                         CellScratch         &scratch)
      {
        const auto &rule = ctx.ref.assumed_strains();
        rule.state(tying, scratch.u_node, scratch.tying);
        if (ctx.want_stress)
          rule.strain_derivatives(scratch.tying, scratch.dE);
        std::fill(std::begin(scratch.w), std::end(scratch.w), 0.);
      }

      /// The internal forces and geometric stiffness of a cell with
      /// assumed strains, through its tying points.
      void
      finish_assumed_cell(const CellContext &ctx,
                          CellScratch       &scratch,
                          CellCopy          &copy)
      {
        const auto &rule = ctx.ref.assumed_strains();
        if (ctx.want_vector && ctx.want_stress)
          {
            double f[3 * AssumedStrains::n_node] = {};
            rule.add_forces(scratch.dE, scratch.w, f);
            for (unsigned int a = 0; a < ctx.n_node; ++a)
              for (unsigned int c = 0; c < 3; ++c)
                copy.residual(ctx.dof_of[a][c]) += f[3 * a + c];
          }
        if (ctx.want_matrix)
          rule.add_geometric_stiffness(scratch.w, scratch.K_node.data());
      }

      /// The stresses, loads and tangent of every quadrature point of a
      /// cell (the membrane's own terms). A cell with assumed strains
      /// (ref.tying) takes its strains from the tying points and its
      /// internal forces and stiffness through them; loads are the same.
      void
      add_cell_points(const CellContext                            &ctx,
                      const RegionMaterial                         &material,
                      const DoFHandler<2, 3>::active_cell_iterator &cell,
                      const unsigned int                            cell_index,
                      CellScratch                                  &scratch,
                      CellCopy                                     &copy)
      {
        const auto &loads = ctx.loads;
        const bool  pressurised =
          ctx.loaded && loads.pressure_acts_on(cell->material_id());
        const bool surface_loaded =
          ctx.loaded && loads.surface_load_acts_on(cell->material_id());
        const TyingGeometry *tying = ctx.ref.tying(cell_index);
        if (tying)
          start_assumed_cell(ctx, *tying, scratch);
        PointState s;
        for (unsigned int q = 0; q < ctx.n_q; ++q)
          {
            const auto   &P  = ctx.ref.point(cell_index, q);
            const auto   *dN = ctx.ref.shape_derivatives(cell_index, q);
            const double *N  = ctx.ref.shape_values(q);
            base_vectors(ctx, P, dN, scratch.u_node, s);
            SymmetricTensor<2, 2> C;
            if (tying)
              C = ctx.ref.assumed_strains().right_cauchy_green(*tying,
                                                               scratch.tying,
                                                               q);
            else
              C = right_cauchy_green({{s.a0, s.a1}});
            if (ctx.want_matrix)
              material.law->evaluate(C, s.S, s.D);
            else if (ctx.want_stress)
              material.law->stress(C, s.S);
            s.dA  = P.JxW;
            s.HdA = material.thickness * s.dA;
            const Tensor<1, 3> dead_load =
              point_loads(ctx, material, pressurised, surface_loaded, P, s);
            if (tying && ctx.want_stress)
              ctx.ref.assumed_strains().add_stress_weights(
                *tying, q, s.S, s.HdA, scratch.w);
            for (unsigned int a = 0; !tying && a < ctx.n_node; ++a)
              {
                scratch.tau[a][0] = s.S[0][0] * dN[a][0] + s.S[0][1] * dN[a][1];
                scratch.tau[a][1] = s.S[0][1] * dN[a][0] + s.S[1][1] * dN[a][1];
              }
            if (ctx.want_vector)
              add_point_forces(ctx, s, N, dead_load, !tying, scratch, copy);
            if (!ctx.want_matrix)
              continue;
            if (tying)
              {
                double Dv[3][3];
                voigt(s.D, Dv);
                ctx.ref.assumed_strains().add_material_stiffness(
                  *tying, q, scratch.dE, Dv, s.HdA, scratch.K_node.data());
              }
            else
              add_point_stiffness(ctx, s, dN, scratch);
            if (s.p != 0.)
              add_pressure_stiffness(ctx, s, N, dN, scratch);
          }
        if (tying)
          finish_assumed_cell(ctx, scratch, copy);
        if (ctx.want_matrix)
          gather_cell_matrix(ctx, scratch, copy);
      }

      /// Dead line loads on the listed boundaries of a cell.
      void
      add_line_loads(const CellContext                            &ctx,
                     const DoFHandler<2, 3>::active_cell_iterator &cell,
                     CellScratch                                  &scratch,
                     CellCopy                                     &copy)
      {
        const auto &boundaries = ctx.loads.line_load_boundaries();
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary()
              && boundaries.count(cell->face(f)->boundary_id()))
            {
              auto &fe_face_values = scratch.fe_face_values;
              fe_face_values.reinit(cell, f);
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                {
                  const Tensor<1, 3> load =
                    ctx.loads.line_load(fe_face_values.quadrature_point(q),
                                        ctx.t);
                  for (unsigned int i = 0; i < ctx.n_dofs; ++i)
                    {
                      const unsigned int c = ctx.ref.component(i);
                      const double       f_ext =
                        load[c] * fe_face_values.shape_value_component(i, q, c)
                        * fe_face_values.JxW(q);
                      copy.residual(i) -= f_ext;
                      copy.external(i) += f_ext;
                    }
                }
            }
      }

      /**
       * Adds a cell's matrix and vectors to the global ones, one cell at a
       * time in cell order (the sums over cells are formed as on one
       * thread): cells without constraints and with owned rows at the
       * precomputed positions, cells whose constrained dofs (rigid plates)
       * have owned targets condensed at precomputed positions, the others
       * through the constraints.
       */
      struct CellCopier
      {
        const AffineConstraints<double> &constraints;
        const AssemblyRequest           &request;
        LA::MatrixPositions             &positions;
        double                          *residual_values;
        double                          *external_values;
        bool                             want_matrix;
        /// Without a matrix: the owned values of the residual and the
        /// applied loads.
        LA::OwnedValues residual_owned, external_owned;

        /// A vector of a cell with no constrained dof and no matrix: each
        /// entry by local index where owned here, else through @p target.
        void
        add_owned(const CellCopy        &copy,
                  const Vector<double>  &cell_vector,
                  const LA::OwnedValues &owned,
                  LA::Vector            *target) const
        {
          if (!target)
            return;
          for (unsigned int i = 0; i < cell_vector.size(); ++i)
            if (owned.owns(copy.dof_indices[i]))
              owned[copy.dof_indices[i]] += cell_vector[i];
            else
              (*target)(copy.dof_indices[i]) += cell_vector[i];
        }

        /// A cell vector: by local index on the fast path, else through
        /// the constraints.
        void
        add_vector(const CellCopy       &copy,
                   const Vector<double> &cell_vector,
                   double               *local,
                   LA::Vector           *target) const
        {
          if (copy.fast && local)
            positions.add_vector(copy.cell_index, cell_vector.data(), local);
          else if (copy.condensed && local
                   && positions.condensed_owned(copy.cell_index))
            positions.add_condensed_vector(copy.cell_index,
                                           cell_vector.data(),
                                           local);
          else if (target)
            constraints.distribute_local_to_global(cell_vector,
                                                   copy.dof_indices,
                                                   *target);
        }

        void
        operator()(const CellCopy &copy) const
        {
          for (unsigned int k = 0; k < request.cell_terms.size(); ++k)
            request.cell_terms[k]->commit(*copy.records[k], copy.dof_indices);
          if (copy.owned)
            {
              add_owned(copy, copy.residual, residual_owned, request.residual);
              add_owned(copy, copy.external, external_owned, request.external);
              return;
            }
          if (copy.fast)
            {
              positions.add(copy.cell_index, &copy.matrix(0, 0));
              add_vector(copy,
                         copy.residual,
                         residual_values,
                         request.residual);
            }
          else if (copy.condensed)
            {
              positions.add_condensed(copy.cell_index, &copy.matrix(0, 0));
              add_vector(copy,
                         copy.residual,
                         residual_values,
                         request.residual);
            }
          else
            LA::distribute(constraints,
                           copy.matrix,
                           copy.residual,
                           copy.dof_indices,
                           want_matrix ? request.tangent : nullptr,
                           request.residual);
          add_vector(copy, copy.external, external_values, request.external);
        }
      };
    } // namespace

    namespace
    {
      /// Let the cells of @p ctx read @p u by local index (see
      /// LA::GhostedIndices), where all their dofs are in @p u's range.
      void
      read_by_local_index(const LA::Vector   &u,
                          LA::GhostedIndices &indices,
                          CellContext        &ctx)
      {
        ctx.u_values  = indices.values(u,
                                      ctx.ref.dof_indices(0),
                                      ctx.ref.n_cells(),
                                      ctx.n_dofs);
        ctx.u_indices = &indices;
      }

      /// Direct access to @p v's owned values for an assembly without a
      /// matrix (none with one, or without @p v).
      LA::OwnedValues
      owned_values(const CellContext &ctx, LA::Vector *v)
      {
        return ctx.want_matrix || !v ? LA::OwnedValues() : LA::OwnedValues(*v);
      }
    } // namespace

    const RegionMaterial &
    MembraneAssembler::cell_material(const types::material_id id,
                                     const bool               loaded) const
    {
      if (!loaded)
        return form_finding_laws.at(id);
      return plain_laws.empty() ? materials[id] : plain_laws.at(id);
    }

    void
    MembraneAssembler::assemble(const LA::Vector                &u,
                                const AffineConstraints<double> &constraints,
                                const AssemblyRequest           &request) const
    {
      Assert(mapping != nullptr, ExcNotInitialized());
      const auto     &fe = dof_handler->get_fe();
      const QGauss<2> quadrature(degree + 1);
      const QGauss<1> face_quadrature(degree + 1);
      loads.set_time(request.time);
      CellContext ctx = make_context(reference_geometry(),
                                     loads,
                                     form_finding_laws.empty(),
                                     request,
                                     quadrature.size(),
                                     fe.n_dofs_per_cell());
      const auto &ref = ctx.ref;
      read_by_local_index(u, ghosted_indices, ctx);
      const bool direct = ctx.want_matrix
                          && positions.update(*request.tangent,
                                              ref.dof_indices(0),
                                              ref.n_cells(),
                                              ctx.n_dofs,
                                              constraints);

      // The locally owned cells in the order of the reference data.
      std::vector<DoFHandler<2, 3>::active_cell_iterator> cells;
      cells.reserve(ref.n_cells());
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          cells.push_back(cell);
      const auto first   = cells.cbegin();
      using CellIterator = decltype(first);

      const auto worker = [&](const CellIterator &it,
                              CellScratch        &scratch,
                              CellCopy           &copy) {
        const auto        &cell       = *it;
        const unsigned int cell_index = it - first;
        gather_cell_values(ctx, u, cell_index, scratch, copy);
        add_cell_points(ctx,
                        cell_material(cell->material_id(), ctx.loaded),
                        cell,
                        cell_index,
                        scratch,
                        copy);
        if (ctx.loaded && ctx.want_vector
            && !loads.line_load_boundaries().empty())
          add_line_loads(ctx, cell, scratch, copy);
        for (unsigned int k = 0; k < request.cell_terms.size(); ++k)
          request.cell_terms[k]->cell(cell,
                                      ref,
                                      cell_index,
                                      copy.local_u,
                                      ctx.want_matrix ? &copy.matrix : nullptr,
                                      request.residual ? &copy.residual
                                                       : nullptr,
                                      *scratch.terms[k],
                                      *copy.records[k]);
        // Cells without constrained dofs take a direct path.
        bool free = true;
        for (unsigned int i = 0; free && i < ctx.n_dofs; ++i)
          free = !constraints.is_constrained(copy.dof_indices[i]);
        copy.fast  = free && direct && positions.direct(cell_index);
        copy.owned = free && !ctx.want_matrix;
        copy.condensed =
          direct && !copy.fast && positions.condensed(cell_index);
      };
      const CellCopier copier{constraints,
                              request,
                              positions,
                              direct && request.residual
                                ? positions.local_values(*request.residual)
                                : nullptr,
                              direct && request.external
                                ? positions.local_values(*request.external)
                                : nullptr,
                              ctx.want_matrix,
                              owned_values(ctx, request.residual),
                              owned_values(ctx, request.external)};

      WorkStream::run(cells.cbegin(),
                      cells.cend(),
                      worker,
                      copier,
                      CellScratch(*mapping,
                                  fe,
                                  face_quadrature,
                                  ctx.n_node,
                                  request.cell_terms),
                      CellCopy(ctx.n_dofs, request.cell_terms),
                      2 * MultithreadInfo::n_threads(),
                      cells_per_task);

      if (direct)
        positions.flush(*request.tangent);
      for (auto *v : {request.residual, request.external})
        if (v)
          v->compress(VectorOperation::add);
      if (request.tangent)
        request.tangent->compress(VectorOperation::add);
    }

    void
    MembraneAssembler::surface_laplacian(
      const AffineConstraints<double> &constraints,
      LA::SparseMatrix                &L) const
    {
      const auto                          &fe = dof_handler->get_fe();
      const QGauss<2>                      quadrature(degree + 1);
      FEValues<2, 3>                       fe_values(*mapping,
                               fe,
                               quadrature,
                               update_gradients | update_JxW_values);
      const unsigned int                   n_dofs = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(n_dofs);
      FullMatrix<double>                   cell_matrix(n_dofs, n_dofs);
      L = 0.;
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dof_indices);
            cell_matrix = 0;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const unsigned int ci = fe.system_to_component_index(i).first;
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    if (fe.system_to_component_index(j).first == ci)
                      cell_matrix(i, j) +=
                        fe_values.shape_grad_component(i, q, ci)
                        * fe_values.shape_grad_component(j, q, ci)
                        * fe_values.JxW(q);
                }
            constraints.distribute_local_to_global(cell_matrix, dof_indices, L);
          }
      L.compress(VectorOperation::add);
    }

    void
    MembraneAssembler::mass_matrix(const AffineConstraints<double> &constraints,
                                   LA::SparseMatrix                &M) const
    {
      const auto                          &fe = dof_handler->get_fe();
      const QGauss<2>                      quadrature(degree + 1);
      FEValues<2, 3>                       fe_values(*mapping,
                               fe,
                               quadrature,
                               update_values | update_JxW_values);
      const unsigned int                   n_dofs = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(n_dofs);
      FullMatrix<double>                   cell_matrix(n_dofs, n_dofs);
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const RegionMaterial &m     = materials[cell->material_id()];
            const double          rho_h = m.density * m.thickness;
            fe_values.reinit(cell);
            cell->get_dof_indices(dof_indices);
            cell_matrix = 0;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const unsigned int ci = fe.system_to_component_index(i).first;
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    if (fe.system_to_component_index(j).first == ci)
                      cell_matrix(i, j) +=
                        rho_h * fe_values.shape_value_component(i, q, ci)
                        * fe_values.shape_value_component(j, q, ci)
                        * fe_values.JxW(q);
                }
            constraints.distribute_local_to_global(cell_matrix, dof_indices, M);
          }
      M.compress(VectorOperation::add);
    }

    void
    MembraneAssembler::lumped_mass(LA::Vector &m) const
    {
      // The row sums of the consistent mass: the shape functions of each
      // component sum to one, so row i sums to rho H int N_i dA.
      const auto                          &fe = dof_handler->get_fe();
      const QGauss<2>                      quadrature(degree + 1);
      FEValues<2, 3>                       fe_values(*mapping,
                               fe,
                               quadrature,
                               update_values | update_JxW_values);
      const unsigned int                   n_dofs = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(n_dofs);
      Vector<double>                       cell_mass(n_dofs);
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const RegionMaterial &material = materials[cell->material_id()];
            const double          rho_h = material.density * material.thickness;
            fe_values.reinit(cell);
            cell->get_dof_indices(dof_indices);
            cell_mass = 0.;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              for (unsigned int i = 0; i < n_dofs; ++i)
                cell_mass(i) += rho_h
                                * fe_values.shape_value_component(
                                  i, q, fe.system_to_component_index(i).first)
                                * fe_values.JxW(q);
            m.add(dof_indices, cell_mass);
          }
      m.compress(VectorOperation::add);
    }

    double
    MembraneAssembler::enclosed_volume(const LA::Vector &u) const
    {
      const auto                      &fe = dof_handler->get_fe();
      const QGauss<2>                  quadrature(degree + 1);
      FEValues<2, 3>                   fe_values(*mapping,
                               fe,
                               quadrature,
                               update_values | update_gradients
                                 | update_normal_vectors
                                 | update_quadrature_points
                                 | update_JxW_values);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<2, 3>>        grad_u(quadrature.size());
      std::vector<Tensor<1, 3>>        u_q(quadrature.size());
      double                           volume = 0.;
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[displacement].get_function_gradients(u, grad_u);
            fe_values[displacement].get_function_values(u, u_q);
            const double sign = cell_orientation(geometry, fe_values);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const TangentFrame frame =
                  tangent_frame(sign * fe_values.normal_vector(q));
                const auto     a = deformed_tangents(frame, grad_u[q]);
                const Point<3> x = fe_values.quadrature_point(q) + u_q[q];
                volume += x * cross_product_3d(a[0], a[1]) * fe_values.JxW(q);
              }
          }
      return Utilities::MPI::sum(volume, dof_handler->get_communicator()) / 3.;
    }

    double
    MembraneAssembler::surface_area(const LA::Vector &u) const
    {
      const auto                      &fe = dof_handler->get_fe();
      const QGauss<2>                  quadrature(degree + 1);
      FEValues<2, 3>                   fe_values(*mapping,
                               fe,
                               quadrature,
                               update_gradients | update_normal_vectors
                                 | update_JxW_values);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<2, 3>>        grad_u(quadrature.size());
      double                           area = 0.;
      for (const auto &cell : dof_handler->active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[displacement].get_function_gradients(u, grad_u);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const auto a =
                  deformed_tangents(tangent_frame(fe_values.normal_vector(q)),
                                    grad_u[q]);
                area += cross_product_3d(a[0], a[1]).norm() * fe_values.JxW(q);
              }
          }
      return Utilities::MPI::sum(area, dof_handler->get_communicator());
    }
  } // namespace membrane
} // namespace pneuma
