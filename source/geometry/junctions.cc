#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>

#include <pneuma/geometry/junctions.h>

#include <algorithm>
#include <array>
#include <map>

namespace pneuma
{
  namespace geometry
  {
    unsigned int
    split_junctions(SurfaceMeshData &data)
    {
      auto &cells = data.cells;

      std::map<MeshLine, std::vector<unsigned int>> line_cells;
      for (unsigned int c = 0; c < cells.size(); ++c)
        for (unsigned int e = 0; e < 4; ++e)
          line_cells[cell_line(cells[c], e)].push_back(c);
      std::set<MeshLine>     junction_lines;
      std::set<unsigned int> junction_vertices;
      for (const auto &[line, on] : line_cells)
        if (on.size() > 2)
          {
            junction_lines.insert(line);
            junction_vertices.insert(line.first);
            junction_vertices.insert(line.second);
          }
      if (junction_lines.empty())
        return 0;

      std::map<unsigned int, std::vector<unsigned int>> vertex_cells;
      for (unsigned int c = 0; c < cells.size(); ++c)
        for (const auto v : cells[c].vertices)
          if (junction_vertices.count(v))
            vertex_cells[v].push_back(c);

      // Original line of every (cell, edge), to carry tags across the split.
      std::vector<std::array<MeshLine, 4>> original(cells.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        for (unsigned int e = 0; e < 4; ++e)
          original[c][e] = cell_line(cells[c], e);

      // Fans around each junction vertex: cells joined through lines at the
      // vertex that are not junctions (union-find); all fans but the first
      // get a copy of the vertex.
      std::vector<std::array<unsigned int, 4>> new_vertex(cells.size());
      for (unsigned int c = 0; c < cells.size(); ++c)
        for (unsigned int i = 0; i < 4; ++i)
          new_vertex[c][i] = cells[c].vertices[i];
      for (const auto &[v, around] : vertex_cells)
        {
          std::vector<unsigned int> parent(around.size());
          for (unsigned int k = 0; k < around.size(); ++k)
            parent[k] = k;
          const auto root = [&](unsigned int k) {
            while (parent[k] != k)
              k = parent[k] = parent[parent[k]];
            return k;
          };
          std::map<MeshLine, std::vector<unsigned int>> lines_at_v;
          for (unsigned int k = 0; k < around.size(); ++k)
            for (unsigned int e = 0; e < 4; ++e)
              {
                const auto &line = original[around[k]][e];
                if ((line.first == v || line.second == v)
                    && !junction_lines.count(line))
                  lines_at_v[line].push_back(k);
              }
          for (const auto &[line, ks] : lines_at_v)
            for (unsigned int k = 1; k < ks.size(); ++k)
              parent[root(ks[k])] = root(ks[0]);
          std::map<unsigned int, unsigned int> copy_of_fan;
          for (unsigned int k = 0; k < around.size(); ++k)
            {
              const unsigned int fan = root(k);
              auto               it  = copy_of_fan.find(fan);
              if (it == copy_of_fan.end())
                {
                  unsigned int index = v;
                  if (!copy_of_fan.empty())
                    {
                      index = data.vertices.size();
                      data.vertices.push_back(data.vertices[v]);
                    }
                  it = copy_of_fan.emplace(fan, index).first;
                }
              for (unsigned int i = 0; i < 4; ++i)
                if (cells[around[k]].vertices[i] == v)
                  new_vertex[around[k]][i] = it->second;
            }
        }
      for (unsigned int c = 0; c < cells.size(); ++c)
        for (unsigned int i = 0; i < 4; ++i)
          cells[c].vertices[i] = new_vertex[c][i];

      // Tags: a tagged boundary line keeps its id on its one cell; every
      // line that the split turned into a boundary is a junction face.
      std::map<MeshLine, types::boundary_id> tag;
      for (const auto &l : data.tagged_lines)
        tag[mesh_line(l.vertices[0], l.vertices[1])] = l.boundary_id;
      std::map<MeshLine, unsigned int> new_count;
      for (const auto &c : cells)
        for (unsigned int e = 0; e < 4; ++e)
          ++new_count[cell_line(c, e)];
      std::vector<CellData<1>> tagged;
      for (unsigned int c = 0; c < cells.size(); ++c)
        for (unsigned int e = 0; e < 4; ++e)
          {
            const MeshLine now = cell_line(cells[c], e);
            if (new_count[now] != 1)
              continue;
            const auto &was = original[c][e];
            CellData<1> l;
            l.vertices = {now.first, now.second};
            if (line_cells[was].size() > 1)
              l.boundary_id = junction_boundary_id;
            else if (tag.count(was))
              l.boundary_id = tag[was];
            else
              continue;
            tagged.push_back(l);
          }
      data.tagged_lines = tagged;
      return junction_lines.size();
    }

    void
    JunctionTies::find(const Mapping<2, 3>                &mapping,
                       const DoFHandler<2, 3>             &dof_handler,
                       const std::set<types::material_id> &rigid_ids,
                       const IndexSet                     &locally_relevant)
    {
      const MPI_Comm comm = dof_handler.get_communicator();
      ties.clear();
      masters        = IndexSet(dof_handler.n_dofs());
      const auto &fe = dof_handler.get_fe();

      // Records on junction faces: x, y, z, component, dof, rigid.
      std::vector<double>                  local;
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      std::map<types::global_dof_index, Point<3>> support;
      DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
      double size = 0.;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            size = std::max(size, cell->diameter());
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary()
                  && cell->face(f)->boundary_id() == junction_boundary_id)
                {
                  cell->face(f)->get_dof_indices(face_dofs);
                  for (unsigned int i = 0; i < face_dofs.size(); ++i)
                    {
                      const Point<3> &x = support.at(face_dofs[i]);
                      local.insert(
                        local.end(),
                        {x[0],
                         x[1],
                         x[2],
                         double(fe.face_system_to_component_index(i).first),
                         double(face_dofs[i]),
                         rigid_ids.count(cell->material_id()) ? 1. : 0.});
                    }
                }
          }
      size                = Utilities::MPI::max(size, comm);
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
      std::sort(records.begin(),
                records.end(),
                [](const auto &a, const auto &b) {
                  return a.component != b.component ? a.component < b.component
                                                    : a.x[0] < b.x[0];
                });
      const double      tolerance = 1e-8 * size;
      std::vector<bool> grouped(records.size(), false);
      for (unsigned int a = 0; a < records.size(); ++a)
        {
          if (grouped[a])
            continue;
          std::vector<unsigned int> group = {a};
          for (unsigned int b = a + 1;
               b < records.size()
               && records[b].component == records[a].component
               && records[b].x[0] - records[a].x[0] <= tolerance;
               ++b)
            if (!grouped[b] && records[b].x.distance(records[a].x) <= tolerance)
              group.push_back(b);
          for (const auto g : group)
            grouped[g] = true;
          // Distinct dofs of the group; the master is a rigid copy if any.
          std::map<types::global_dof_index, bool> dofs;
          for (const auto g : group)
            dofs[records[g].dof] = dofs[records[g].dof] || records[g].rigid;
          // Every point of a junction face has a copy on another fan; one
          // without would be a tear (copies refined differently).
          AssertThrow(dofs.size() >= 2,
                      ExcMessage("a junction point at "
                                 + std::to_string(records[a].x[0]) + ", "
                                 + std::to_string(records[a].x[1]) + ", "
                                 + std::to_string(records[a].x[2])
                                 + " has no copy to be tied to"));
          auto master = dofs.begin();
          for (auto it = dofs.begin(); it != dofs.end(); ++it)
            if (it->second)
              {
                master = it;
                break;
              }
          masters.add_index(master->first);

          for (const auto &[dof, rigid] : dofs)
            if (dof != master->first && !(rigid && master->second)
                && locally_relevant.is_element(dof))
              ties.emplace_back(dof, master->first);
        }
      masters.compress();
    }

    void
    JunctionTies::add_constraints(AffineConstraints<double> &constraints) const
    {
      for (const auto &[copy, master] : ties)
        if (constraints.can_store_line(copy)
            && !constraints.is_constrained(copy))
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
