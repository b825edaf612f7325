#include <deal.II/grid/grid_tools.h>

#include <pneuma/core/input_error.h>
#include <pneuma/geometry/scene_generator.h>

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

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
      prm.add_parameter("Memory limit",
                        memory_limit,
                        "Size guard [GB]: a run whose mesh and factorized "
                        "tangent would need more memory than this (estimated "
                        "from the cells after Global refinements, before "
                        "refining) stops with exit 1 and says how much it "
                        "would need. 0: this machine's memory; negative: no "
                        "guard.",
                        Patterns::Double());
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

    double
    SceneGenerator::estimated_memory(const double unknowns,
                                     const double unknowns_per_cell)
    {
      // About 200 MB for the libraries and 3 KB per unknown for Q1 (mesh,
      // sparse tangent and its MUMPS factors: 255 MB at 26k unknowns,
      // 495 MB at 104k on the airbeam), growing like the nonzeros per row
      // (Q2: about 2.5 times Q1's) and slowly with the fill-in of the
      // factorization (n log n).
      const double per_unknown =
        3e3 * (unknowns_per_cell > 3.5 ? 2.5 : 1.)
        * (1. + 0.1 * std::log2(std::max(unknowns / 1e5, 1.)));
      return 2e8 + per_unknown * unknowns;
    }

    void
    SceneGenerator::create_triangulation(
      parallel::distributed::Triangulation<2, 3> &tria,
      const std::string                          &saved,
      const double                                unknowns_per_cell) const
    {
      Triangulation<2, 3> coarse;
      surface->create_coarse_mesh(coarse);
      const std::string where = geometry_type == "gmsh"
                                  ? "Geometry/gmsh/Mesh file"
                                  : "Geometry/" + geometry_type;
      // Lengths are in metres: a coarse mesh of no extent or of an
      // astronomical one is a typing error (e.g. Radius = 1e300).
      const auto   box    = GridTools::compute_bounding_box(coarse);
      const double extent = box.get_boundary_points().first.distance(
        box.get_boundary_points().second);
      if (!(std::isfinite(extent) && extent >= 1e-6 && extent <= 1e6))
        {
          std::ostringstream m;
          m << "the membrane spans " << std::setprecision(3) << extent
            << " m; lengths are in metres (1e-6 m to 1e6 m)";
          throw InputError(where, m.str());
        }
      if (saved.empty() && memory_limit >= 0.)
        {
          const double cells =
            coarse.n_active_cells() * std::pow(4., refinements);
          const double unknowns = cells * unknowns_per_cell;
          const double need     = estimated_memory(unknowns, unknowns_per_cell);
          double       have     = memory_limit * 1e9;
          if (have == 0.)
            have = static_cast<double>(sysconf(_SC_PHYS_PAGES))
                   * static_cast<double>(sysconf(_SC_PAGE_SIZE));
          if (need > have)
            {
              std::ostringstream m;
              m << std::setprecision(3) << refinements << " refinements of "
                << coarse.n_active_cells() << " coarse cells make " << cells
                << " cells and about " << unknowns
                << " unknowns, which need about " << need / 1e9
                << " GB of memory; "
                << (memory_limit > 0. ? "the limit is " : "this machine has ")
                << have / 1e9
                << " GB (lower Global refinements, or raise Geometry/Memory "
                   "limit if the estimate is wrong)";
              throw InputError("Geometry/Global refinements", m.str());
            }
        }
      tria.copy_triangulation(coarse);
      // Manifolds: curved surfaces and rims follow the true geometry.
      surface->attach_manifolds(tria);
      if (saved.empty())
        {
          tria.refine_global(refinements);
          return;
        }
      // p4est aborts on a file it cannot read: check first, on all ranks.
      bool readable = true;
      if (Utilities::MPI::this_mpi_process(tria.get_communicator()) == 0)
        readable = std::ifstream(saved).good()
                   && std::ifstream(saved + ".info").good()
                   && std::ifstream(saved + "_fixed.data").good();
      readable =
        Utilities::MPI::broadcast(tria.get_communicator(), readable, 0);
      check_input(readable,
                  "--restart " + saved.substr(0, saved.rfind('/')),
                  "has no readable mesh ('" + saved
                    + "' and its .info and "
                      "_fixed.data files)");
      unsigned int coarse_cells = 0;
      {
        std::ifstream info(saved + ".info");
        std::string   header;
        unsigned int  version = 0, n_procs = 0, fixed = 0, variable = 0;
        std::getline(info, header);
        info >> version >> n_procs >> fixed >> variable >> coarse_cells;
      }
      check_input(coarse_cells == tria.n_cells(0),
                  "--restart " + saved.substr(0, saved.rfind('/')),
                  "the checkpoint's mesh has " + std::to_string(coarse_cells)
                    + " coarse cells, this input's "
                    + std::to_string(tria.n_cells(0))
                    + ": it belongs to another geometry");
      tria.load(saved);
    }
  } // namespace geometry
} // namespace pneuma
