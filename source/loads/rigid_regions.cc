#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <pneuma/core/input_error.h>
#include <pneuma/loads/loads.h>
#include <pneuma/loads/rigid_regions.h>

namespace pneuma
{
  namespace loads
  {
    namespace
    {
      /// Over all ranks, the point with the largest score (ties: lowest
      /// coordinates, so every rank picks the same point).
      Point<3>
      global_best(const double score, const Point<3> &p, const MPI_Comm comm)
      {
        const std::array<double, 4> mine{{score, p[0], p[1], p[2]}};
        const auto            all  = Utilities::MPI::all_gather(comm, mine);
        std::array<double, 4> best = all[0];
        for (const auto &a : all)
          if (a[0] > best[0]
              || (a[0] == best[0]
                  && std::make_tuple(a[1], a[2], a[3])
                       < std::make_tuple(best[1], best[2], best[3])))
            best = a;
        return Point<3>(best[1], best[2], best[3]);
      }
    } // namespace

    void
    RigidRegions::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      prm.add_parameter("Rigid regions",
                        text,
                        "Material ids of planar regions that move as rigid "
                        "plates (exact large rotations; in-plane stiffness "
                        "from the region's material). Ids joined by + form "
                        "one plate (e.g. 4+5+6, 7+8+9: a steel end plate "
                        "that closes several chambers). Supports go at the "
                        "plate's reference node, the vertex nearest its "
                        "centroid.",
                        Patterns::Anything());
      prm.leave_subsection();
    }

    void
    RigidRegions::parse_parameters(ParameterHandler &)
    {
      region_ids.clear();
      for (const auto &group : Utilities::split_string_list(text, ','))
        {
          std::set<types::material_id> plate;
          for (const auto &id : Utilities::split_string_list(group, '+'))
            {
              const auto one =
                parse_id_list(id, "Boundary conditions/Rigid regions");
              plate.insert(one.begin(), one.end());
            }
          if (!plate.empty())
            region_ids.push_back(plate);
        }
    }

    IndexSet
    RigidRegions::master_dofs(const Mapping<2, 3>    &mapping,
                              const DoFHandler<2, 3> &dof_handler)
    {
      (void)mapping;
      const MPI_Comm comm = dof_handler.get_communicator();
      IndexSet       result(dof_handler.n_dofs());
      plates.clear();
      for (const auto &ids : region_ids)
        {
          std::string id;
          for (const auto i : ids)
            id += (id.empty() ? "" : "+") + std::to_string(i);
          // The region's vertices and centroid.
          std::vector<Point<3>> vertices;
          Point<3>              sum;
          double                area = 0.;
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned() && ids.count(cell->material_id()))
              {
                sum += cell->measure() * cell->center();
                area += cell->measure();
                for (const auto v : cell->vertex_indices())
                  vertices.push_back(cell->vertex(v));
              }
          const double total = Utilities::MPI::sum(area, comm);
          check_input(total > 0.,
                      "Boundary conditions/Rigid regions",
                      "the mesh has no cells in region " + id);
          Point<3> centroid;
          for (unsigned int d = 0; d < 3; ++d)
            centroid[d] = Utilities::MPI::sum(sum[d], comm) / total;

          Plate plate;
          plate.ids = ids;
          auto pick = [&](const auto &score) {
            double   best = -std::numeric_limits<double>::max();
            Point<3> where;
            for (const auto &v : vertices)
              if (score(v) > best)
                {
                  best  = score(v);
                  where = v;
                }
            return global_best(best, where, comm);
          };
          plate.masters[0] =
            pick([&](const Point<3> &v) { return -v.distance(centroid); });
          plate.masters[1] = pick(
            [&](const Point<3> &v) { return v.distance(plate.masters[0]); });
          plate.masters[2]  = pick([&](const Point<3> &v) {
            return cross_product_3d(v - plate.masters[0],
                                    plate.masters[1] - plate.masters[0])
              .norm();
          });
          const double size = plate.masters[0].distance(plate.masters[1]);
          Tensor<1, 3> normal =
            cross_product_3d(plate.masters[1] - plate.masters[0],
                             plate.masters[2] - plate.masters[0]);
          check_input(normal.norm() > 1e-6 * size * size,
                      "Boundary conditions/Rigid regions",
                      "region " + id
                        + " is degenerate (all its nodes on a line)");
          normal /= normal.norm();
          double off_plane = 0.;
          for (const auto &v : vertices)
            off_plane =
              std::max(off_plane, std::abs((v - plate.masters[0]) * normal));
          off_plane = Utilities::MPI::max(off_plane, comm);
          check_input(off_plane <= 1e-6 * size,
                      "Boundary conditions/Rigid regions",
                      "region " + id + " is not planar (a node is "
                        + std::to_string(off_plane)
                        + " m off its plane); only planar plates can be rigid");

          // Master dofs: known on the ranks that see the vertex. Only the
          // plate's own cells count: at a junction, coincident copies of
          // the vertex belong to other regions and are tied to the plate's
          // copy (a master outside the plate would close a loop of
          // constraints through the tie).
          std::array<types::global_dof_index, 9> local;
          local.fill(0);
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (!cell->is_artificial() && ids.count(cell->material_id()))
              for (const auto v : cell->vertex_indices())
                for (unsigned int m = 0; m < 3; ++m)
                  if (cell->vertex(v).distance(plate.masters[m]) < 1e-12 * size)
                    for (unsigned int c = 0; c < 3; ++c)
                      local[3 * m + c] = cell->vertex_dof_index(v, c) + 1;
          const auto all = Utilities::MPI::all_gather(comm, local);
          plate.master_dofs.fill(0);
          for (const auto &a : all)
            for (unsigned int k = 0; k < 9; ++k)
              plate.master_dofs[k] = std::max(plate.master_dofs[k], a[k]);
          for (auto &d : plate.master_dofs)
            {
              Assert(d > 0, ExcInternalError());
              --d;
              result.add_index(d);
            }
          plates.push_back(plate);
        }
      return result;
    }

    void
    RigidRegions::add_constraints(const Mapping<2, 3>       &mapping,
                                  const DoFHandler<2, 3>    &dof_handler,
                                  AffineConstraints<double> &constraints) const
    {
      slaves.clear();
      if (plates.empty())
        return;
      const auto    &fe = dof_handler.get_fe();
      Quadrature<2>  support(fe.get_unit_support_points());
      FEValues<2, 3> fe_values(mapping, fe, support, update_quadrature_points);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &plate : plates)
        {
          const Point<3>    &A  = plate.masters[0];
          const Tensor<1, 3> e1 = plate.masters[1] - A;
          const Tensor<1, 3> e2 = plate.masters[2] - A;
          // Barycentric coordinates from the 2x2 normal equations.
          const double g11 = e1 * e1, g12 = e1 * e2, g22 = e2 * e2;
          const double det = g11 * g22 - g12 * g12;
          std::set<types::global_dof_index> masters(plate.master_dofs.begin(),
                                                    plate.master_dofs.end());
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (!cell->is_artificial() && plate.ids.count(cell->material_id()))
              {
                fe_values.reinit(cell);
                cell->get_dof_indices(dofs);
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  {
                    const auto dof = dofs[i];
                    if (masters.count(dof) || !constraints.can_store_line(dof)
                        || constraints.is_constrained(dof))
                      continue;
                    const unsigned int c =
                      fe.system_to_component_index(i).first;
                    const Tensor<1, 3> x  = fe_values.quadrature_point(i) - A;
                    const double       r1 = x * e1, r2 = x * e2;
                    const double       wB = (g22 * r1 - g12 * r2) / det;
                    const double       wC = (g11 * r2 - g12 * r1) / det;
                    constraints.add_line(dof);
                    constraints.add_entry(dof,
                                          plate.master_dofs[c],
                                          1. - wB - wC);
                    constraints.add_entry(dof, plate.master_dofs[3 + c], wB);
                    constraints.add_entry(dof, plate.master_dofs[6 + c], wC);
                    slaves.insert(dof);
                  }
              }
        }
    }
  } // namespace loads
} // namespace pneuma
