#include <deal.II/base/quadrature_lib.h>

#include <pneuma/membrane/bending/bending_cells.h>
#include <pneuma/membrane/bending/point_geometry.h>
#include <pneuma/membrane/bending/sacado_energy.h>
#include <pneuma/membrane/membrane_subsystem.h>

#include <type_traits>

namespace pneuma
{
  namespace membrane
  {
    namespace bending
    {
      namespace
      {
        struct CellScratch : CellTerms::Scratch
        {
          CellScratch(const MembraneSubsystem &membrane)
            : base(membrane.dof_handler().get_fe().base_element(0))
            , nodes(membrane.mapping(), base)
            , dof(node_dofs(membrane.dof_handler().get_fe()))
          {
            const QGauss<2> gauss(membrane.degree() + 1);
            for (unsigned int q = 0; q < gauss.size(); ++q)
              {
                shape.push_back(shape_derivatives(base, gauss.point(q)));
                weight.push_back(gauss.weight(q));
              }
          }
          const FiniteElement<2, 3>                              &base;
          NodePositions                                           nodes;
          std::array<std::array<unsigned int, 3>, max_cell_nodes> dof;
          std::vector<ShapeDerivatives>                           shape;
          std::vector<double>                                     weight;
          std::vector<Vec<double>>                                x;
          std::array<double, 15 * 15>                             hessian;
        };

        struct CellRecord : CellTerms::Record
        {
          double energy = 0.;
        };
      } // namespace

      BendingCells::BendingCells(const ShellContext &context)
        : context(context)
      {
      }

      void
      BendingCells::begin(const Assembly &)
      {
        sum = 0.;
      }

      std::unique_ptr<CellTerms::Scratch>
      BendingCells::new_scratch() const
      {
        return std::make_unique<CellScratch>(*context.membrane);
      }

      std::unique_ptr<CellTerms::Record>
      BendingCells::new_record() const
      {
        return std::make_unique<CellRecord>();
      }

      void
      BendingCells::cell(const DoFHandler<2, 3>::active_cell_iterator &cell,
                         const ReferenceGeometry &,
                         const unsigned int,
                         const std::vector<double> &local_u,
                         FullMatrix<double>        *cell_matrix,
                         Vector<double>            *cell_residual,
                         CellTerms::Scratch        &scratch_data,
                         CellTerms::Record         &record_data) const
      {
        auto &record             = static_cast<CellRecord &>(record_data);
        record.energy            = 0.;
        const RegionStiffness *k = context.of(cell->material_id());
        if (k == nullptr || (!cell_matrix && !cell_residual))
          return;
        auto       &s = static_cast<CellScratch &>(scratch_data);
        const auto &X = s.nodes.of(cell);
        s.x           = X;
        for (unsigned int a = 0; a < X.size(); ++a)
          for (unsigned int c = 0; c < 3; ++c)
            s.x[a][c] += local_u[s.dof[a][c]];
        const auto &material =
          context.membrane->material_regions()[cell->material_id()];
        const Tensor<1, 3> w =
          material.warp(context.membrane->geometry(), cell);
        const Vec<double> warp{{w[0], w[1], w[2]}};
        for (unsigned int q = 0; q < s.shape.size(); ++q)
          {
            double G[15], g[15], gradient[15];
            point_derivatives(X, s.shape[q], G);
            const ReferencePoint ref = reference_point(G, warp, k->D, 1.);
            point_derivatives(s.x, s.shape[q], g);
            const double weight = ref.area * s.weight[q];
            const auto   energy = [&](auto *v) {
              using T = std::decay_t<decltype(*v)>;
              T e     = cell_energy(v, ref.frame);
              e *= weight;
              return e;
            };
            record.energy += differentiate<15>(
              g, energy, gradient, cell_matrix ? s.hessian.data() : nullptr);
            add_point_terms(1,
                            &s.shape[q],
                            &s.dof,
                            gradient,
                            s.hessian.data(),
                            cell_residual,
                            cell_matrix);
          }
      }

      void
      BendingCells::commit(const CellTerms::Record &record,
                           const std::vector<types::global_dof_index> &)
      {
        sum += static_cast<const CellRecord &>(record).energy;
      }
    } // namespace bending
  }   // namespace membrane
} // namespace pneuma
