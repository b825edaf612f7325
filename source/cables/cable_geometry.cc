#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <pneuma/cables/cable_geometry.h>
#include <pneuma/core/input_error.h>

#include <fstream>
#include <map>

namespace pneuma
{
  namespace cables
  {
    namespace
    {
      /// Unit vectors (e1, e2, axis) of the ring/helix frame.
      std::array<Tensor<1, 3>, 3>
      helix_frame(const CableDefinition &cable)
      {
        const Tensor<1, 3> a = cable.axis / cable.axis.norm();
        Tensor<1, 3>       e1 =
          cable.reference_direction - (cable.reference_direction * a) * a;
        e1 /= e1.norm();
        return {{e1, cross_product_3d(a, e1), a}};
      }

      /// Triangulation from ordered vertices: cells i -> i+1 (and the last
      /// back to the first when @p closed).
      void
      chain(const std::vector<Point<3>> &vertices,
            const bool                   closed,
            Triangulation<1, 3>         &tria)
      {
        const unsigned int     n_cells = closed ? vertices.size() :
                                                  vertices.size() - 1;
        std::vector<CellData<1>> cells(n_cells);
        for (unsigned int i = 0; i < n_cells; ++i)
          {
            cells[i].vertices[0] = i;
            cells[i].vertices[1] = (i + 1) % vertices.size();
            cells[i].material_id = 0;
          }
        tria.create_triangulation(vertices, cells, SubCellData());
      }

      void
      polyline(const CableDefinition &cable, Triangulation<1, 3> &tria)
      {
        // Elements spread over the segments by length, at least one each.
        const auto &p     = cable.points;
        double      total = 0.;
        for (unsigned int i = 1; i < p.size(); ++i)
          total += p[i].distance(p[i - 1]);
        std::vector<Point<3>> vertices{p[0]};
        for (unsigned int i = 1; i < p.size(); ++i)
          {
            const double       l = p[i].distance(p[i - 1]);
            const unsigned int n = std::max<unsigned int>(
              1, std::lround(cable.n_elements * l / total));
            for (unsigned int k = 1; k <= n; ++k)
              vertices.push_back(p[i - 1] + (double(k) / n) * (p[i] - p[i - 1]));
          }
        chain(vertices, false, tria);
      }

      void
      gmsh(const CableDefinition &cable, Triangulation<1, 3> &tria)
      {
        const std::string path = cable.path + "/Mesh file";
        std::ifstream     in(cable.mesh_file);
        check_input(in.good(),
                    path,
                    "cannot open '" + cable.mesh_file + "'");
        Triangulation<1, 3> file_mesh;
        try
          {
            GridIn<1, 3> grid_in(file_mesh);
            grid_in.read_msh(in);
          }
        catch (const std::exception &e)
          {
            throw InputError(path,
                             "cannot read '" + cable.mesh_file +
                               "' as a 1D-in-3D Gmsh mesh of lines");
          }
        // The selected lines, as vertex pairs; then ordered into one chain.
        std::vector<std::array<unsigned int, 2>> lines;
        for (const auto &cell : file_mesh.active_cell_iterators())
          if (cable.physical_group < 0 ||
              cell->material_id() ==
                static_cast<types::material_id>(cable.physical_group))
            lines.push_back({{cell->vertex_index(0), cell->vertex_index(1)}});
        check_input(!lines.empty(),
                    cable.path + "/Physical group",
                    "no line of '" + cable.mesh_file + "' is in group " +
                      std::to_string(cable.physical_group));
        std::map<unsigned int, std::vector<unsigned int>> at_vertex;
        for (unsigned int l = 0; l < lines.size(); ++l)
          for (const auto v : lines[l])
            at_vertex[v].push_back(l);
        unsigned int start = numbers::invalid_unsigned_int;
        for (const auto &[v, ls] : at_vertex)
          {
            check_input(ls.size() <= 2,
                        path,
                        "the cable branches at vertex " + std::to_string(v));
            if (ls.size() == 1 && start == numbers::invalid_unsigned_int)
              start = v;
          }
        check_input(start != numbers::invalid_unsigned_int,
                    path,
                    "the cable is a closed loop; only open cables can be "
                    "read from Gmsh");
        // Start at the free end that comes first in the file.
        for (const auto &line : lines)
          {
            bool found = false;
            for (const auto v : line)
              if (at_vertex[v].size() == 1)
                {
                  start = v;
                  found = true;
                  break;
                }
            if (found)
              break;
          }
        const auto           &file_vertices = file_mesh.get_vertices();
        std::vector<Point<3>> vertices{file_vertices[start]};
        std::vector<bool>     used(lines.size(), false);
        unsigned int          v = start;
        while (true)
          {
            unsigned int next_line = numbers::invalid_unsigned_int;
            for (const auto l : at_vertex[v])
              if (!used[l])
                next_line = l;
            if (next_line == numbers::invalid_unsigned_int)
              break;
            used[next_line] = true;
            v = lines[next_line][0] == v ? lines[next_line][1] :
                                           lines[next_line][0];
            vertices.push_back(file_vertices[v]);
          }
        check_input(vertices.size() == lines.size() + 1,
                    path,
                    "the lines of the cable are not one connected curve");
        chain(vertices, false, tria);
      }
    } // namespace

    Point<3>
    point_on_helix(const CableDefinition &cable, const double phi)
    {
      const auto   e     = helix_frame(cable);
      double       pitch = 0.;
      if (cable.shape == CableShape::helix)
        pitch = cable.pitch > 0. ?
                  cable.pitch :
                  2. * numbers::PI * cable.radius / std::tan(cable.angle_to_axis);
      const double s     = cable.right_handed ? 1. : -1.;
      const double angle = cable.start_angle + s * phi;
      return cable.centre + pitch * phi / (2. * numbers::PI) * e[2] +
             cable.radius * (std::cos(angle) * e[0] + std::sin(angle) * e[1]);
    }

    void
    create_cable_mesh(const CableDefinition &cable, Triangulation<1, 3> &tria)
    {
      tria.clear();
      switch (cable.shape)
        {
          case CableShape::polyline:
            polyline(cable, tria);
            break;
          case CableShape::ring:
            {
              std::vector<Point<3>> vertices;
              for (unsigned int i = 0; i < cable.n_elements; ++i)
                vertices.push_back(point_on_helix(
                  cable, 2. * numbers::PI * i / cable.n_elements));
              chain(vertices, true, tria);
              break;
            }
          case CableShape::helix:
            {
              std::vector<Point<3>> vertices;
              const double          phi_end = 2. * numbers::PI * cable.turns;
              for (unsigned int i = 0; i <= cable.n_elements; ++i)
                vertices.push_back(
                  point_on_helix(cable, phi_end * i / cable.n_elements));
              chain(vertices, false, tria);
              break;
            }
          case CableShape::gmsh:
            gmsh(cable, tria);
            break;
        }
    }
  } // namespace cables
} // namespace pneuma
