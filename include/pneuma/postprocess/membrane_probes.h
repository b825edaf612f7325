#pragma once
/**
 * @file
 * Probes (Output/Probe points): the membrane state at given points of the
 * reference surface, evaluated at the point itself in the cell that holds
 * it (not a cell average as in the VTU fields): the principal Cauchy
 * membrane forces N1 >= N2 [N/m] with the direction of N1 and, where the
 * region wrinkles (membrane/tension_field.h), the wrinkling state (0 taut,
 * 1 wrinkled, 2 slack), the direction of the wrinkles' tension and the
 * plain law's smaller principal force H S_2 [N/m per reference length]
 * (negative: the compression relaxed away; its zero marks the border of a
 * wrinkled zone). Directions are current unit vectors, signed so that
 * their largest component is positive.
 */
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <pneuma/core/linear_algebra.h>
#include <pneuma/geometry/scene_generator.h>
#include <pneuma/membrane/constitutive_law.h>
#include <pneuma/postprocess/membrane_fields.h>

#include <array>
#include <string>
#include <vector>

namespace pneuma
{
  namespace postprocess
  {
    using namespace dealii;

    /// The membrane state at one probe.
    struct ProbeValues
    {
      PrincipalForces forces;
      /// 0 taut, 1 wrinkled, 2 slack; 0 where the region does not wrinkle.
      double       wrinkling_state = 0.;
      Tensor<1, 3> wrinkle_direction;
      double       plain_minor_force = 0.;
    };

    /**
     * The membrane state at @p points of the reference surface. Each point
     * is evaluated on one rank (the lowest that owns a cell holding it);
     * the others return zeros, so a sum over the ranks gives the values.
     * A point that lies on no cell (farther from the surface than 1e-3
     * of the nearest cell's diameter) is a collective InputError naming
     * @p entry.
     */
    std::vector<ProbeValues>
    membrane_probes(const Mapping<2, 3>             &mapping,
                    const DoFHandler<2, 3>          &dof_handler,
                    const membrane::MaterialRegions &materials,
                    const geometry::SceneGenerator  &geometry,
                    const LA::Vector                &u,
                    const std::vector<Point<3>>     &points,
                    const std::string               &entry);
  } // namespace postprocess
} // namespace pneuma
