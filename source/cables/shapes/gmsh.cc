/**
 * @file
 * One open cable from the lines of a 1D-in-3D Gmsh mesh (GridIn::read_msh):
 * the lines of Physical group (or every line), ordered into one chain from
 * the free end that comes first in the file. The file's own nodes are the
 * cable's; "Number of elements" does not apply.
 */

#include <deal.II/grid/grid_in.h>

#include <pneuma/cables/cable_shape.h>
#include <pneuma/core/input_error.h>

#include <array>
#include <fstream>
#include <map>

namespace pneuma
{
  namespace cables
  {
    namespace
    {
      class GmshLines : public CableShape
      {
      public:
        void
        declare_parameters(ParameterHandler &prm) override
        {
          prm.add_parameter("Mesh file",
                            mesh_file,
                            "A 1D-in-3D .msh file (line elements), relative "
                            "to the working directory.",
                            Patterns::Anything());
          prm.add_parameter("Physical group",
                            physical_group,
                            "The physical curve that is this cable (-1: "
                            "every line of the file).",
                            Patterns::Integer(-1));
        }

        void
        parse_parameters(ParameterHandler &, const std::string &path) override
        {
          check_input(!mesh_file.empty(), path + "/Mesh file", "is empty");
          this->path = path;
        }

        void
        create_mesh(const unsigned int,
                    Triangulation<1, 3> &tria) const override
        {
          const std::string file_path = path + "/Mesh file";
          std::ifstream     in(mesh_file);
          check_input(in.good(), file_path, "cannot open '" + mesh_file + "'");
          Triangulation<1, 3> file_mesh;
          try
            {
              GridIn<1, 3> grid_in(file_mesh);
              grid_in.read_msh(in);
            }
          catch (const std::exception &e)
            {
              throw InputError(file_path,
                               "cannot read '" + mesh_file
                                 + "' as a 1D-in-3D Gmsh mesh of lines");
            }
          // The selected lines, as vertex pairs; then ordered into one
          // chain.
          std::vector<std::array<unsigned int, 2>> lines;
          for (const auto &cell : file_mesh.active_cell_iterators())
            if (physical_group < 0
                || cell->material_id()
                     == static_cast<types::material_id>(physical_group))
              lines.push_back({{cell->vertex_index(0), cell->vertex_index(1)}});
          check_input(!lines.empty(),
                      path + "/Physical group",
                      "no line of '" + mesh_file + "' is in group "
                        + std::to_string(physical_group));
          std::map<unsigned int, std::vector<unsigned int>> at_vertex;
          for (unsigned int l = 0; l < lines.size(); ++l)
            for (const auto v : lines[l])
              at_vertex[v].push_back(l);
          unsigned int start = numbers::invalid_unsigned_int;
          for (const auto &[v, ls] : at_vertex)
            {
              check_input(ls.size() <= 2,
                          file_path,
                          "the cable branches at vertex " + std::to_string(v));
              if (ls.size() == 1 && start == numbers::invalid_unsigned_int)
                start = v;
            }
          check_input(start != numbers::invalid_unsigned_int,
                      file_path,
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
              v               = lines[next_line][0] == v ? lines[next_line][1]
                                                         : lines[next_line][0];
              vertices.push_back(file_vertices[v]);
            }
          check_input(vertices.size() == lines.size() + 1,
                      file_path,
                      "the lines of the cable are not one connected curve");
          create_chain_mesh(vertices, false, tria);
        }

      private:
        std::string mesh_file;
        int         physical_group = -1;
        /// "Cables/Cable <k>/gmsh", for messages.
        std::string path;
      };
    } // namespace

    PNEUMA_REGISTER_VARIANT(CableShape,
                            GmshLines,
                            "gmsh",
                            "the lines of Physical group in a 1D-in-3D Gmsh "
                            "Mesh file")
  } // namespace cables
} // namespace pneuma
