#include <deal.II/base/mpi.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/numerics/rtree.h>

#include <pneuma/contact/contact_system.h>
#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      /// Whether pair @p p measures its gap along the smoothed normal in
      /// the load step to pseudo time @p t (Smoothed normal from).
      bool
      smoothed_at(const ContactPair &p, const double t)
      {
        return p.smoothed_normal
               && (p.smoothed_from <= 0. || t > p.smoothed_from);
      }

      /**
       * The masters whose boxes in @p tree (ContactSystem::master_boxes)
       * touch the box of the cable element @p x0 - @p x1 enlarged by
       * @p reach, in master order (closed boxes: touching counts).
       */
      template <class Tree>
      std::vector<unsigned int>
      masters_near(const Tree         &tree,
                   const Tensor<1, 3> &x0,
                   const Tensor<1, 3> &x1,
                   const double        reach)
      {
        Point<3> lower, upper;
        for (unsigned int i = 0; i < 3; ++i)
          {
            lower[i] = std::min(x0[i], x1[i]) - reach;
            upper[i] = std::max(x0[i], x1[i]) + reach;
          }
        std::vector<std::pair<BoundingBox<3>, unsigned int>> hits;
        tree.query(boost::geometry::index::intersects(
                     BoundingBox<3>({lower, upper})),
                   std::back_inserter(hits));
        std::vector<unsigned int> found;
        found.reserve(hits.size());
        for (const auto &hit : hits)
          found.push_back(hit.second);
        std::sort(found.begin(), found.end());
        return found;
      }
    } // namespace

    ContactSystem::ContactSystem(const ContactParameters        &parameters,
                                 const geometry::SceneGenerator &geometry,
                                 const cables::CableSystem      &cables)
      : parameters(parameters)
      , geometry(geometry)
      , cables(cables)
    {
    }

    void
    ContactSystem::setup(const Mapping<2, 3>    &mapping,
                         const DoFHandler<2, 3> &dof_handler,
                         const MPI_Comm          comm_)
    {
      comm = comm_;
      masters.clear();
      pairs.clear();
      coupled.clear();
      if (empty())
        return;
      const FiniteElement<2, 3> &fe = dof_handler.get_fe();
      degree                        = fe.base_element(0).degree;
      const unsigned int n          = degree + 1;

      // Master cells: owned membrane cells in any pair's regions.
      std::set<types::material_id> regions;
      bool                         all_regions = false;
      for (const auto &p : parameters.all())
        {
          all_regions = all_regions || p.regions.empty();
          regions.insert(p.regions.begin(), p.regions.end());
        }
      std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
      const auto                           make_master = [&](const auto &cell) {
        MasterCell m;
        m.cell     = cell;
        m.material = cell->material_id();
        m.dofs.resize(3 * n * n);
        m.reference.resize(n * n);
        cell->get_dof_indices(cell_dofs);
        for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
          {
            const auto [c, base] = fe.system_to_component_index(k);
            const Point<2>     xi = fe.base_element(0).unit_support_point(base);
            const unsigned int a =
              std::lround(xi[0] * degree) + n * std::lround(xi[1] * degree);
            m.dofs[3 * a + c] = cell_dofs[k];
          }
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            m.reference[i + n * j] = mapping.transform_unit_to_real_cell(
              cell, Point<2>(double(i) / degree, double(j) / degree));
        // Outward sign and area of the patch at its centre.
        const Point<3> x =
          mapping.transform_unit_to_real_cell(cell, Point<2>(0.5, 0.5));
        // rho_1 x rho_2 at the centre from the lattice.
        Tensor<1, 3> d1, d2;
        if (degree == 1)
          {
            d1 = 0.5
                 * (m.reference[1] - m.reference[0] + m.reference[3]
                    - m.reference[2]);
            d2 = 0.5
                 * (m.reference[2] - m.reference[0] + m.reference[3]
                    - m.reference[1]);
          }
        else
          {
            d1 = m.reference[5] - m.reference[3];
            d2 = m.reference[7] - m.reference[1];
          }
        const Tensor<1, 3> normal = cross_product_3d(d1, d2);
        m.outward = geometry.orientation(x, normal);
        m.area    = normal.norm();
        return m;
      };
      // Owned and ghost cells of the pairs' regions: the owned ones are
      // the masters, all of them give the nodal normals.
      std::vector<MasterCell> neighbourhood;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial()
            && (all_regions || regions.count(cell->material_id())))
          {
            neighbourhood.push_back(make_master(cell));
            if (cell->is_locally_owned())
              masters.push_back(neighbourhood.back());
          }

      // Cable points.
      for (const auto &p : parameters.all())
        {
          PairData                d;
          const cables::CableView v = cables.view(p.cable);
          const QGauss<1>         gauss(p.points_per_element);
          const QGaussLobatto<1>  lobatto(std::max(2u, p.points_per_element));
          const Quadrature<1>    &rule =
            p.lobatto ? static_cast<const Quadrature<1> &>(lobatto) : gauss;
          unsigned int index = 0;
          double       h_max = 0.;
          d.beam             = !v.section_components.empty() && p.radius == 0.;
          for (const auto &cell : v.dof_handler->active_cell_iterators())
            {
              std::vector<types::global_dof_index> dofs(d.beam ? 18 : 6);
              std::vector<double>                  values(dofs.size());
              std::array<Tensor<1, 3>, 2>          X;
              for (unsigned int vtx = 0; vtx < 2; ++vtx)
                {
                  for (unsigned int c = 0; c < 3; ++c)
                    {
                      const auto local  = cell->vertex_dof_index(vtx, c);
                      dofs[3 * vtx + c] = v.offset + local;
                      X[vtx][c]         = (*v.reference)[local];
                    }
                  // The contact's layout of a beam cell: the mid-line, then
                  // a1 and a2 of each vertex.
                  if (d.beam)
                    for (unsigned int c = 0; c < 6; ++c)
                      dofs[6 + 6 * vtx + c] =
                        v.offset
                        + cell->vertex_dof_index(vtx, v.section_components[c]);
                }
              for (unsigned int i = 0; i < dofs.size(); ++i)
                values[i] = (*v.reference)[dofs[i] - v.offset];
              d.cell_reference_values.push_back(values);
              const double length = (X[1] - X[0]).norm();
              h_max               = std::max(h_max, length);
              for (unsigned int q = 0; q < rule.size(); ++q)
                d.points.push_back(
                  {index, rule.point(q)[0], rule.weight(q) * length});
              d.cell_dofs.push_back(dofs);
              d.cell_reference.push_back(X);
              ++index;
            }
          d.smoothed = smoothed_at(p, 0.);
          if (p.smoothed_normal)
            {
              std::vector<NormalCell> cells;
              for (const auto &m : neighbourhood)
                if (p.regions.empty() || p.regions.count(m.material))
                  cells.push_back(
                    {m.dofs, m.reference, p.outside ? m.outward : -m.outward});
              d.normals.reinit(degree, cells);
            }
          d.radius = p.radius > 0. ? p.radius : v.radius;
          d.search =
            p.search_distance > 0. ? p.search_distance : d.radius + h_max;
          d.candidates.resize(index);
          d.anchor.assign(d.points.size(), -1);
          d.anchor_xi.assign(d.points.size(), Point<2>());
          pairs.push_back(d);
        }
      recorded = new_record();
    }

    IndexSet
    ContactSystem::cable_dofs(const types::global_dof_index size) const
    {
      IndexSet dofs(size);
      for (const auto &p : pairs)
        for (const auto &cell : p.cell_dofs)
          for (const auto i : cell)
            dofs.add_index(i);
      return dofs;
    }

    MasterPatch
    ContactSystem::patch(const MasterCell &m,
                         const bool        outside,
                         const LA::Vector *u,
                         NodalNormals     *normals) const
    {
      MasterPatch patch;
      patch.degree = degree;
      patch.nodes  = m.reference;
      if (u)
        for (unsigned int a = 0; a < patch.nodes.size(); ++a)
          for (unsigned int c = 0; c < 3; ++c)
            patch.nodes[a][c] += (*u)[m.dofs[3 * a + c]];
      patch.sign = outside ? m.outward : -m.outward;
      if (normals && u)
        for (unsigned int a = 0; a < patch.nodes.size(); ++a)
          patch.normals.push_back(normals->normal(m.dofs[3 * a], *u));
      return patch;
    }

    void
    ContactSystem::variable_map(
      const PairData                                        &d,
      const unsigned int                                     cable_cell,
      const MasterCell                                      &m,
      const LA::Vector                                      *u,
      std::vector<types::global_dof_index>                  &dofs,
      std::vector<std::vector<std::pair<unsigned, double>>> *rows) const
    {
      const auto &slave = d.cell_dofs[cable_cell];
      dofs.assign(slave.begin(), slave.end());
      dofs.insert(dofs.end(), m.dofs.begin(), m.dofs.end());
      if (!d.smoothed)
        return;
      const unsigned int n_nodes = m.reference.size();
      // Position of a dof in the list (appended if new).
      const auto position = [&](const types::global_dof_index i) {
        for (unsigned int j = slave.size(); j < dofs.size(); ++j)
          if (dofs[j] == i)
            return j;
        dofs.push_back(i);
        return static_cast<unsigned int>(dofs.size() - 1);
      };
      std::vector<std::vector<unsigned int>> node_positions(n_nodes);
      for (unsigned int a = 0; a < n_nodes; ++a)
        for (const auto i : d.normals.dependencies(m.dofs[3 * a]))
          node_positions[a].push_back(position(i));
      if (!rows)
        return;
      const unsigned int n_direct = slave.size() + m.dofs.size();
      rows->assign(n_direct + 3 * n_nodes, {});
      for (unsigned int v = 0; v < n_direct; ++v)
        (*rows)[v].emplace_back(v, 1.);
      for (unsigned int a = 0; a < n_nodes; ++a)
        {
          const FullMatrix<double> &J = d.normals.jacobian(m.dofs[3 * a], *u);
          for (unsigned int c = 0; c < 3; ++c)
            for (unsigned int j = 0; j < J.n(); ++j)
              if (J(c, j) != 0.)
                (*rows)[n_direct + 3 * a + c].emplace_back(node_positions[a][j],
                                                           J(c, j));
        }
    }

    std::vector<std::pair<BoundingBox<3>, unsigned int>>
    ContactSystem::master_boxes(const ContactPair &p, const LA::Vector *u) const
    {
      std::vector<std::pair<BoundingBox<3>, unsigned int>> boxes;
      for (unsigned int m = 0; m < masters.size(); ++m)
        {
          if (!p.regions.empty() && !p.regions.count(masters[m].material))
            continue;
          const auto box = bounding_box(patch(masters[m], p.outside, u));
          boxes.emplace_back(
            BoundingBox<3>({Point<3>(box.first), Point<3>(box.second)}), m);
        }
      return boxes;
    }

    bool
    ContactSystem::update_candidates(const LA::Vector *u)
    {
      if (empty())
        return false;
      bool grown = false;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          PairData          &d = pairs[k];
          const ContactPair &p = parameters.all()[k];
          // An R-tree of the current boxes of the master cells of this pair
          // (O(log M) per cable cell instead of a scan of all M boxes).
          const auto   tree  = pack_rtree(master_boxes(p, u));
          const double reach = d.radius + d.search;
          for (unsigned int c = 0; c < d.cell_dofs.size(); ++c)
            {
              std::array<Tensor<1, 3>, 2> x = d.cell_reference[c];
              if (u)
                for (unsigned int v = 0; v < 2; ++v)
                  for (unsigned int i = 0; i < 3; ++i)
                    x[v][i] += (*u)[d.cell_dofs[c][3 * v + i]];
              // In master order, whatever the tree's: the projections and
              // their sums do not depend on the search structure.
              const auto found = masters_near(tree, x[0], x[1], reach);
              for (const unsigned int m : found)
                if (coupled.insert(std::array<unsigned int, 3>{{k, c, m}})
                      .second)
                  grown = true;
              d.candidates[c] = found;
            }
        }
      return Utilities::MPI::max(grown ? 1 : 0, comm) > 0;
    }

    void
    ContactSystem::add_sparsity(
      DynamicSparsityPattern          &dsp,
      const AffineConstraints<double> &constraints) const
    {
      std::vector<types::global_dof_index> dofs;
      for (const auto &[k, c, m] : coupled)
        {
          variable_map(pairs[k], c, masters[m], nullptr, dofs, nullptr);
          constraints.add_entries_local_to_global(dofs, dsp, false);
        }
    }

    /// The local terms of one point, added through the constraints, and
    /// with a smoothed master normal chained from the variables to the
    /// dofs: the force P^T r and its Jacobian P^T A P (r has no rows for
    /// the nodal normals: they are not unknowns, only their columns chain
    /// to the node positions they come from).
    class ContactSystem::Distributor
    {
    public:
      Distributor(const AffineConstraints<double> &constraints,
                  LA::SparseMatrix                *tangent,
                  LA::Vector                      *residual,
                  const bool                       smoothed)
        : constraints(constraints)
        , tangent(tangent)
        , residual(residual)
        , smoothed(smoothed)
      {
      }

      const AffineConstraints<double>                      &constraints;
      LA::SparseMatrix                                     *tangent;
      LA::Vector                                           *residual;
      bool                                                  smoothed;
      std::vector<types::global_dof_index>                  dofs;
      std::vector<std::vector<std::pair<unsigned, double>>> rows;
      Vector<double>                                        chained;
      FullMatrix<double>                                    chained_matrix;

      void
      add(const Vector<double> &g, const FullMatrix<double> &A)
      {
        if (!smoothed)
          {
            LA::distribute(constraints, A, g, dofs, tangent, residual);
            return;
          }
        const unsigned int n_t = dofs.size(), n_v = rows.size();
        chained.reinit(n_t);
        for (unsigned int v = 0; v < n_v; ++v)
          for (const auto &[j, w] : rows[v])
            chained(j) += w * g(v);
        if (tangent)
          {
            // P^T A P with the sparse rows of P.
            FullMatrix<double> AP(n_v, n_t);
            for (unsigned int i = 0; i < n_v; ++i)
              for (unsigned int v = 0; v < n_v; ++v)
                if (const double a = A(i, v); a != 0.)
                  for (const auto &[j, w] : rows[v])
                    AP(i, j) += a * w;
            chained_matrix.reinit(n_t, n_t);
            for (unsigned int i = 0; i < n_v; ++i)
              for (const auto &[j1, w] : rows[i])
                for (unsigned int j2 = 0; j2 < n_t; ++j2)
                  chained_matrix(j1, j2) += w * AP(i, j2);
          }
        LA::distribute(
          constraints, chained_matrix, chained, dofs, tangent, residual);
      }
    };

    /// The current patches (and boxes) of a pair's masters, made when
    /// first used.
    class ContactSystem::Patches
    {
    public:
      Patches(const ContactSystem &system,
              const ContactPair   &p,
              const PairData      &d,
              const LA::Vector    &u)
        : system(system)
        , p(p)
        , d(d)
        , u(u)
        , patches(system.masters.size())
        , made(system.masters.size(), false)
        , boxes(system.masters.size())
      {
      }
      const MasterPatch &
      operator()(const unsigned int m)
      {
        if (!made[m])
          {
            patches[m] = system.patch(system.masters[m],
                                      p.outside,
                                      &u,
                                      d.smoothed ? &d.normals : nullptr);
            boxes[m]   = bounding_box(patches[m]);
            made[m]    = true;
          }
        return patches[m];
      }
      /// The box of master @p m (made).
      const std::pair<Tensor<1, 3>, Tensor<1, 3>> &
      box(const unsigned int m) const
      {
        return boxes[m];
      }

    private:
      const ContactSystem                               &system;
      const ContactPair                                 &p;
      const PairData                                    &d;
      const LA::Vector                                  &u;
      std::vector<MasterPatch>                           patches;
      std::vector<bool>                                  made;
      std::vector<std::pair<Tensor<1, 3>, Tensor<1, 3>>> boxes;
    };

    ContactRecord
    ContactSystem::new_record() const
    {
      ContactRecord r;
      for (const auto &d : pairs)
        {
          ContactRecord::Pair rp;
          const unsigned int  n = d.points.size();
          rp.line_load.assign(n, 0.);
          rp.pending_anchor = d.anchor;
          rp.pending_xi     = d.anchor_xi;
          rp.seen_master.assign(n, -1);
          rp.seen_xi.assign(n, Point<2>());
          rp.seen_offset.assign(n, Tensor<1, 3>());
          r.pairs.push_back(rp);
        }
      r.reports.assign(pairs.size(), ContactReport());
      r.master_force.assign(masters.size(), 0.);
      return r;
    }

    std::vector<SlaveSection>
    ContactSystem::current_sections(const PairData   &d,
                                    const LA::Vector &u) const
    {
      // Solid beam: the current section at the element's nodes (the
      // contact's layout of a cell: 6 mid-line dofs, then a1, a2 of
      // vertex 0 and of vertex 1).
      std::vector<SlaveSection> sections(d.beam ? d.cell_dofs.size() : 0);
      for (unsigned int c = 0; c < sections.size(); ++c)
        for (unsigned int v = 0; v < 2; ++v)
          for (unsigned int i = 0; i < 3; ++i)
            {
              const unsigned int j1 = 6 + 6 * v + i, j2 = j1 + 3;
              sections[c].a1[v][i] =
                d.cell_reference_values[c][j1] + u[d.cell_dofs[c][j1]];
              sections[c].a2[v][i] =
                d.cell_reference_values[c][j2] + u[d.cell_dofs[c][j2]];
            }
      return sections;
    }

    ContactSystem::Nearest
    ContactSystem::nearest(const PairData &d,
                           const Slave    &slave,
                           Patches        &patches) const
    {
      // Nearest projection inside a candidate cell, per point, here; then
      // the nearest over all ranks wins (lowest rank on a tie).
      const unsigned int n_points = d.points.size();
      const int          rank     = Utilities::MPI::this_mpi_process(comm);
      Nearest            near;
      near.local.assign(n_points, {std::numeric_limits<double>::max(), rank});
      near.master.assign(n_points, 0);
      near.projection.resize(n_points);
      for (unsigned int q = 0; q < n_points; ++q)
        {
          const CablePoint  &pt = d.points[q];
          const Tensor<1, 3> x  = (1. - pt.eta) * slave[pt.cable_cell][0]
                                 + pt.eta * slave[pt.cable_cell][1];
          for (const unsigned int m : d.candidates[pt.cable_cell])
            {
              const MasterPatch &patch_m = patches(m);
              // A point farther than R from the cell's box (plus the bulge
              // of a curved cell, bounded by its box size) cannot touch it.
              const auto &box      = patches.box(m);
              bool        near_box = true;
              for (unsigned int i = 0; i < 3 && near_box; ++i)
                {
                  const double margin =
                    d.radius + 0.25 * (box.second[i] - box.first[i]);
                  near_box = x[i] >= box.first[i] - margin
                             && x[i] <= box.second[i] + margin;
                }
              if (!near_box)
                continue;
              const Projection proj = project(patch_m, x, d.radius);
              if (proj.inside && proj.distance < near.local[q].distance)
                {
                  near.local[q].distance = proj.distance;
                  near.master[q]         = m;
                  near.projection[q]     = proj;
                }
            }
        }
      near.global = near.local;
      MPI_Allreduce(near.local.data(),
                    near.global.data(),
                    n_points,
                    MPI_DOUBLE_INT,
                    MPI_MINLOC,
                    comm);
      for (unsigned int q = 0; q < n_points; ++q)
        near.held.push_back(near.global[q].rank == rank
                            && near.local[q].distance
                                 != std::numeric_limits<double>::max());
      return near;
    }

    void
    ContactSystem::assemble(const LA::Vector                &u,
                            const AffineConstraints<double> &constraints,
                            LA::SparseMatrix                *tangent,
                            LA::Vector                      *residual,
                            ContactRecord                   &record) const
    {
      if (record.pairs.size() != pairs.size())
        record = new_record();
      std::fill(record.master_force.begin(), record.master_force.end(), 0.);
      for (unsigned int k = 0; k < pairs.size(); ++k)
        assemble_pair(k, u, constraints, tangent, residual, record);
      if (residual)
        residual->compress(VectorOperation::add);
      if (tangent)
        tangent->compress(VectorOperation::add);
    }

    void
    ContactSystem::assemble_pair(const unsigned int               k,
                                 const LA::Vector                &u,
                                 const AffineConstraints<double> &constraints,
                                 LA::SparseMatrix                *tangent,
                                 LA::Vector                      *residual,
                                 ContactRecord                   &record) const
    {
      const PairData    &d        = pairs[k];
      const ContactPair &p        = parameters.all()[k];
      const unsigned int n_points = d.points.size();
      d.normals.clear_cache();
      const Slave          slave    = current_slave(d, u);
      const auto           sections = current_sections(d, u);
      Patches              patches(*this, p, d, u);
      const Nearest        near = nearest(d, slave, patches);
      ContactReport        report;
      ContactRecord::Pair &rec = record.pairs[k];
      report.points            = n_points;
      std::fill(rec.line_load.begin(), rec.line_load.end(), 0.);
      std::fill(rec.pending_anchor.begin(), rec.pending_anchor.end(), -1);
      std::fill(rec.seen_master.begin(), rec.seen_master.end(), -1);
      // The gaps of the points assembled here, and those that penetrate.
      std::vector<double>       gaps(n_points, 0.);
      std::vector<unsigned int> penetrating;
      for (unsigned int q = 0; q < n_points; ++q)
        {
          if (!near.held[q])
            continue;
          const CablePoint &pt   = d.points[q];
          const Projection &proj = near.projection[q];
          gaps[q]                = proj.gap;
          if (d.beam)
            {
              // The section's extent along n instead of R.
              const SlaveSection &sc = sections[pt.cable_cell];
              const Tensor<1, 3>  a1 =
                (1. - pt.eta) * sc.a1[0] + pt.eta * sc.a1[1];
              const Tensor<1, 3> a2 =
                (1. - pt.eta) * sc.a2[0] + pt.eta * sc.a2[1];
              gaps[q] +=
                d.radius - std::hypot(a1 * proj.normal, a2 * proj.normal);
            }
          if (!(gaps[q] >= 0.))
            penetrating.push_back(q);
        }
      // The penalty terms of the penetrating points, on the task threads:
      // each point's automatic differentiation is independent of the
      // others' (the patches in use were all made by the search above).
      // They are added to the system in point order below, so the sums do
      // not depend on the thread count.
      std::vector<Vector<double>>     gradients(n_points);
      std::vector<FullMatrix<double>> hessians(n_points);
      parallel::apply_to_subranges(
        0u,
        static_cast<unsigned int>(penetrating.size()),
        [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int i = begin; i < end; ++i)
            {
              const unsigned int q  = penetrating[i];
              const CablePoint  &pt = d.points[q];
              penalty_terms(patches(near.master[q]),
                            slave[pt.cable_cell],
                            pt.eta,
                            d.radius,
                            p.penalty,
                            pt.weight,
                            near.projection[q].xi,
                            &gradients[q],
                            tangent ? &hessians[q] : nullptr,
                            d.beam ? &sections[pt.cable_cell] : nullptr);
            }
        },
        8);
      Distributor distributor(constraints, tangent, residual, d.smoothed);
      for (unsigned int q = 0; q < n_points; ++q)
        if (near.held[q])
          add_point(k,
                    q,
                    gaps[q],
                    near,
                    slave,
                    sections,
                    patches,
                    gradients[q],
                    hessians[q],
                    u,
                    distributor,
                    report,
                    record);
      // Every rank reports the same numbers.
      report.active_points = Utilities::MPI::sum(report.active_points, comm);
      report.total_force   = Utilities::MPI::sum(report.total_force, comm);
      for (unsigned int i = 0; i < 3; ++i)
        report.force[i] = Utilities::MPI::sum(report.force[i], comm);
      report.max_penetration =
        Utilities::MPI::max(report.max_penetration, comm);
      report.slip_points    = Utilities::MPI::sum(report.slip_points, comm);
      report.friction_force = Utilities::MPI::sum(report.friction_force, comm);
      Utilities::MPI::sum(rec.line_load, comm, rec.line_load);
      record.reports[k] = report;
    }

    void
    ContactSystem::add_point(const unsigned int               k,
                             const unsigned int               q,
                             const double                     gap,
                             const Nearest                   &near,
                             const Slave                     &slave,
                             const std::vector<SlaveSection> &sections,
                             Patches                         &patches,
                             const Vector<double>            &gradient,
                             const FullMatrix<double>        &hessian,
                             const LA::Vector                &u,
                             Distributor                     &distributor,
                             ContactReport                   &report,
                             ContactRecord                   &record) const
    {
      const PairData      &d    = pairs[k];
      const ContactPair   &p    = parameters.all()[k];
      ContactRecord::Pair &rec  = record.pairs[k];
      const CablePoint    &pt   = d.points[q];
      const unsigned int   m    = near.master[q];
      const Projection    &proj = near.projection[q];
      if (gap < d.search)
        {
          // Near: the reference of the next step's check.
          rec.seen_master[q] = m;
          rec.seen_xi[q]     = proj.xi;
          rec.seen_offset[q] = (1. - pt.eta) * slave[pt.cable_cell][0]
                               + pt.eta * slave[pt.cable_cell][1]
                               - position(patches(m), proj.xi);
        }
      if (gap >= 0.)
        return;
      variable_map(d,
                   pt.cable_cell,
                   masters[m],
                   &u,
                   distributor.dofs,
                   d.smoothed ? &distributor.rows : nullptr);
      distributor.add(gradient, hessian);
      const double N   = -p.penalty * gap; // >= 0
      rec.line_load[q] = N;
      ++report.active_points;
      report.total_force += N * pt.weight;
      // The force on the cable, -(r_0 + r_1) = N w n.
      for (unsigned int i = 0; i < 3; ++i)
        report.force[i] -= gradient(i) + gradient(3 + i);
      report.max_penetration = std::max(report.max_penetration, -gap);
      record.master_force[m] += N * pt.weight;
      if (p.friction > 0.)
        add_friction(
          k, q, near, slave, sections, patches, distributor, report, record);
    }

    void
    ContactSystem::add_friction(const unsigned int               k,
                                const unsigned int               q,
                                const Nearest                   &near,
                                const Slave                     &slave,
                                const std::vector<SlaveSection> &sections,
                                Patches                         &patches,
                                Distributor                     &distributor,
                                ContactReport                   &report,
                                ContactRecord                   &record) const
    {
      const PairData      &d    = pairs[k];
      const ContactPair   &p    = parameters.all()[k];
      ContactRecord::Pair &rec  = record.pairs[k];
      const CablePoint    &pt   = d.points[q];
      const unsigned int   m    = near.master[q];
      const Projection    &proj = near.projection[q];
      if (d.anchor[q] < 0)
        {
          // First contact: stick where it touches.
          rec.pending_anchor[q] = m;
          rec.pending_xi[q]     = proj.xi;
          return;
        }
      // The anchor, expressed on the current cell m.
      Point<2> xi_a = d.anchor_xi[q];
      if (static_cast<unsigned int>(d.anchor[q]) != m)
        {
          const Tensor<1, 3> ya = position(patches(d.anchor[q]), xi_a);
          xi_a                  = project(patches(m), ya, 0., proj.xi).xi;
        }
      Vector<double>      f_residual;
      FullMatrix<double>  f_jacobian;
      const FrictionState fs =
        friction_terms(patches(m),
                       xi_a,
                       slave[pt.cable_cell],
                       pt.eta,
                       d.radius,
                       p.penalty,
                       p.tangential_penalty,
                       p.friction,
                       pt.weight,
                       proj.xi,
                       &f_residual,
                       distributor.tangent ? &f_jacobian : nullptr,
                       d.beam ? &sections[pt.cable_cell] : nullptr);
      distributor.add(f_residual, f_jacobian);
      report.friction_force += fs.traction.norm() * pt.weight;
      // The resultant on the cable takes the friction too.
      for (unsigned int i = 0; i < 3; ++i)
        report.force[i] += fs.traction[i] * pt.weight;
      rec.pending_anchor[q] = m;
      rec.pending_xi[q]     = xi_a;
      if (!fs.slip)
        return;
      ++report.slip_points;
      // Where the slip drags the anchor: its projection on this cable
      // element's candidates.
      rec.pending_anchor[q] = -1;
      double best_d         = std::numeric_limits<double>::max();
      for (const unsigned int c : d.candidates[pt.cable_cell])
        {
          const Projection a = project(patches(c), fs.anchor_target, 0.);
          if (a.inside && a.distance < best_d)
            {
              best_d                = a.distance;
              rec.pending_anchor[q] = c;
              rec.pending_xi[q]     = a.xi;
            }
        }
      if (rec.pending_anchor[q] < 0)
        {
          rec.pending_anchor[q] = m;
          rec.pending_xi[q]     = xi_a;
        }
    }

    void
    ContactSystem::record_state(const LA::Vector                &u,
                                const AffineConstraints<double> &constraints)
    {
      assemble(u, constraints, nullptr, nullptr, recorded);
    }

    bool
    ContactSystem::set_time(const double t)
    {
      bool turned = false;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          const bool smoothed = smoothed_at(parameters.all()[k], t);
          turned              = turned || (smoothed && !pairs[k].smoothed);
          pairs[k].smoothed   = smoothed;
        }
      return turned;
    }

    bool
    ContactSystem::smoothed() const
    {
      for (const auto &d : pairs)
        if (d.smoothed)
          return true;
      return false;
    }

    void
    ContactSystem::commit_step()
    {
      committed_reports = recorded.reports;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          PairData                  &d   = pairs[k];
          const ContactRecord::Pair &rec = recorded.pairs[k];
          d.anchor                       = rec.pending_anchor;
          d.anchor_xi                    = rec.pending_xi;
          d.start_master                 = rec.seen_master;
          d.start_xi                     = rec.seen_xi;
          d.start_offset                 = rec.seen_offset;
        }
    }

    std::vector<std::array<Tensor<1, 3>, 2>>
    ContactSystem::current_slave(const PairData &d, const LA::Vector &u) const
    {
      std::vector<std::array<Tensor<1, 3>, 2>> slave(d.cell_dofs.size());
      for (unsigned int c = 0; c < d.cell_dofs.size(); ++c)
        for (unsigned int v = 0; v < 2; ++v)
          for (unsigned int i = 0; i < 3; ++i)
            slave[c][v][i] =
              d.cell_reference[c][v][i] + u[d.cell_dofs[c][3 * v + i]];
      return slave;
    }

    std::string
    ContactSystem::check_step(const LA::Vector &u) const
    {
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          const PairData    &d     = pairs[k];
          const ContactPair &p     = parameters.all()[k];
          const auto         slave = current_slave(d, u);
          const auto         point = [&](const CablePoint &pt) {
            return (1. - pt.eta) * slave[pt.cable_cell][0]
                   + pt.eta * slave[pt.cable_cell][1];
          };
          std::map<unsigned int, MasterPatch> patches;
          const auto current = [&](const unsigned int m) -> const auto &
          {
            auto it = patches.find(m);
            if (it == patches.end())
              it = patches.emplace(m, patch(masters[m], p.outside, &u)).first;
            return it->second;
          };
          // 1. Motion relative to the master of the points near it at the
          // step's start.
          double moved = 0.;
          if (p.max_motion > 0.)
            for (unsigned int q = 0; q < d.start_master.size(); ++q)
              if (d.start_master[q] >= 0)
                {
                  const Tensor<1, 3> offset =
                    point(d.points[q])
                    - position(current(d.start_master[q]), d.start_xi[q]);
                  moved = std::max(moved, (offset - d.start_offset[q]).norm());
                }
          // 2. Penetration of cells outside the step's candidates.
          std::vector<std::vector<unsigned int>> cell_points(
            d.cell_dofs.size());
          for (unsigned int q = 0; q < d.points.size(); ++q)
            cell_points[d.points[q].cable_cell].push_back(q);
          unsigned int missed = 0;
          const double reach  = d.radius + d.search;
          const auto   tree   = pack_rtree(master_boxes(p, &u));
          for (unsigned int c = 0; c < d.cell_dofs.size(); ++c)
            {
              const auto &cand = d.candidates[c];
              for (const unsigned int m :
                   masters_near(tree, slave[c][0], slave[c][1], reach))
                {
                  if (std::find(cand.begin(), cand.end(), m) != cand.end())
                    continue;
                  for (const unsigned int q : cell_points[c])
                    {
                      const Projection proj =
                        project(current(m), point(d.points[q]), d.radius);
                      if (proj.inside && proj.gap < 0.)
                        ++missed;
                    }
                }
            }
          moved  = Utilities::MPI::max(moved, comm);
          missed = Utilities::MPI::sum(missed, comm);
          std::ostringstream why;
          if (p.max_motion > 0. && moved > p.max_motion * d.search)
            why << p.path << ": a cable point moved " << moved
                << " m relative to the membrane in the step, more than "
                << p.max_motion << " of the search distance " << d.search
                << " m (Maximum motion per step)";
          else if (missed > 0)
            why << p.path << ": " << missed
                << " cable point(s) penetrate membrane cells that were not "
                   "contact candidates in the step";
          if (!why.str().empty())
            return why.str();
        }
      return "";
    }

    void
    ContactSystem::save_checkpoint(Checkpoint &checkpoint) const
    {
      // Per pair and point: the anchor's cell id (empty: none) and its
      // convective coordinates, from the rank that holds it.
      using Anchor = std::pair<std::string, std::vector<double>>;
      std::vector<std::vector<Anchor>> anchors(pairs.size());
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          const PairData     &d = pairs[k];
          std::vector<Anchor> local(d.anchor.size());
          for (unsigned int q = 0; q < d.anchor.size(); ++q)
            if (d.anchor[q] >= 0)
              local[q] = {masters[d.anchor[q]].cell->id().to_string(),
                          {d.anchor_xi[q][0], d.anchor_xi[q][1]}};
          const auto all = Utilities::MPI::gather(comm, local, 0);
          anchors[k]     = local;
          for (const auto &part : all)
            for (unsigned int q = 0; q < part.size(); ++q)
              if (!part[q].first.empty())
                anchors[k][q] = part[q];
        }
      checkpoint.put("contact/anchors", anchors);
    }

    void
    ContactSystem::load_checkpoint(const Checkpoint &checkpoint)
    {
      using Anchor = std::pair<std::string, std::vector<double>>;
      const auto saved =
        checkpoint.get<std::vector<std::vector<Anchor>>>("contact/anchors");
      check_input(saved.size() == pairs.size(),
                  "--restart " + checkpoint.directory(),
                  "the checkpoint has another number of contact pairs");
      std::map<std::string, int> local;
      for (unsigned int m = 0; m < masters.size(); ++m)
        local[masters[m].cell->id().to_string()] = m;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          PairData &d = pairs[k];
          check_input(saved[k].size() == d.anchor.size(),
                      "--restart " + checkpoint.directory(),
                      "the checkpoint has another number of contact points");
          for (unsigned int q = 0; q < d.anchor.size(); ++q)
            {
              const auto it = saved[k][q].first.empty()
                                ? local.end()
                                : local.find(saved[k][q].first);
              d.anchor[q]   = it == local.end() ? -1 : it->second;
              if (it != local.end())
                d.anchor_xi[q] =
                  Point<2>(saved[k][q].second[0], saved[k][q].second[1]);
            }
        }
      // What a commit keeps until the state is recorded again.
      recorded = new_record();
    }

    Vector<double>
    ContactSystem::cable_line_load(const unsigned int cable) const
    {
      Vector<double> load;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        if (parameters.all()[k].cable == cable)
          {
            const PairData &d = pairs[k];
            if (load.size() == 0)
              load.reinit(d.cell_dofs.size());
            std::vector<double> weight(d.cell_dofs.size(), 0.);
            Vector<double>      sum(d.cell_dofs.size());
            for (unsigned int q = 0; q < d.points.size(); ++q)
              {
                sum[d.points[q].cable_cell] +=
                  recorded.pairs[k].line_load[q] * d.points[q].weight;
                weight[d.points[q].cable_cell] += d.points[q].weight;
              }
            for (unsigned int c = 0; c < load.size(); ++c)
              load[c] += weight[c] > 0. ? sum[c] / weight[c] : 0.;
          }
      return load;
    }

    Vector<float>
    ContactSystem::membrane_pressure(const unsigned int n_active_cells) const
    {
      Vector<float> pressure(n_active_cells);
      for (unsigned int m = 0; m < masters.size(); ++m)
        pressure[masters[m].cell->active_cell_index()] =
          recorded.master_force[m] / masters[m].area;
      return pressure;
    }
  } // namespace contact
} // namespace pneuma
