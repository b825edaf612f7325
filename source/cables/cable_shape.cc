#include <pneuma/cables/cable_shape.h>

namespace pneuma
{
  namespace cables
  {
    void
    create_chain_mesh(const std::vector<Point<3>> &vertices,
                      const bool                   closed,
                      Triangulation<1, 3>         &tria)
    {
      const unsigned int n_cells =
        closed ? vertices.size() : vertices.size() - 1;
      std::vector<CellData<1>> cells(n_cells);
      for (unsigned int i = 0; i < n_cells; ++i)
        {
          cells[i].vertices[0] = i;
          cells[i].vertices[1] = (i + 1) % vertices.size();
          cells[i].material_id = 0;
        }
      tria.create_triangulation(vertices, cells, SubCellData());
    }
  } // namespace cables
} // namespace pneuma
