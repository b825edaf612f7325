/**
 * @file
 * The membrane's reports: the check that the scene is held, the monitor
 * points, the reactions from the model's support residual with the
 * applied loads, and the statistics of a state.
 */

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <pneuma/core/checkpoint.h>
#include <pneuma/core/collective_error.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/model.h>
#include <pneuma/core/share_constraints.h>
#include <pneuma/membrane/face_assembly.h>
#include <pneuma/membrane/form_finding_law.h>
#include <pneuma/membrane/membrane_subsystem.h>
#include <pneuma/postprocess/membrane_fields.h>
#include <pneuma/postprocess/membrane_probes.h>

#include <fstream>
#include <limits>
#include <sstream>

namespace pneuma
{
  namespace membrane
  {
    namespace
    {
      /// The rigid motions of the eigenvectors @p vectors of the zero
      /// eigenvalues @p values (translations, then rotations), by their
      /// leading terms.
      std::string
      describe_motions(const Vector<double>     &values,
                       const FullMatrix<double> &vectors)
      {
        const char        *names[6] = {"translation along x",
                                       "translation along y",
                                       "translation along z",
                                       "rotation about x",
                                       "rotation about y",
                                       "rotation about z"};
        std::ostringstream free;
        for (unsigned int m = 0; m < values.size(); ++m)
          {
            free << (m ? "; " : "");
            bool first = true;
            for (unsigned int j = 0; j < 6; ++j)
              if (std::abs(vectors(j, m)) > 0.3)
                {
                  free << (first ? "" : " + ") << names[j];
                  first = false;
                }
          }
        return free.str();
      }
    } // namespace

    void
    MembraneSubsystem::check_well_posed() const
    {
      // A rigid motion r (3 translations, 3 rotations about the centroid,
      // scaled to unit size over the membrane) is removed by the supports
      // iff it moves some prescribed dof: the free motions are the null
      // space of G = sum over prescribed dofs i of r(i) r(i)^T (6 x 6).
      // Rigid plates and ties follow rigid motions, so they count through
      // their prescribed masters. Checked before the first factorization,
      // so that an ill-posed scene is a message, not minutes of cut-backs.
      std::map<types::global_dof_index, Point<3>> support;
      const Point<3> centre = support_centroid(support);
      double         size   = 0.;
      for (const auto &[i, x] : support)
        size = std::max(size, x.distance(centre));
      size = std::max(Utilities::MPI::max(size, comm), 1e-300);

      const auto        &constraints = model.constraints();
      FullMatrix<double> G(6, 6);
      for (unsigned int c = 0; c < 3; ++c)
        {
          std::vector<bool> mask(3, false);
          mask[c] = true;
          for (const auto i : DoFTools::extract_dofs(dofs, ComponentMask(mask)))
            if (constraints.is_constrained(i)
                && constraints.get_constraint_entries(i)->empty())
              {
                const Tensor<1, 3> r = (support.at(i) - centre) / size;
                double             row[6];
                for (unsigned int a = 0; a < 3; ++a)
                  {
                    Tensor<1, 3> e;
                    e[a]       = 1.;
                    row[a]     = (a == c) ? 1. : 0.;
                    row[3 + a] = cross_product_3d(e, r)[c];
                  }
                for (unsigned int j = 0; j < 6; ++j)
                  for (unsigned int k = 0; k < 6; ++k)
                    G(j, k) += row[j] * row[k];
              }
        }
      // A clamped shell edge holds the rotations about its direction.
      if (shell)
        for (const auto &a : shell->clamped_axes())
          for (unsigned int j = 0; j < 3; ++j)
            for (unsigned int k = 0; k < 3; ++k)
              G(3 + j, 3 + k) += a[j] * a[k];
      double trace = 0.;
      for (unsigned int j = 0; j < 6; ++j)
        for (unsigned int k = 0; k < 6; ++k)
          {
            G(j, k) = Utilities::MPI::sum(G(j, k), comm);
            if (j == k)
              trace += G(j, j);
          }

      // The free motions: eigenvectors of G with (numerically) zero
      // eigenvalue, described by their leading terms.
      LAPACKFullMatrix<double> lapack(6, 6);
      lapack = G;
      Vector<double>     values;
      FullMatrix<double> vectors;
      lapack.compute_eigenvalues_symmetric(
        -1., 1e-10 * std::max(trace, 1.), 1e-14, values, vectors);
      if (values.size() == 0)
        return;
      std::ostringstream where;
      where << centre;
      const std::string motion = "the membrane is free to move as a rigid "
                                 "body ("
                                 + describe_motions(values, vectors)
                                 + "; rotations about its centroid ("
                                 + where.str() + "))";
      // Contact with supported cables or obstacles may hold it; then it is
      // a warning.
      const auto holders = model.with<Holds>();
      if (std::any_of(holders.begin(), holders.end(), [this](const Holds *h) {
            return h->holds(*this);
          }))
        {
          model.out() << "pneuma: warning: " << motion
                      << " until contact holds it: a static stage needs "
                         "that contact from its first iteration on (Load "
                         "stepping/Strategy = relaxation finds it)"
                      << std::endl;
          return;
        }
      throw InputError("Boundary conditions",
                       motion
                         + ": add supports (Fixed points, Fixed boundaries, "
                           "Fixed regions) that hold it");
    }

    // ------------------------------------------------------------------
    // Reports
    // ------------------------------------------------------------------
    std::pair<std::array<types::global_dof_index, 3>, std::array<double, 3>>
    MembraneSubsystem::nearest_vertex(const Point<3> &p) const
    {
      double local_min = std::numeric_limits<double>::max();
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto v : cell->vertex_indices())
            local_min = std::min(local_min, cell->vertex(v).distance(p));
      const double global_min = Utilities::MPI::min(local_min, comm);
      // The lowest rank that owns a vertex at that distance reports it.
      std::array<types::global_dof_index, 3> dof;
      dof.fill(numbers::invalid_dof_index);
      std::array<double, 3> position{{0., 0., 0.}};
      bool                  found = false;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned() && !found)
          for (const auto v : cell->vertex_indices())
            if (cell->vertex(v).distance(p) <= global_min * (1 + 1e-12)
                && owned_dofs.is_element(cell->vertex_dof_index(v, 0)))
              {
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    dof[c]      = cell->vertex_dof_index(v, c);
                    position[c] = cell->vertex(v)[c];
                    // The surface form finding found.
                    if (reference_shift.size() > 0)
                      position[c] += reference_shift[dof[c]];
                  }
                found = true;
                break;
              }
      const unsigned int me = Utilities::MPI::this_mpi_process(comm);
      const unsigned int reporter =
        Utilities::MPI::min(found ? me : numbers::invalid_unsigned_int, comm);
      if (me != reporter)
        {
          dof.fill(numbers::invalid_dof_index);
          position.fill(0.);
        }
      for (unsigned int c = 0; c < 3; ++c)
        position[c] = Utilities::MPI::sum(position[c], comm);
      return {dof, position};
    }

    void
    MembraneSubsystem::locate_monitor_points()
    {
      monitor_dofs.clear();
      monitor_positions.clear();
      for (const auto &p : monitor_points)
        {
          const auto [dof, position] = nearest_vertex(p);
          monitor_dofs.push_back(dof);
          monitor_positions.push_back(position);
        }
    }

    void
    MembraneSubsystem::locate_point_loads()
    {
      point_load_dofs.clear();
      const auto &points = model.loads().point_load_points();
      for (unsigned int k = 0; k < points.size(); ++k)
        {
          const auto [dof, x] = nearest_vertex(points[k]);
          point_load_dofs.push_back(dof);
          model.out() << "Point load " << k << " at (" << points[k]
                      << "): vertex (" << x[0] << ", " << x[1] << ", " << x[2]
                      << ")" << std::endl;
        }
    }

    bool
    MembraneSubsystem::add_point_loads(
      const double                     t,
      const AffineConstraints<double> &constraints,
      LA::Vector                      *residual,
      LA::Vector                      *external) const
    {
      // Off in form finding, as the assembler's loads are.
      const auto &points = model.loads().point_load_points();
      if (points.empty() || form_finding)
        return false;
      std::vector<types::global_dof_index> indices(3);
      Vector<double>                       force(3), minus(3);
      for (unsigned int k = 0; k < points.size(); ++k)
        if (point_load_dofs[k][0] != numbers::invalid_dof_index)
          {
            const Tensor<1, 3> f = model.loads().point_load(points[k], t);
            for (unsigned int c = 0; c < 3; ++c)
              {
                indices[c] = point_load_dofs[k][c];
                force[c]   = f[c];
                minus[c]   = -f[c];
              }
            if (residual)
              constraints.distribute_local_to_global(minus, indices, *residual);
            if (external)
              constraints.distribute_local_to_global(force, indices, *external);
          }
      return true;
    }

    void
    MembraneSubsystem::compute_reactions(const LA::Vector      &u,
                                         const double           t,
                                         std::array<double, 3> &reaction,
                                         std::array<double, 3> &applied) const
    {
      // The reactions: the model's support residual (every subsystem's
      // f_int - f_ext with the dependent dofs' forces condensed onto their
      // masters): at a prescribed dof, the force the support exerts on the
      // structure, whatever loads it (cables pressing on it too). The
      // applied loads are assembled here; those of the cell terms
      // (chambers) count as applied loads.
      LA::Vector      ext = model.make_field(), scratch = model.make_field();
      AssemblyRequest request;
      request.time     = t;
      request.external = &ext;
      assembler->assemble(u, model.kinematic_constraints(), request);
      for (const auto *terms : cell_terms)
        terms->add_loads(u, model.kinematic_constraints(), t, scratch, ext);
      if (add_point_loads(t, model.kinematic_constraints(), nullptr, &ext))
        ext.compress(VectorOperation::add);
      const LA::Vector &residual = model.support_residual();
      reaction.fill(0.);
      applied.fill(0.);
      const auto &constraints = model.constraints();
      for (unsigned int c = 0; c < 3; ++c)
        {
          std::vector<bool> mask(3, false);
          mask[c] = true;
          const IndexSet component_dofs =
            DoFTools::extract_dofs(dofs, ComponentMask(mask));
          for (const auto i : component_dofs)
            {
              applied[c] += ext[i];
              if (constraints.is_constrained(i)
                  && constraints.get_constraint_entries(i)->empty())
                reaction[c] += residual[i];
            }
          reaction[c] = Utilities::MPI::sum(reaction[c], comm);
          applied[c]  = Utilities::MPI::sum(applied[c], comm);
        }

      // Per supported boundary: the force and its moment about the origin
      // at the current positions, from the prescribed dofs on it (a node
      // on two boundaries counts in both).
      boundary_reactions.clear();
      const auto &ids = boundary_conditions.supported_boundaries();
      if (ids.empty())
        return;
      const auto                                 &fe = dofs.get_fe();
      std::map<types::global_dof_index, Point<3>> support;
      DoFTools::map_dofs_to_support_points(*mapping_cache, dofs, support);
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      for (const auto id : ids)
        {
          std::set<types::global_dof_index> seen;
          Tensor<1, 3>                      force, moment;
          for (const auto &cell : dofs.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto f : cell->face_indices())
                if (cell->face(f)->at_boundary()
                    && cell->face(f)->boundary_id() == id)
                  {
                    cell->face(f)->get_dof_indices(face_dofs);
                    // The face's nodes: their three dofs, by base index.
                    std::map<unsigned int,
                             std::array<types::global_dof_index, 3>>
                      nodes;
                    for (unsigned int k = 0; k < face_dofs.size(); ++k)
                      {
                        const auto ci = fe.face_system_to_component_index(k);
                        nodes[ci.second][ci.first] = face_dofs[k];
                      }
                    for (const auto &[base, d] : nodes)
                      {
                        if (!owned_dofs.is_element(d[0])
                            || !seen.insert(d[0]).second)
                          continue;
                        Tensor<1, 3> x, r;
                        for (unsigned int c = 0; c < 3; ++c)
                          {
                            x[c] = support.at(d[c])[c] + u[d[c]];
                            if (constraints.is_constrained(d[c])
                                && constraints.get_constraint_entries(d[c])
                                     ->empty())
                              r[c] = residual[d[c]];
                          }
                        force += r;
                        moment += cross_product_3d(x, r);
                      }
                  }
          // A clamped shell edge's weak clamp acts on the nodes next to it
          // too: its moment (its forces add up to zero).
          if (shell && shell->clamp_moments().count(id) > 0)
            moment += shell->clamp_moments().at(id);
          std::array<double, 6> fm;
          for (unsigned int c = 0; c < 3; ++c)
            {
              fm[c]     = Utilities::MPI::sum(force[c], comm);
              fm[3 + c] = Utilities::MPI::sum(moment[c], comm);
            }
          boundary_reactions[id] = fm;
        }
    }

    void
    MembraneSubsystem::add_statistics(Statistics       &statistics,
                                      const LA::Vector &field,
                                      const double      t) const
    {
      const auto run = StatisticsGroup::run();
      // The supports' reaction and the applied load at every converged
      // state (one residual assembly per step): a load-deflection curve
      // needs the force the mesh actually carries, which differs from a
      // load function's nominal value where the function is discontinuous
      // across cells (a load band narrower than its cells).
      std::array<double, 3> reaction, applied;
      compute_reactions(field, t, reaction, applied);
      statistics.add_vector(run, "reaction", "N", reaction, Statistics::report);
      statistics.add_vector(
        run, "applied_load", "N", applied, Statistics::report);
      // With shells, the walls' strain energy split: membrane (all
      // regions, at the field) and bending (the shells', at the last
      // assembly, which is the field's).
      if (shell)
        {
          statistics.add(
            run,
            "membrane_energy",
            "J",
            Utilities::MPI::sum(
              postprocess::membrane_strain_energy(*mapping_cache,
                                                  dofs,
                                                  reference_geometry(),
                                                  materials,
                                                  scene,
                                                  field),
              comm),
            Statistics::report);
          statistics.add(run,
                         "bending_energy",
                         "J",
                         Utilities::MPI::sum(shell->energy(), comm),
                         Statistics::report);
        }
      if (statistics.is_summary())
        {
          statistics.add_count(run,
                               "cells",
                               mesh.n_global_active_cells(),
                               Statistics::summary | Statistics::test);
          for (const auto &[id, fm] : boundary_reactions)
            {
              const std::string b = "boundary_" + std::to_string(id);
              statistics.add_vector(run,
                                    b + "_reaction",
                                    "N",
                                    {{fm[0], fm[1], fm[2]}},
                                    Statistics::summary);
              statistics.add_vector(run,
                                    b + "_reaction_moment",
                                    "N m",
                                    {{fm[3], fm[4], fm[5]}},
                                    Statistics::summary);
            }
          if (form_finding_updates > 0)
            {
              statistics.add_count(run,
                                   "form_finding_updates",
                                   form_finding_updates,
                                   Statistics::summary);
              statistics.add(run,
                             "surface_area",
                             "m^2",
                             assembler->surface_area(field),
                             Statistics::summary);
            }
        }
      if (materials.any_wrinkling())
        {
          const auto w = postprocess::wrinkling_summary(*mapping_cache,
                                                        dofs,
                                                        reference_geometry(),
                                                        materials,
                                                        scene,
                                                        field);
          statistics.add(
            run, "wrinkled_area", "m^2", w.areas[1], Statistics::report);
          statistics.add(
            run, "slack_area", "m^2", w.areas[2], Statistics::report);
          statistics.add(
            run, "plain_minor_force", "N/m", w.minor_force, Statistics::report);
        }
      if (scene.is_closed())
        {
          statistics.add(run,
                         "volume",
                         "m^3",
                         assembler->enclosed_volume(field),
                         Statistics::all);
          statistics.add(run,
                         "initial_volume",
                         "m^3",
                         reference_volume,
                         Statistics::summary);
        }
      for (unsigned int m = 0; m < monitor_dofs.size(); ++m)
        {
          std::array<double, 3> u{{0., 0., 0.}};
          for (unsigned int c = 0; c < 3; ++c)
            if (monitor_dofs[m][c] != numbers::invalid_dof_index)
              u[c] = field[monitor_dofs[m][c]];
          const StatisticsGroup group{"m", "monitor_points", "monitor", m};
          statistics.add_vector(
            group, "position", "m", monitor_positions[m], Statistics::summary);
          statistics.add_vector(
            group, "u", "m", u, Statistics::all, Statistics::Reduction::sum);
        }
      if (!probe_points.empty())
        {
          const auto probes =
            postprocess::membrane_probes(*mapping_cache,
                                         dofs,
                                         materials,
                                         scene,
                                         field,
                                         probe_points,
                                         "Output/Probe points");
          const auto sum = Statistics::Reduction::sum;
          const auto vec = [](const Tensor<1, 3> &t) {
            return std::array<double, 3>{{t[0], t[1], t[2]}};
          };
          for (unsigned int k = 0; k < probes.size(); ++k)
            {
              const auto           &p = probes[k];
              const StatisticsGroup group{"p", "probe_points", "probe", k};
              statistics.add_vector(
                group,
                "position",
                "m",
                {{probe_points[k][0], probe_points[k][1], probe_points[k][2]}},
                Statistics::summary);
              statistics.add(
                group, "N1", "N/m", p.forces.N1, Statistics::all, sum);
              statistics.add(
                group, "N2", "N/m", p.forces.N2, Statistics::all, sum);
              statistics.add_vector(group,
                                    "N1_direction",
                                    "",
                                    vec(p.forces.direction_1),
                                    Statistics::all,
                                    sum);
              if (materials.any_wrinkling())
                {
                  statistics.add_count(group,
                                       "wrinkling_state",
                                       p.wrinkling_state,
                                       Statistics::all,
                                       sum);
                  statistics.add_vector(group,
                                        "wrinkle_direction",
                                        "",
                                        vec(p.wrinkle_direction),
                                        Statistics::all,
                                        sum);
                  statistics.add(group,
                                 "plain_minor_force",
                                 "N/m",
                                 p.plain_minor_force,
                                 Statistics::all,
                                 sum);
                }
            }
        }
    }
  } // namespace membrane
} // namespace pneuma
