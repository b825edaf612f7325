#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/numerics/rtree.h>

#include <pneuma/contact/derived_penalty.h>
#include <pneuma/contact/surfaces/cell_search.h>
#include <pneuma/contact/surfaces/surface_contact.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      using Box = std::pair<Tensor<1, 3>, Tensor<1, 3>>;

      /// Is @p x within @p margin of @p box?
      bool
      near_box(const Tensor<1, 3> &x, const Box &box, const double margin)
      {
        for (unsigned int i = 0; i < 3; ++i)
          if (x[i] < box.first[i] - margin || x[i] > box.second[i] + margin)
            return false;
        return true;
      }
    } // namespace

    SurfaceContact::SurfaceContact(const std::vector<SurfacePair>  &parameters,
                                   const membrane::MaterialRegions &materials)
      : parameters(parameters)
      , materials(materials)
    {
    }

    void
    SurfaceContact::setup(const Mapping<2, 3>    &mapping,
                          const DoFHandler<2, 3> &dof_handler,
                          const MPI_Comm          comm_)
    {
      comm   = comm_;
      degree = dof_handler.get_fe().base_element(0).degree;
      gather_cells(mapping, dof_handler);
      const QGauss<2> gauss(degree + 1);
      points.clear();
      shape.clear();
      unit_weights.clear();
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          points.push_back(gauss.point(q));
          shape.push_back(shape_values(degree, gauss.point(q)));
          unit_weights.push_back(gauss.weight(q));
        }
      make_sides();
      find_seams();
      coupled.clear();
    }

    void
    SurfaceContact::gather_cells(const Mapping<2, 3>    &mapping,
                                 const DoFHandler<2, 3> &dof_handler)
    {
      const auto        &fe     = dof_handler.get_fe();
      const unsigned int n      = degree + 1;
      const auto         in_any = [&](const types::material_id id) {
        for (const auto &p : parameters)
          if (p.on_first(id) || p.on_second(id))
            return true;
        return false;
      };
      // The owned cells of the pairs' regions, packed for the exchange:
      // per cell its dofs in lattice order, and its material, active index
      // and reference nodes.
      std::vector<types::global_dof_index> packed_dofs,
        cell_dofs(fe.n_dofs_per_cell());
      std::vector<double> packed_values;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && in_any(cell->material_id()))
          {
            cell->get_dof_indices(cell_dofs);
            std::vector<types::global_dof_index> lattice(3 * n * n);
            for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
              {
                const auto [c, base] = fe.system_to_component_index(k);
                const Point<2> xi = fe.base_element(0).unit_support_point(base);
                lattice[3
                          * (std::lround(xi[0] * degree)
                             + n * std::lround(xi[1] * degree))
                        + c]      = cell_dofs[k];
              }
            packed_dofs.insert(packed_dofs.end(),
                               lattice.begin(),
                               lattice.end());
            packed_values.push_back(cell->material_id());
            packed_values.push_back(cell->active_cell_index());
            for (unsigned int j = 0; j < n; ++j)
              for (unsigned int i = 0; i < n; ++i)
                {
                  const Point<3> y = mapping.transform_unit_to_real_cell(
                    cell, Point<2>(double(i) / degree, double(j) / degree));
                  for (unsigned int c = 0; c < 3; ++c)
                    packed_values.push_back(y[c]);
                }
          }
      const auto all_dofs   = Utilities::MPI::all_gather(comm, packed_dofs);
      const auto all_values = Utilities::MPI::all_gather(comm, packed_values);

      // Unpack, in the order of the reference centroids (the same for any
      // partition).
      const QGauss<2>                                     gauss(degree + 1);
      std::vector<std::pair<std::array<double, 4>, Cell>> sorted;
      for (unsigned int r = 0; r < all_dofs.size(); ++r)
        for (unsigned int c = 0; 3 * n * n * (c + 1) <= all_dofs[r].size(); ++c)
          {
            Cell          cell;
            const double *v = &all_values[r][c * (2 + 3 * n * n)];
            cell.material   = static_cast<types::material_id>(v[0]);
            cell.owner      = r;
            cell.dofs.assign(all_dofs[r].begin() + 3 * n * n * c,
                             all_dofs[r].begin() + 3 * n * n * (c + 1));
            std::array<double, 4> key{{0., 0., 0., v[1]}};
            cell.reference.resize(n * n);
            for (unsigned int a = 0; a < n * n; ++a)
              for (unsigned int d = 0; d < 3; ++d)
                {
                  cell.reference[a][d] = v[2 + 3 * a + d];
                  key[d] += v[2 + 3 * a + d] / (n * n);
                }
            const MasterPatch patch{degree, cell.reference, 1., {}};
            for (unsigned int q = 0; q < gauss.size(); ++q)
              {
                cell.weights.push_back(gauss.weight(q)
                                       * area_element(patch, gauss.point(q)));
                cell.area += cell.weights.back();
              }
            cell.half_thickness = 0.5 * materials[cell.material].thickness;
            sorted.emplace_back(key, cell);
          }
      std::stable_sort(sorted.begin(),
                       sorted.end(),
                       [](const auto &a, const auto &b) {
                         for (unsigned int d = 0; d < 3; ++d)
                           if (a.first[d] != b.first[d])
                             return a.first[d] < b.first[d];
                         return false;
                       });
      const int rank = Utilities::MPI::this_mpi_process(comm);
      cells.clear();
      cell_of_active.assign(dof_handler.get_triangulation().n_active_cells(),
                            -1);
      thickest = 0.;
      for (unsigned int i = 0; i < sorted.size(); ++i)
        {
          cells.push_back(sorted[i].second);
          if (cells.back().owner == rank)
            cell_of_active[static_cast<unsigned int>(sorted[i].first[3])] = i;
          thickest = std::max(thickest, 2. * cells.back().half_thickness);
        }
    }

    void
    SurfaceContact::make_sides()
    {
      // The sides of every pair; the default search distance starts at a
      // quarter of the largest cell size (box diagonal) of its regions.
      const int rank = Utilities::MPI::this_mpi_process(comm);
      pairs.assign(parameters.size(), PairData());
      for (unsigned int k = 0; k < parameters.size(); ++k)
        {
          const SurfacePair &p = parameters[k];
          PairData          &d = pairs[k];
          d.sides.resize(p.self() ? 1 : 2);
          double h = 0.;
          for (unsigned int s = 0; s < d.sides.size(); ++s)
            {
              Side &side = d.sides[s];
              side.opposite.assign(cells.size(), 0);
              for (unsigned int c = 0; c < cells.size(); ++c)
                {
                  const types::material_id id    = cells[c].material;
                  const bool               first = p.on_first(id);
                  const bool mine  = s == 0 ? first : p.on_second(id);
                  const bool other = p.self() ? first
                                     : s == 0 ? p.on_second(id)
                                              : first;
                  side.opposite[c] = other ? 1 : 0;
                  if (mine && cells[c].owner == rank)
                    side.slaves.push_back(c);
                  if (mine || other)
                    {
                      const Box box = bounding_box(
                        MasterPatch{degree, cells[c].reference, 1., {}});
                      h = std::max(h, (box.second - box.first).norm());
                    }
                }
              side.candidates.assign(side.slaves.size(), {});
              side.orientation.assign(side.slaves.size(), {});
            }
          d.largest = h;
          d.search  = p.search_distance > 0. ? p.search_distance : 0.25 * h;
        }
    }

    IndexSet
    SurfaceContact::relevant_dofs(const types::global_dof_index size) const
    {
      std::vector<types::global_dof_index> all;
      for (const auto &c : cells)
        all.insert(all.end(), c.dofs.begin(), c.dofs.end());
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());
      IndexSet dofs(size);
      dofs.add_indices(all.begin(), all.end());
      return dofs;
    }

    std::vector<types::material_id>
    SurfaceContact::missing_regions(const unsigned int k) const
    {
      std::set<types::material_id> present;
      for (const auto &c : cells)
        present.insert(c.material);
      std::vector<types::material_id> missing;
      for (const auto &set : {parameters[k].first, parameters[k].second})
        for (const auto id : set)
          if (!present.count(id))
            missing.push_back(id);
      return missing;
    }

    std::vector<MasterPatch>
    SurfaceContact::current_patches(const LA::Vector *u) const
    {
      std::vector<MasterPatch> patches(cells.size());
      parallel::apply_to_subranges(
        0u,
        static_cast<unsigned int>(cells.size()),
        [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int c = begin; c < end; ++c)
            {
              patches[c].degree = degree;
              patches[c].nodes  = cells[c].reference;
              if (u)
                for (unsigned int a = 0; a < patches[c].nodes.size(); ++a)
                  for (unsigned int i = 0; i < 3; ++i)
                    patches[c].nodes[a][i] += (*u)[cells[c].dofs[3 * a + i]];
            }
        },
        256);
      return patches;
    }

    bool
    SurfaceContact::touching(const unsigned int a, const unsigned int b) const
    {
      // A shared corner node (the same dofs, or the same place: regions
      // meshed apart and tied).
      const unsigned int                n = degree + 1;
      const std::array<unsigned int, 4> corners{
        {0, n - 1, n * (n - 1), n * n - 1}};
      const double tolerance =
        1e-8 * std::sqrt(std::max(cells[a].area, cells[b].area));
      for (const unsigned int i : corners)
        for (const unsigned int j : corners)
          if (cells[a].dofs[3 * i] == cells[b].dofs[3 * j]
              || (cells[a].reference[i] - cells[b].reference[j]).norm()
                   <= tolerance)
            return true;
      return false;
    }

    double
    SurfaceContact::offset(const unsigned int a, const unsigned int b) const
    {
      return cells[a].half_thickness + cells[b].half_thickness;
    }

    double
    SurfaceContact::cell_penalty(const unsigned int k,
                                 const unsigned int cell) const
    {
      const SurfacePair &p = parameters[k];
      if (p.penalty > 0.)
        return p.penalty;
      return derived_penalty(materials[cells[cell].material],
                             cells[cell].area,
                             degree,
                             p.penalty_factor);
    }

    std::pair<double, double>
    SurfaceContact::penalty_range(const unsigned int k) const
    {
      double lo = std::numeric_limits<double>::max(), hi = 0.;
      for (const auto &side : pairs[k].sides)
        for (const unsigned int c : side.slaves)
          {
            lo = std::min(lo, cell_penalty(k, c));
            hi = std::max(hi, cell_penalty(k, c));
          }
      return {Utilities::MPI::min(lo, comm), Utilities::MPI::max(hi, comm)};
    }

    void
    SurfaceContact::commit(const LA::Vector *u)
    {
      auto patches = current_patches(u);
      if (converged.size() == patches.size())
        for (unsigned int k = 0; k < pairs.size(); ++k)
          {
            // The default search distance follows the motion: four times
            // the largest node motion of the pair's cells in the step just
            // accepted, at least twice the largest thickness and at most
            // the largest cell size (a step that moves farther is cut
            // back by check()).
            if (parameters[k].search_distance > 0.)
              continue;
            double motion = 0.;
            for (unsigned int c = 0; c < cells.size(); ++c)
              if (pairs[k].sides[0].opposite[c]
                  || pairs[k].sides.back().opposite[c])
                for (unsigned int a = 0; a < patches[c].nodes.size(); ++a)
                  motion = std::max(
                    motion,
                    (patches[c].nodes[a] - converged[c].nodes[a]).norm());
            if (motion > 0.)
              pairs[k].search = std::min(pairs[k].largest,
                                         std::max(2. * thickest, 4. * motion));
          }
      converged = std::move(patches);
    }

    bool
    SurfaceContact::update_candidates(const LA::Vector *u)
    {
      const auto       patches = current_patches(u);
      std::vector<Box> boxes(cells.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        boxes[c] = bounding_box(patches[c]);
      bool grown = false;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        for (Side &side : pairs[k].sides)
          {
            std::vector<std::pair<BoundingBox<3>, unsigned int>> opposite;
            for (unsigned int c = 0; c < cells.size(); ++c)
              if (side.opposite[c])
                opposite.emplace_back(enlarged(boxes[c], 0.), c);
            const auto   tree  = pack_rtree(opposite);
            const double reach = thickest + pairs[k].search;
            for (unsigned int i = 0; i < side.slaves.size(); ++i)
              {
                const unsigned int s     = side.slaves[i];
                auto              &found = side.candidates[i];
                found = cells_near(tree, enlarged(boxes[s], reach));
                found.erase(std::remove_if(found.begin(),
                                           found.end(),
                                           [&](const unsigned int m) {
                                             return m == s || touching(s, m)
                                                    || at_seam(s, m);
                                           }),
                            found.end());
                // The side of each point to each candidate: 0 (not yet
                // known); side_of() measures it when first needed.
                side.orientation[i].assign(points.size() * found.size(), 0);
                for (const unsigned int m : found)
                  if (coupled.insert({s, m}).second)
                    grown = true;
              }
          }
      return Utilities::MPI::max(grown ? 1 : 0, comm) > 0;
    }

    void
    SurfaceContact::add_sparsity(
      DynamicSparsityPattern          &dsp,
      const AffineConstraints<double> &constraints) const
    {
      std::vector<types::global_dof_index> dofs;
      for (const auto &[s, m] : coupled)
        {
          dofs = cells[s].dofs;
          dofs.insert(dofs.end(), cells[m].dofs.begin(), cells[m].dofs.end());
          constraints.add_entries_local_to_global(dofs, dsp, false);
        }
    }

    SurfaceContact::State
    SurfaceContact::current_state(const LA::Vector &u) const
    {
      State state;
      state.patches = current_patches(&u);
      state.boxes.resize(cells.size());
      state.motion.assign(cells.size(), 0.);
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          state.boxes[c] = bounding_box(state.patches[c]);
          for (unsigned int a = 0; a < state.patches[c].nodes.size(); ++a)
            state.motion[c] = std::max(
              state.motion[c],
              (state.patches[c].nodes[a] - converged[c].nodes[a]).norm());
        }
      return state;
    }

    signed char
    SurfaceContact::side_of(const Side        &side,
                            const unsigned int i,
                            const unsigned int q,
                            const unsigned int j) const
    {
      signed char &o = side.orientation[i][q * side.candidates[i].size() + j];
      if (o == 0)
        {
          // The sign of the signed distance in the last accepted state.
          const Tensor<1, 3> x = position(converged[side.slaves[i]], points[q]);
          o =
            project(converged[side.candidates[i][j]], x, 0.).gap < 0. ? -1 : 1;
        }
      return o;
    }

    int
    SurfaceContact::nearest(const Side         &side,
                            const unsigned int  i,
                            const Tensor<1, 3> &x,
                            const State        &state,
                            Projection         &projection) const
    {
      const unsigned int s        = side.slaves[i];
      int                best     = -1;
      double             distance = std::numeric_limits<double>::max();
      for (unsigned int j = 0; j < side.candidates[i].size(); ++j)
        {
          const unsigned int m   = side.candidates[i][j];
          const Box         &box = state.boxes[m];
          // A point farther from the cell's box than the offset, the bulge
          // of a curved cell (bounded by its size) and the two cells'
          // motion since the last accepted state cannot touch it: it was
          // outside then. (A Newton iterate that took a point deep behind
          // the cell is within that bound and pushed back.)
          double size = 0.;
          for (unsigned int d = 0; d < 3; ++d)
            size = std::max(size, box.second[d] - box.first[d]);
          if (!near_box(x,
                        box,
                        offset(s, m) + 0.25 * size + state.motion[s]
                          + state.motion[m]))
            continue;
          const Projection p = project(state.patches[m], x, 0.);
          if (p.inside && p.distance < distance)
            {
              distance   = p.distance;
              best       = j;
              projection = p;
            }
        }
      return best;
    }

    std::vector<SurfaceContact::Active>
    SurfaceContact::active_points(const State   &state,
                                  SurfaceRecord *record) const
    {
      std::vector<Active> active;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        for (unsigned int s = 0; s < pairs[k].sides.size(); ++s)
          {
            // The slaves on the task threads (each writes only its own
            // cell's gap and its own orientations), joined in slave order:
            // the list does not depend on the thread count.
            const Side                      &side = pairs[k].sides[s];
            std::vector<std::vector<Active>> of_slave(side.slaves.size());
            parallel::apply_to_subranges(
              0u,
              static_cast<unsigned int>(side.slaves.size()),
              [&](const unsigned int begin, const unsigned int end) {
                for (unsigned int i = begin; i < end; ++i)
                  of_slave[i] = slave_points(k, s, i, state, record);
              },
              16);
            for (auto &a : of_slave)
              active.insert(active.end(),
                            std::make_move_iterator(a.begin()),
                            std::make_move_iterator(a.end()));
            if (record)
              record->reports[k].points += side.slaves.size() * points.size();
          }
      return active;
    }

    std::vector<SurfaceContact::Active>
    SurfaceContact::slave_points(const unsigned int k,
                                 const unsigned int s,
                                 const unsigned int i,
                                 const State       &state,
                                 SurfaceRecord     *record) const
    {
      const Side         &side = pairs[k].sides[s];
      const unsigned int  c    = side.slaves[i];
      std::vector<Active> active;
      for (unsigned int q = 0; q < points.size(); ++q)
        {
          const Tensor<1, 3> x = position(state.patches[c], points[q]);
          Projection         p;
          const int          j = nearest(side, i, x, state, p);
          if (j < 0)
            continue;
          const unsigned int m   = side.candidates[i][j];
          const signed char  o   = side_of(side, i, q, j);
          const double       off = offset(c, m);
          const double       gap = o * p.gap - off;
          if (record)
            record->cell_gap[c] = std::min(record->cell_gap[c], gap);
          if (gap >= 0.)
            continue;
          Active a;
          a.pair        = k;
          a.side        = s;
          a.slave       = c;
          a.q           = q;
          a.master      = m;
          a.xi          = p.xi;
          a.gap         = gap;
          a.offset      = off;
          a.penalty     = cell_penalty(k, c);
          a.weight      = cells[c].weights[q];
          a.orientation = o;
          active.push_back(a);
        }
      return active;
    }

    void
    SurfaceContact::add_terms(const Active                    &a,
                              const AffineConstraints<double> &constraints,
                              LA::SparseMatrix                *tangent,
                              LA::Vector                      *residual) const
    {
      // Variables of the kernel: slave node 0 and 1 (the point twice, eta
      // = 0), then the master's nodes; the point is sum_b phi_b y_b of the
      // slave cell's nodes.
      const unsigned int                   ns   = cells[a.slave].dofs.size();
      const unsigned int                   nm   = cells[a.master].dofs.size();
      const auto                          &phi  = shape[a.q];
      std::vector<types::global_dof_index> dofs = cells[a.slave].dofs;
      dofs.insert(dofs.end(),
                  cells[a.master].dofs.begin(),
                  cells[a.master].dofs.end());
      // Row v of the kernel's variables -> (local dof, weight).
      const auto chain = [&](const unsigned int v, auto &&add) {
        if (v < 3)
          for (unsigned int b = 0; b < ns / 3; ++b)
            add(3 * b + v, phi[b]);
        else if (v >= 6)
          add(ns + v - 6, 1.);
      };
      Vector<double>     g(ns + nm);
      FullMatrix<double> K(tangent ? ns + nm : 0, tangent ? ns + nm : 0);
      for (unsigned int v = 0; v < a.gradient.size(); ++v)
        chain(v, [&](const unsigned int i, const double w) {
          g(i) += w * a.gradient(v);
        });
      if (tangent)
        for (unsigned int v = 0; v < a.gradient.size(); ++v)
          chain(v, [&](const unsigned int i, const double wi) {
            for (unsigned int z = 0; z < a.gradient.size(); ++z)
              if (a.hessian(v, z) != 0.)
                chain(z, [&](const unsigned int j, const double wj) {
                  K(i, j) += wi * wj * a.hessian(v, z);
                });
          });
      LA::distribute(constraints, K, g, dofs, tangent, residual);
    }

    void
    SurfaceContact::assemble(const LA::Vector                &u,
                             const AffineConstraints<double> &constraints,
                             LA::SparseMatrix                *tangent,
                             LA::Vector                      *residual,
                             SurfaceRecord                   *record) const
    {
      const State state   = current_state(u);
      const auto &patches = state.patches;
      if (record)
        {
          record->reports.assign(pairs.size(), SurfaceReport());
          record->cell_force.assign(cells.size(), 0.);
          record->cell_area.assign(cells.size(), 0.);
          record->cell_gap.assign(cells.size(),
                                  std::numeric_limits<double>::max());
        }
      std::vector<Active> active = active_points(state, record);
      // The terms on the task threads (each point's differentiation is
      // independent), added in point order below: the sums do not depend
      // on the thread count.
      parallel::apply_to_subranges(
        0u,
        static_cast<unsigned int>(active.size()),
        [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int i = begin; i < end; ++i)
            {
              Active     &a        = active[i];
              MasterPatch m        = patches[a.master];
              m.sign               = a.orientation;
              const Tensor<1, 3> x = position(patches[a.slave], points[a.q]);
              penalty_terms(m,
                            {{x, x}},
                            0.,
                            a.offset,
                            a.penalty,
                            a.weight,
                            a.xi,
                            &a.gradient,
                            tangent ? &a.hessian : nullptr);
            }
        },
        8);
      if (tangent || residual)
        for (const Active &a : active)
          add_terms(a, constraints, tangent, residual);
      if (residual)
        residual->compress(VectorOperation::add);
      if (tangent)
        tangent->compress(VectorOperation::add);
      if (record)
        add_record(active, patches, *record);
    }

    void
    SurfaceContact::add_record(const std::vector<Active>      &active,
                               const std::vector<MasterPatch> &patches,
                               SurfaceRecord                  &record) const
    {
      for (const Active &a : active)
        {
          SurfaceReport &r = record.reports[a.pair];
          const double   N = -a.penalty * a.gap * a.weight;
          r.active_points += 1;
          r.total_force += N;
          r.energy += 0.5 * a.penalty * a.gap * a.gap * a.weight;
          r.penetration = std::max(r.penetration, -a.gap);
          // The force on the point, -dPi/dx; on the first side as slave
          // (side 0) or as master (side 1).
          Tensor<1, 3> f;
          for (unsigned int i = 0; i < 3; ++i)
            f[i] = -a.gradient(i);
          r.force += a.side == 0 ? f : -f;
          // The point's current area (each side's points count half).
          r.area += 0.5 * unit_weights[a.q]
                    * area_element(patches[a.slave], points[a.q]);
          record.cell_force[a.slave] += N;
          record.cell_force[a.master] += N;
        }
      // The current area of the owned slave cells (for the pressure).
      for (unsigned int c = 0; c < cells.size(); ++c)
        if (cells[c].owner
            == static_cast<int>(Utilities::MPI::this_mpi_process(comm)))
          for (unsigned int q = 0; q < points.size(); ++q)
            record.cell_area[c] +=
              unit_weights[q] * area_element(patches[c], points[q]);
      for (auto &r : record.reports)
        {
          r.active_points = Utilities::MPI::sum(r.active_points, comm);
          r.points        = Utilities::MPI::sum(r.points, comm);
          r.total_force   = Utilities::MPI::sum(r.total_force, comm);
          r.energy        = Utilities::MPI::sum(r.energy, comm);
          r.area          = Utilities::MPI::sum(r.area, comm);
          r.penetration   = Utilities::MPI::max(r.penetration, comm);
          r.force         = Utilities::MPI::sum(r.force, comm);
        }
      Utilities::MPI::sum(record.cell_force, comm, record.cell_force);
      Utilities::MPI::sum(record.cell_area, comm, record.cell_area);
      Utilities::MPI::min(record.cell_gap, comm, record.cell_gap);
    }

    std::string
    SurfaceContact::check(const LA::Vector &u, const bool start) const
    {
      const State state = current_state(u);
      const auto &boxes = state.boxes;
      std::string reason;
      for (unsigned int k = 0; k < pairs.size() && reason.empty(); ++k)
        for (const Side &side : pairs[k].sides)
          {
            std::vector<std::pair<BoundingBox<3>, unsigned int>> opposite;
            for (unsigned int c = 0; c < cells.size(); ++c)
              if (side.opposite[c])
                opposite.emplace_back(enlarged(boxes[c], 0.), c);
            const auto tree = pack_rtree(opposite);
            for (unsigned int i = 0; i < side.slaves.size() && reason.empty();
                 ++i)
              for (unsigned int q = 0; q < points.size() && reason.empty(); ++q)
                reason = check_point(k, side, i, q, state, tree, start);
          }
      // The first reason of the lowest rank that has one.
      const auto all = Utilities::MPI::all_gather(comm, reason);
      for (const auto &r : all)
        if (!r.empty())
          return r;
      return "";
    }

    template <class Tree>
    std::string
    SurfaceContact::check_point(const unsigned int k,
                                const Side        &side,
                                const unsigned int i,
                                const unsigned int q,
                                const State       &state,
                                const Tree        &tree,
                                const bool         start) const
    {
      const auto        &patches = state.patches;
      const unsigned int s       = side.slaves[i];
      const auto        &cand    = side.candidates[i];
      const Tensor<1, 3> x       = position(patches[s], points[q]);
      const auto         say     = [&](const unsigned int m,
                           const double       distance,
                           const std::string &what) {
        std::ostringstream o;
        o << parameters[k].path << ": the point (" << x[0] << ", " << x[1]
          << ", " << x[2] << ") of region " << int(cells[s].material) << " is "
          << distance << " m from a cell of region " << int(cells[m].material)
          << what;
        return o.str();
      };
      const auto half_thicknesses = [&](const unsigned int m) {
        std::ostringstream o;
        o << ", closer than their half thicknesses (" << offset(s, m) << " m)";
        return o.str();
      };
      // Passed through a candidate: behind its mid-surface (the penalty
      // leaves gaps far below the offset).
      Projection p;
      if (!start)
        if (const int j = nearest(side, i, x, state, p); j >= 0)
          {
            const unsigned int m = cand[j];
            const double       o = side_of(side, i, q, j);
            if (o * p.gap < 0.)
              return say(m,
                         p.distance,
                         " on the wrong side: the membranes passed through "
                         "each other in the step");
          }
      // Within the offset of a cell the step did not test.
      for (const unsigned int m : cells_near(tree, enlarged({x, x}, thickest)))
        {
          if (m == s || touching(s, m) || at_seam(s, m)
              || (!start && std::binary_search(cand.begin(), cand.end(), m)))
            continue;
          const Projection pm    = project(patches[m], x, 0.);
          const double     limit = (start ? 0.99 : 1.) * offset(s, m);
          if (pm.inside && pm.distance < limit)
            return say(m,
                       pm.distance,
                       half_thicknesses(m)
                         + (start ? ": the membranes overlap at the start"
                                  : ", and the cell was not a candidate of the "
                                    "step (it moved farther than the Search "
                                    "distance)"));
        }
      return "";
    }
  } // namespace contact
} // namespace pneuma
