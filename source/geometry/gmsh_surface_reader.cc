#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <pneuma/core/input_error.h>
#include <pneuma/geometry/gmsh_surface_reader.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

namespace pneuma
{
  namespace geometry
  {
    namespace
    {
      /// Gmsh element types pneuma reads or names in a message.
      constexpr int gmsh_line = 1, gmsh_triangle = 2, gmsh_quad = 3,
                    gmsh_quad9 = 10, gmsh_quad8 = 16, gmsh_triangle6 = 9;

      /// Reads a Gmsh file line by line and turns every failure into one
      /// InputError that names the parameter and the file.
      class MshParser
      {
      public:
        MshParser(const std::string &file, const std::string &parameter)
          : file(file)
          , parameter(parameter)
          , in(file)
        {
          check_input(static_cast<bool>(in),
                      parameter,
                      "cannot open the mesh file '" + file + "'");
        }

        [[noreturn]] void
        fail(const std::string &what) const
        {
          throw InputError(parameter, "'" + file + "': " + what);
        }

        /// The next non-empty line as a stream; fails at the end of file.
        std::istringstream
        next(const std::string &expected)
        {
          std::string line;
          while (std::getline(in, line))
            if (line.find_first_not_of(" \t\r") != std::string::npos)
              return std::istringstream(line);
          fail("ends before " + expected);
        }

        /// Skip forward to the line "$Name"; false at the end of file.
        bool
        find_section(std::string &name)
        {
          std::string line;
          while (std::getline(in, line))
            if (!line.empty() && line[0] == '$'
                && line.compare(0, 4, "$End") != 0)
              {
                name = line.substr(1);
                while (!name.empty()
                       && (name.back() == '\r' || name.back() == ' '))
                  name.pop_back();
                return true;
              }
          return false;
        }

        template <typename T>
        T
        read(std::istringstream &s, const std::string &what)
        {
          T value;
          if (!(s >> value))
            fail("cannot read " + what);
          return value;
        }

        /// Three coordinates from @p s.
        Point<3>
        read_point(std::istringstream &s)
        {
          Point<3> x;
          for (unsigned int d = 0; d < 3; ++d)
            x[d] = read<double>(s, "a node coordinate");
          return x;
        }

        const std::string file, parameter;

      private:
        std::ifstream in;
      };

      /// Nodes of a Gmsh element type, or 0 for one pneuma does not know.
      unsigned int
      nodes_of(const int type)
      {
        switch (type)
          {
            case gmsh_line:
              return 2;
            case gmsh_triangle:
              return 3;
            case gmsh_quad:
              return 4;
            case 15:
              return 1;
            case 8:
              return 3;
            case gmsh_triangle6:
              return 6;
            case gmsh_quad9:
              return 9;
            case gmsh_quad8:
              return 8;
            default:
              return 0;
          }
      }

      /// Collects the elements of both formats into SurfaceMeshData.
      struct Collector
      {
        MshParser       &parser;
        SurfaceMeshData &data;
        /// Keep triangles (a rigid surface) instead of failing on them.
        bool                                   triangles;
        std::unordered_map<long, unsigned int> node_index;
        /// Gmsh element tag of every cell, and the "warp" vectors by tag.
        std::vector<long>                      cell_tags;
        std::unordered_map<long, Tensor<1, 3>> warp;
        long                                   element = 0;

        unsigned int
        vertex(const long tag) const
        {
          const auto it = node_index.find(tag);
          if (it == node_index.end())
            parser.fail("an element refers to the unknown node "
                        + std::to_string(tag));
          return it->second;
        }

        void
        add(const int type, const std::vector<long> &nodes, const int tag)
        {
          if (type == gmsh_quad)
            {
              // Gmsh numbers a quadrilateral counter-clockwise, deal.II
              // lexicographically.
              CellData<2> c;
              c.vertices    = {vertex(nodes[0]),
                               vertex(nodes[1]),
                               vertex(nodes[3]),
                               vertex(nodes[2])};
              c.material_id = static_cast<types::material_id>(tag);
              data.cells.push_back(c);
              cell_tags.push_back(element);
            }
          else if (type == gmsh_line && tag > 0)
            {
              CellData<1> l;
              l.vertices    = {vertex(nodes[0]), vertex(nodes[1])};
              l.boundary_id = static_cast<types::boundary_id>(tag);
              data.tagged_lines.push_back(l);
            }
          else if (type == gmsh_triangle && triangles)
            data.triangles.push_back(
              {{vertex(nodes[0]), vertex(nodes[1]), vertex(nodes[2])}});
          else if (type == gmsh_triangle6 && triangles)
            parser.fail("holds second-order triangles; save a first-order "
                        "mesh");
          else if (type == gmsh_triangle || type == gmsh_triangle6)
            parser.fail("holds triangles; pneuma needs quadrilaterals "
                        "(Gmsh: Recombine Surface, or Mesh.RecombineAll = 1)");
          else if (type == gmsh_quad9 || type == gmsh_quad8)
            parser.fail("holds second-order quadrilaterals; save a "
                        "first-order mesh (the degree is set by "
                        "'Membrane/Degree')");
        }
      };

      /**
       * An $ElementData section (the same in versions 2 and 4): keep the
       * view named "warp" (3 components per element), the fabric's warp
       * direction per element; other views are skipped.
       */
      void
      read_element_data(MshParser &parser, Collector &collector)
      {
        auto        s       = parser.next("the element data's string tags");
        const int   strings = parser.read<int>(s, "the number of string tags");
        std::string name;
        for (int k = 0; k < strings; ++k)
          {
            std::string line;
            auto        tag_line = parser.next("a string tag");
            std::getline(tag_line, line);
            if (k == 0)
              {
                const auto a = line.find('"'), b = line.rfind('"');
                name = (a != std::string::npos && b > a)
                         ? line.substr(a + 1, b - a - 1)
                         : line;
              }
          }
        s               = parser.next("the element data's real tags");
        const int reals = parser.read<int>(s, "the number of real tags");
        for (int k = 0; k < reals; ++k)
          parser.next("a real tag");
        s                  = parser.next("the element data's integer tags");
        const int integers = parser.read<int>(s, "the number of integer tags");
        std::vector<long> tags;
        for (int k = 0; k < integers; ++k)
          {
            auto t = parser.next("an integer tag");
            tags.push_back(parser.read<long>(t, "an integer tag"));
          }
        if (tags.size() < 3)
          parser.fail("has an $ElementData view without its number of "
                      "components and entries");
        const long components = tags[1], entries = tags[2];
        if (name == "warp" && components != 3)
          parser.fail("has a \"warp\" $ElementData view with "
                      + std::to_string(components)
                      + " components per element; it needs 3 (a vector)");
        for (long k = 0; k < entries; ++k)
          {
            auto       line = parser.next("the last element data entry");
            const long tag  = parser.read<long>(line, "an element tag");
            if (name != "warp")
              continue;
            Tensor<1, 3> v;
            for (unsigned int d = 0; d < 3; ++d)
              v[d] = parser.read<double>(line, "a warp component");
            if (!std::isfinite(v.norm()))
              parser.fail("has a non-finite \"warp\" vector for element "
                          + std::to_string(tag));
            collector.warp[tag] = v;
          }
      }

      void
      read_version_2(MshParser &parser, Collector &collector)
      {
        std::string section;
        while (parser.find_section(section))
          if (section == "Nodes")
            {
              auto       head = parser.next("the node count");
              const long n    = parser.read<long>(head, "the node count");
              for (long k = 0; k < n; ++k)
                {
                  auto       s   = parser.next("the last node");
                  const long tag = parser.read<long>(s, "a node tag");
                  collector.node_index[tag] = collector.data.vertices.size();
                  collector.data.vertices.push_back(parser.read_point(s));
                }
            }
          else if (section == "ElementData")
            read_element_data(parser, collector);
          else if (section == "Elements")
            {
              auto       head = parser.next("the element count");
              const long n    = parser.read<long>(head, "the element count");
              for (long k = 0; k < n; ++k)
                {
                  auto s             = parser.next("the last element");
                  collector.element  = parser.read<long>(s, "an element tag");
                  const int type     = parser.read<int>(s, "an element type");
                  const int ntags    = parser.read<int>(s, "an element's tags");
                  int       physical = 0;
                  for (int t = 0; t < ntags; ++t)
                    {
                      const int value = parser.read<int>(s, "an element tag");
                      if (t == 0)
                        physical = value;
                    }
                  std::vector<long> nodes(nodes_of(type));
                  for (auto &v : nodes)
                    v = parser.read<long>(s, "an element's nodes");
                  collector.add(type, nodes, physical);
                }
            }
      }

      void
      read_version_4(MshParser &parser, Collector &collector)
      {
        // Physical tag of each (dimension, entity): the first one listed.
        std::map<std::pair<int, int>, int> physical;
        std::string                        section;
        while (parser.find_section(section))
          if (section == "Entities")
            {
              auto head = parser.next("the entity counts");
              int  count[4];
              for (auto &c : count)
                c = parser.read<int>(head, "the entity counts");
              for (int dim = 0; dim < 4; ++dim)
                for (int k = 0; k < count[dim]; ++k)
                  {
                    auto      s   = parser.next("the last entity");
                    const int tag = parser.read<int>(s, "an entity tag");
                    for (int c = 0; c < (dim == 0 ? 3 : 6); ++c)
                      parser.read<double>(s, "an entity's bounding box");
                    const int n = parser.read<int>(s, "physical tag count");
                    for (int t = 0; t < n; ++t)
                      {
                        const int p = parser.read<int>(s, "a physical tag");
                        if (t == 0)
                          physical[{dim, tag}] = p;
                      }
                  }
            }
          else if (section == "Nodes")
            {
              auto       head   = parser.next("the node blocks");
              const long blocks = parser.read<long>(head, "the node blocks");
              for (long b = 0; b < blocks; ++b)
                {
                  auto s = parser.next("a node block");
                  parser.read<int>(s, "a node block's dimension");
                  parser.read<int>(s, "a node block's entity");
                  parser.read<int>(s, "parametric");
                  const long n = parser.read<long>(s, "a node block's size");
                  std::vector<long> tags(n);
                  for (auto &t : tags)
                    {
                      auto line = parser.next("a node tag");
                      t         = parser.read<long>(line, "a node tag");
                    }
                  for (const auto t : tags)
                    {
                      // Parametric (u, v) after x, y, z are ignored.
                      auto line = parser.next("a node's coordinates");
                      collector.node_index[t] = collector.data.vertices.size();
                      collector.data.vertices.push_back(
                        parser.read_point(line));
                    }
                }
            }
          else if (section == "ElementData")
            read_element_data(parser, collector);
          else if (section == "Elements")
            {
              auto       head   = parser.next("the element blocks");
              const long blocks = parser.read<long>(head, "the element blocks");
              for (long b = 0; b < blocks; ++b)
                {
                  auto       s      = parser.next("an element block");
                  const int  dim    = parser.read<int>(s, "a block dimension");
                  const int  entity = parser.read<int>(s, "a block entity");
                  const int  type   = parser.read<int>(s, "an element type");
                  const long n      = parser.read<long>(s, "a block size");
                  const auto p      = physical.find({dim, entity});
                  const int  tag    = p == physical.end() ? 0 : p->second;
                  for (long k = 0; k < n; ++k)
                    {
                      auto line = parser.next("the last element");
                      collector.element =
                        parser.read<long>(line, "an element tag");
                      std::vector<long> nodes(nodes_of(type));
                      for (auto &v : nodes)
                        v = parser.read<long>(line, "an element's nodes");
                      collector.add(type, nodes, tag);
                    }
                }
            }
      }
    } // namespace

    SurfaceMeshData
    read_gmsh_surface(const std::string &file,
                      const std::string &parameter,
                      const bool         triangles)
    {
      MshParser   parser(file, parameter);
      std::string section;
      if (!parser.find_section(section) || section != "MeshFormat")
        parser.fail("is not a Gmsh mesh (no $MeshFormat)");
      auto         s       = parser.next("the format line");
      const double version = parser.read<double>(s, "the format version");
      const int    binary  = parser.read<int>(s, "the file type");
      if (binary != 0)
        parser.fail("is a binary Gmsh file; save it as ASCII "
                    "(gmsh -save -format msh22, or msh41)");

      SurfaceMeshData data;
      Collector       collector{parser, data, triangles, {}, {}, {}, 0};
      if (version >= 2. && version < 3.)
        read_version_2(parser, collector);
      else if (version >= 4. && version < 5.)
        read_version_4(parser, collector);
      else
        {
          std::ostringstream v;
          v << version;
          parser.fail("has the unsupported MSH version " + v.str()
                      + " (use 2.2 or 4.1)");
        }
      if (!collector.warp.empty())
        for (const auto tag : collector.cell_tags)
          {
            const auto it = collector.warp.find(tag);
            data.cell_warp.push_back(it == collector.warp.end() ? Tensor<1, 3>()
                                                                : it->second);
          }
      return data;
    }

    void
    create_from_surface_data(SurfaceMeshData &data, Triangulation<2, 3> &tria)
    {
      // Only lines on the boundary can carry a boundary id.
      std::map<MeshLine, unsigned int> count;
      for (const auto &c : data.cells)
        for (unsigned int e = 0; e < 4; ++e)
          ++count[cell_line(c, e)];
      SubCellData sub;
      for (const auto &l : data.tagged_lines)
        {
          const auto it = count.find(mesh_line(l.vertices[0], l.vertices[1]));
          if (it != count.end() && it->second == 1)
            sub.boundary_lines.push_back(l);
        }
      GridTools::delete_unused_vertices(data.vertices, data.cells, sub);
      GridTools::consistently_order_cells(data.cells);
      tria.clear();
      tria.create_triangulation(data.vertices, data.cells, sub);
    }
  } // namespace geometry
} // namespace pneuma
