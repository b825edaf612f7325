#pragma once

/**
 * @file
 * The default penalty of the membrane's contacts (rigid obstacles,
 * membrane to membrane): \f$\epsilon = f\,E t/h^2\f$ [Pa/m] per cell, with
 * E t = 3 mu t of the cell's region (mu the law's initial shear modulus, t
 * the thickness) and h the node spacing (sqrt of the cell's reference area
 * over the element degree). Under a contact pressure p it leaves the gap
 * p h^2/(f E t): it falls with the mesh as h^2, like the geometric error of
 * the discrete surface, and stays below it for f = 10 at the membrane
 * strains of inflated structures (doc/theory.md "Rigid obstacles").
 */

#include <pneuma/membrane/constitutive_law.h>

namespace pneuma
{
  namespace contact
  {
    /// f E t / h^2 of a cell of @p material with reference @p area and
    /// element @p degree.
    inline double
    derived_penalty(const membrane::RegionMaterial &material,
                    const double                    area,
                    const unsigned int              degree,
                    const double                    factor)
    {
      const double Et =
        3. * material.plain_law->initial_shear_modulus() * material.thickness;
      return factor * Et / (area / double(degree * degree));
    }
  } // namespace contact
} // namespace pneuma
