#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

#include <pneuma/core/input_error.h>
#include <pneuma/loads/boundary_conditions.h>
#include <pneuma/loads/loads.h>

#include <Epetra_FEVector.h>

namespace pneuma
{
  namespace loads
  {
    namespace
    {
      std::array<bool, 3>
      parse_components(const std::string &text, const std::string &path)
      {
        std::array<bool, 3> mask = {{false, false, false}};
        const std::string   t    = Utilities::trim(text);
        check_input(!t.empty(), path, "no components given (use x, y, z)");
        for (const char c : t)
          {
            check_input(c == 'x' || c == 'y' || c == 'z',
                        path,
                        "component '" + std::string(1, c)
                          + "' is not one of x, y, z");
            mask[c - 'x'] = true;
          }
        return mask;
      }
    } // namespace

    BoundaryConditions::BoundaryConditions()
      : displacement_function(std::make_unique<Functions::ParsedFunction<3>>(3))
    {
    }

    void
    BoundaryConditions::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      prm.add_parameter("Fixed boundaries",
                        text.fixed_boundaries,
                        "Clamped edges and symmetry planes: "
                        "'id: components; ...', e.g. '0: xyz; 2: y'.",
                        Patterns::Anything());
      prm.add_parameter("Fixed points",
                        text.fixed_points,
                        "Supports at the mesh vertex nearest to a point [m]: "
                        "'x, y, z: components; ...', e.g. '0,0,0: xyz'.",
                        Patterns::Anything());
      prm.add_parameter("Fixed regions",
                        text.fixed_regions,
                        "Material ids whose nodes are all held: 'ids' "
                        "(every component: rigid, fixed regions such as "
                        "clamped end plates) or 'ids: components; ...', "
                        "e.g. '0: z' keeps a flat sheet in its plane (a "
                        "plane-stress analysis).",
                        Patterns::Anything());
      prm.add_parameter("Prescribed displacement boundaries",
                        text.displaced_boundaries,
                        "Boundary ids whose displacement follows the "
                        "function 'Prescribed displacement' of (x,y,z,t).",
                        Patterns::List(Patterns::Integer(0)));
      prm.add_parameter("Prescribed displacement regions",
                        text.displaced_regions,
                        "Material ids whose nodes all follow the function "
                        "'Prescribed displacement' of (x,y,z,t) (e.g. a "
                        "piston or a moving end plate).",
                        Patterns::List(Patterns::Integer(0)));
      declare_function(prm, "Prescribed displacement", 3, "0; 0; 0");
      prm.leave_subsection();
    }

    void
    BoundaryConditions::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      fixed_boundaries.clear();
      for (const auto &item :
           Utilities::split_string_list(text.fixed_boundaries, ';'))
        {
          const std::string path = "Boundary conditions/Fixed boundaries";
          const auto        kv   = Utilities::split_string_list(item, ':');
          check_input(kv.size() == 2,
                      path,
                      "'" + item + "' is not of the form 'id: components'");
          const auto ids = parse_id_list(kv[0], path);
          for (const auto id : ids)
            fixed_boundaries[id] = parse_components(kv[1], path);
        }
      fixed_points.clear();
      for (const auto &item :
           Utilities::split_string_list(text.fixed_points, ';'))
        {
          const std::string path = "Boundary conditions/Fixed points";
          const auto        kv   = Utilities::split_string_list(item, ':');
          check_input(kv.size() == 2,
                      path,
                      "'" + item
                        + "' is not of the form 'x, y, z: components'");
          const Point<3> p = parse_point(kv[0], path);
          fixed_points.emplace_back(p, parse_components(kv[1], path));
        }
      fixed_regions.clear();
      for (const auto &item :
           Utilities::split_string_list(text.fixed_regions, ';'))
        {
          const std::string path = "Boundary conditions/Fixed regions";
          const auto        kv   = Utilities::split_string_list(item, ':');
          check_input(kv.size() == 1 || kv.size() == 2,
                      path,
                      "'" + item
                        + "' is not of the form 'ids' or 'ids: "
                          "components'");
          const std::array<bool, 3> mask =
            kv.size() == 2 ? parse_components(kv[1], path)
                           : std::array<bool, 3>{{true, true, true}};
          for (const auto id : parse_id_list(kv[0], path))
            fixed_regions[id] = mask;
        }
      const auto dr =
        parse_id_list(text.displaced_regions,
                      "Boundary conditions/Prescribed displacement regions");
      displaced_regions = std::set<types::material_id>(dr.begin(), dr.end());
      const auto db =
        parse_id_list(text.displaced_boundaries,
                      "Boundary conditions/Prescribed displacement boundaries");
      displaced_boundaries = std::set<types::boundary_id>(db.begin(), db.end());
      parse_function(prm,
                     *displacement_function,
                     "Prescribed displacement",
                     "Boundary conditions/Prescribed displacement");
      prm.leave_subsection();
    }

    void
    BoundaryConditions::check_against_mesh(
      const DoFHandler<2, 3> &dof_handler) const
    {
      std::set<unsigned int> boundary_ids, material_ids;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            material_ids.insert(cell->material_id());
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                boundary_ids.insert(cell->face(f)->boundary_id());
          }
      const MPI_Comm comm           = dof_handler.get_communicator();
      auto           all_boundaries = Utilities::MPI::compute_set_union(
        std::vector<unsigned int>(boundary_ids.begin(), boundary_ids.end()),
        comm);
      auto all_materials = Utilities::MPI::compute_set_union(
        std::vector<unsigned int>(material_ids.begin(), material_ids.end()),
        comm);
      const std::set<unsigned int> b(all_boundaries.begin(),
                                     all_boundaries.end());
      const std::set<unsigned int> m(all_materials.begin(),
                                     all_materials.end());
      for (const auto &fb : fixed_boundaries)
        check_input(b.count(fb.first),
                    "Boundary conditions/Fixed boundaries",
                    "the mesh has no boundary with id "
                      + std::to_string(fb.first));
      for (const auto id : displaced_boundaries)
        check_input(b.count(id),
                    "Boundary conditions/Prescribed displacement boundaries",
                    "the mesh has no boundary with id " + std::to_string(id));
      for (const auto &[id, mask] : fixed_regions)
        check_input(m.count(id),
                    "Boundary conditions/Fixed regions",
                    "the mesh has no cells in region " + std::to_string(id));
      for (const auto id : displaced_regions)
        check_input(m.count(id),
                    "Boundary conditions/Prescribed displacement regions",
                    "the mesh has no cells in region " + std::to_string(id));
    }

    std::map<types::global_dof_index, double>
    BoundaryConditions::prescribed_dofs(const Mapping<2, 3>    &mapping,
                                        const DoFHandler<2, 3> &dof_handler,
                                        const double            t) const
    {
      std::map<types::global_dof_index, double> values;
      const Functions::ZeroFunction<3>          zero(3);

      for (const auto &fb : fixed_boundaries)
        {
          const ComponentMask mask(
            std::vector<bool>(fb.second.begin(), fb.second.end()));
          VectorTools::interpolate_boundary_values(
            mapping, dof_handler, fb.first, zero, values, mask);
        }
      if (!displaced_boundaries.empty())
        {
          displacement_function->set_time(t);
          std::map<types::boundary_id, const Function<3> *> functions;
          for (const auto id : displaced_boundaries)
            functions[id] = displacement_function.get();
          VectorTools::interpolate_boundary_values(mapping,
                                                   dof_handler,
                                                   functions,
                                                   values);
        }

      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          if (const auto region = fixed_regions.find(cell->material_id());
              region != fixed_regions.end())
            {
              const auto &fe = cell->get_fe();
              dofs.resize(fe.n_dofs_per_cell());
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (region->second[fe.system_to_component_index(i).first])
                  values[dofs[i]] = 0.;
            }

      if (!displaced_regions.empty())
        {
          displacement_function->set_time(t);
          const auto    &fe          = dof_handler.get_fe();
          const auto    &unit_points = fe.get_unit_support_points();
          Vector<double> value(3);
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (!cell->is_artificial()
                && displaced_regions.count(cell->material_id()))
              {
                dofs.resize(fe.n_dofs_per_cell());
                cell->get_dof_indices(dofs);
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  {
                    const Point<3> x =
                      mapping.transform_unit_to_real_cell(cell, unit_points[i]);
                    values[dofs[i]] = displacement_function->value(
                      x, fe.system_to_component_index(i).first);
                  }
              }
        }

      // Point supports: the nearest vertex over all ranks.
      for (const auto &fp : fixed_points)
        {
          double local_min = std::numeric_limits<double>::max();
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (!cell->is_artificial())
              for (const auto v : cell->vertex_indices())
                local_min =
                  std::min(local_min, cell->vertex(v).distance(fp.first));
          const double global_min =
            Utilities::MPI::min(local_min, dof_handler.get_communicator());
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (!cell->is_artificial())
              for (const auto v : cell->vertex_indices())
                if (cell->vertex(v).distance(fp.first)
                    <= global_min * (1. + 1e-12) + 1e-14)
                  for (unsigned int c = 0; c < 3; ++c)
                    if (fp.second[c])
                      values[cell->vertex_dof_index(v, c)] = 0.;
        }
      return values;
    }

    void
    BoundaryConditions::add_update_constraints(
      const DoFHandler<2, 3>                     &dof_handler,
      const std::set<types::global_dof_index>    &rigid_slaves,
      const std::vector<types::global_dof_index> &rigid_masters,
      const std::set<types::global_dof_index>    &junction_copies,
      AffineConstraints<double>                  &constraints) const
    {
      held = HeldDofs(); // (a new mesh or numbering)
      // The mapping does not matter for homogeneous values.
      const auto values =
        prescribed_dofs(StaticMappingQ1<2, 3>::mapping, dof_handler, 0.);
      // Plate masters prescribed on any rank (a rank need not see them).
      std::vector<int> held(rigid_masters.size());
      for (unsigned int k = 0; k < rigid_masters.size(); ++k)
        held[k] = values.count(rigid_masters[k]) ? 1 : 0;
      Utilities::MPI::max(held, dof_handler.get_communicator(), held);
      std::set<types::global_dof_index> held_masters;
      for (unsigned int k = 0; k < rigid_masters.size(); ++k)
        if (held[k])
          held_masters.insert(rigid_masters[k]);
      bool conflict = false;
      for (const auto &v : values)
        {
          // A junction copy follows its master (which a support at the
          // same place holds anyway).
          if (junction_copies.count(v.first))
            continue;
          if (rigid_slaves.count(v.first))
            {
              // Redundant, not a conflict, where the plate's own copy of a
              // junction vertex is its prescribed master (a support at the
              // plate's reference node when that is a junction vertex).
              bool redundant = constraints.is_constrained(v.first);
              if (redundant)
                for (const auto &e :
                     *constraints.get_constraint_entries(v.first))
                  if (std::abs(e.second) > 1e-12
                      && !held_masters.count(e.first))
                    redundant = false;
              conflict = conflict || !redundant;
            }
          else if (constraints.can_store_line(v.first)
                   && !constraints.is_constrained(v.first))
            constraints.add_line(v.first);
        }
      check_input(!Utilities::MPI::logical_or(conflict,
                                              dof_handler.get_communicator()),
                  "Boundary conditions",
                  "a fixed point, boundary or region lies inside a rigid "
                  "region; support a rigid plate at its reference node (the "
                  "vertex nearest its centroid)");
    }

    void
    BoundaryConditions::set_prescribed_values(
      const Mapping<2, 3>    &mapping,
      const DoFHandler<2, 3> &dof_handler,
      const double            t,
      LA::Vector             &solution) const
    {
      const bool static_supports =
        displaced_boundaries.empty() && displaced_regions.empty();
      const types::global_cell_index n_cells =
        dof_handler.get_triangulation().n_global_active_cells();
      if (static_supports
          && (held.dof_handler != &dof_handler
              || held.n_dofs != dof_handler.n_dofs()
              || held.n_cells != n_cells))
        {
          held.dof_handler = &dof_handler;
          held.n_dofs      = dof_handler.n_dofs();
          held.n_cells     = n_cells;
          held.owned.clear();
          for (const auto &v : prescribed_dofs(mapping, dof_handler, t))
            if (solution.locally_owned_elements().is_element(v.first))
              held.owned.push_back(v.first);
        }
      // Every value is written in place on the rank that owns it: no
      // exchange (a compress plans one collectively at every call, and an
      // explicit step sets the prescribed values at every step).
      Epetra_FEVector &v     = solution.trilinos_vector();
      const auto       write = [&v](const types::global_dof_index i,
                              const double                  value) {
        const int local =
          v.Map().LID(static_cast<TrilinosWrappers::types::int_type>(i));
        AssertThrow(local >= 0, ExcInternalError());
        v[0][local] = value;
      };
      if (static_supports)
        for (const auto i : held.owned)
          write(i, 0.);
      else
        for (const auto &p : prescribed_dofs(mapping, dof_handler, t))
          if (solution.locally_owned_elements().is_element(p.first))
            write(p.first, p.second);
    }
  } // namespace loads
} // namespace pneuma
