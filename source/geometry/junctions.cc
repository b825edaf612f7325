#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>

#include <pneuma/geometry/junctions.h>

#include <algorithm>
#include <map>

namespace pneuma
{
  namespace geometry
  {
    bool
    split_junctions(const Triangulation<2, 3> &in, Triangulation<2, 3> &out)
    {
      std::map<unsigned int, unsigned int> line_cells;
      for (const auto &cell : in.active_cell_iterators())
        for (const auto l : cell->line_indices())
          ++line_cells[cell->line_index(l)];
      std::set<unsigned int> junction_vertices;
      for (const auto &cell : in.active_cell_iterators())
        for (const auto l : cell->line_indices())
          if (line_cells[cell->line_index(l)] > 2)
            {
              junction_vertices.insert(cell->line(l)->vertex_index(0));
              junction_vertices.insert(cell->line(l)->vertex_index(1));
            }
      if (junction_vertices.empty())
        return false;

      // One copy of each junction vertex per material region.
      std::vector<Point<3>> vertices = in.get_vertices();
      std::map<std::pair<unsigned int, types::material_id>, unsigned int>
        copy_of;
      const auto vertex_for = [&](const unsigned int       v,
                                  const types::material_id m) {
        if (!junction_vertices.count(v))
          return v;
        const auto key = std::make_pair(v, m);
        auto       it  = copy_of.find(key);
        if (it != copy_of.end())
          return it->second;
        // The first region keeps the original vertex.
        bool used = false;
        for (const auto &[k, index] : copy_of)
          if (k.first == v)
            used = true;
        unsigned int index = v;
        if (used)
          {
            index = vertices.size();
            vertices.push_back(vertices[v]);
          }
        copy_of[key] = index;
        return index;
      };

      std::vector<CellData<2>> cells;
      for (const auto &cell : in.active_cell_iterators())
        {
          CellData<2> c;
          c.vertices.resize(4);
          for (const auto v : cell->vertex_indices())
            c.vertices[v] =
              vertex_for(cell->vertex_index(v), cell->material_id());
          c.material_id = cell->material_id();
          c.manifold_id = cell->manifold_id();
          cells.push_back(c);
        }

      // Boundary ids: lines that become boundaries by the split are
      // junction faces; old boundary lines keep theirs.
      std::map<std::pair<unsigned int, unsigned int>, unsigned int> new_count;
      const auto key = [](unsigned int a, unsigned int b) {
        return std::make_pair(std::min(a, b), std::max(a, b));
      };
      for (const auto &cell : in.active_cell_iterators())
        for (const auto l : cell->line_indices())
          {
            const auto line = cell->line(l);
            ++new_count[key(vertex_for(line->vertex_index(0),
                                       cell->material_id()),
                             vertex_for(line->vertex_index(1),
                                        cell->material_id()))];
          }
      SubCellData sub;
      std::set<std::pair<unsigned int, unsigned int>> done;
      for (const auto &cell : in.active_cell_iterators())
        for (const auto l : cell->line_indices())
          {
            const auto line = cell->line(l);
            const auto k =
              key(vertex_for(line->vertex_index(0), cell->material_id()),
                  vertex_for(line->vertex_index(1), cell->material_id()));
            if (new_count[k] != 1 || !done.insert(k).second)
              continue;
            const bool was_boundary = line_cells[cell->line_index(l)] == 1;
            CellData<1> b;
            b.vertices    = {k.first, k.second};
            b.boundary_id = was_boundary ? line->boundary_id() :
                                           junction_boundary_id;
            b.manifold_id = line->manifold_id();
            sub.boundary_lines.push_back(b);
          }
      out.clear();
      out.create_triangulation(vertices, cells, sub);
      return true;
    }

    void
    JunctionTies::find(const Mapping<2, 3>                 &mapping,
                       const DoFHandler<2, 3>              &dof_handler,
                       const std::set<types::material_id> &rigid_ids,
                       const IndexSet                      &locally_relevant)
    {
      const MPI_Comm comm = dof_handler.get_communicator();
      ties.clear();
      masters = IndexSet(dof_handler.n_dofs());
      const auto &fe = dof_handler.get_fe();

      // Records on junction faces: x, y, z, component, dof, rigid.
      std::vector<double> local;
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      std::map<types::global_dof_index, Point<3>> support;
      DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
      double size = 0.;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            size = std::max(size, cell->diameter());
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == junction_boundary_id)
                {
                  cell->face(f)->get_dof_indices(face_dofs);
                  for (unsigned int i = 0; i < face_dofs.size(); ++i)
                    {
                      const Point<3> &x = support.at(face_dofs[i]);
                      local.insert(local.end(),
                                   {x[0],
                                    x[1],
                                    x[2],
                                    double(fe.face_system_to_component_index(i)
                                             .first),
                                    double(face_dofs[i]),
                                    rigid_ids.count(cell->material_id()) ?
                                      1. :
                                      0.});
                    }
                }
          }
      size = Utilities::MPI::max(size, comm);
      const auto gathered = Utilities::MPI::all_gather(comm, local);
      struct Record
      {
        Point<3>                x;
        unsigned int            component;
        types::global_dof_index dof;
        bool                    rigid;
      };
      std::vector<Record> records;
      for (const auto &part : gathered)
        for (unsigned int k = 0; k + 5 < part.size(); k += 6)
          records.push_back({Point<3>(part[k], part[k + 1], part[k + 2]),
                             static_cast<unsigned int>(part[k + 3]),
                             static_cast<types::global_dof_index>(part[k + 4]),
                             part[k + 5] > 0.5});
      std::sort(records.begin(), records.end(), [](const auto &a, const auto &b) {
        return a.component != b.component ? a.component < b.component :
                                            a.x[0] < b.x[0];
      });
      const double tolerance = 1e-8 * size;
      std::vector<bool> grouped(records.size(), false);
      for (unsigned int a = 0; a < records.size(); ++a)
        {
          if (grouped[a])
            continue;
          std::vector<unsigned int> group = {a};
          for (unsigned int b = a + 1;
               b < records.size() &&
               records[b].component == records[a].component &&
               records[b].x[0] - records[a].x[0] <= tolerance;
               ++b)
            if (!grouped[b] && records[b].x.distance(records[a].x) <= tolerance)
              group.push_back(b);
          for (const auto g : group)
            grouped[g] = true;
          // Distinct dofs of the group; the master is a rigid copy if any.
          std::map<types::global_dof_index, bool> dofs;
          for (const auto g : group)
            dofs[records[g].dof] = dofs[records[g].dof] || records[g].rigid;
          if (dofs.size() < 2)
            continue;
          auto master = dofs.begin();
          for (auto it = dofs.begin(); it != dofs.end(); ++it)
            if (it->second)
              {
                master = it;
                break;
              }
          masters.add_index(master->first);
          for (const auto &[dof, rigid] : dofs)
            if (dof != master->first && !(rigid && master->second) &&
                locally_relevant.is_element(dof))
              ties.emplace_back(dof, master->first);
        }
      masters.compress();
    }

    void
    JunctionTies::add_constraints(AffineConstraints<double> &constraints) const
    {
      for (const auto &[copy, master] : ties)
        if (constraints.can_store_line(copy) &&
            !constraints.is_constrained(copy))
          {
            constraints.add_line(copy);
            constraints.add_entry(copy, master, 1.);
          }
    }

    std::set<types::global_dof_index>
    JunctionTies::copies() const
    {
      std::set<types::global_dof_index> result;
      for (const auto &t : ties)
        result.insert(t.first);
      return result;
    }
  } // namespace geometry
} // namespace pneuma
