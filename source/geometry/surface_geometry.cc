#include <pneuma/core/input_error.h>
#include <pneuma/geometry/surface_geometry.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace pneuma
{
  namespace geometry
  {
    void
    check_length(const double value, const std::string &parameter)
    {
      check_input(value > 0., parameter, "must be positive");
      if (!(value <= 1e6))
        {
          std::ostringstream what;
          what << "is " << value << " m; lengths are in metres (at most 1e6 m)";
          throw InputError(parameter, what.str());
        }
    }

    unsigned int
    cylinder_cells_along(const double       length,
                         const double       radius,
                         const unsigned int given,
                         const std::string &path)
    {
      if (given > 0)
        return given;
      // A quarter of the circumference per cell.
      const double n = std::round(length / (0.5 * M_PI * radius));
      if (!(n <= 1000.))
        {
          std::ostringstream what;
          what << "is " << radius << " m for a Length of " << length
               << " m: nearly square coarse cells would need " << n
               << " along the axis (at most 1000); check the units, or "
                  "give Cells along length";
          throw InputError(path + "/Radius", what.str());
        }
      return std::max(1u, static_cast<unsigned int>(n));
    }
  } // namespace geometry
} // namespace pneuma
