#include <pneuma/core/input_error.h>
#include <pneuma/geometry/scene_generator.h>

namespace pneuma
{
  namespace geometry
  {
    void
    SceneGenerator::declare_type(ParameterHandler &prm)
    {
      const auto &registry = GeometryRegistry::instance();
      prm.enter_subsection("Geometry");
      prm.declare_entry("Type",
                        "closed cylinder",
                        Patterns::Selection(registry.names() + "|none"),
                        "Membrane surface; its constants are in the "
                        "subsection of its name. "
                          + registry.descriptions()
                          + "; none: no membrane (a scene of cables only).");
      prm.leave_subsection();
    }

    void
    SceneGenerator::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      prm.add_parameter("Global refinements",
                        refinements,
                        "Uniform refinements of the coarse mesh.",
                        Patterns::Integer(0, 12));
      variants = GeometryRegistry::instance().declare_all(prm);
      prm.leave_subsection();
    }

    void
    SceneGenerator::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      geometry_type = prm.get("Type");
      surface       = GeometryRegistry::instance().take(
        variants, prm, geometry_type, "Geometry/Type", "Geometry");
      prm.leave_subsection();
    }

    void
    SceneGenerator::create_triangulation(
      parallel::distributed::Triangulation<2, 3> &tria) const
    {
      Triangulation<2, 3> coarse;
      surface->create_coarse_mesh(coarse);
      tria.copy_triangulation(coarse);
      // Manifolds: curved surfaces and rims follow the true geometry.
      surface->attach_manifolds(tria);
      tria.refine_global(refinements);
    }
  } // namespace geometry
} // namespace pneuma
