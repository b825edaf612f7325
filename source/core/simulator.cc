#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/sparsity_tools.h>

#include <pneuma/core/input_error.h>
#include <pneuma/core/share_constraints.h>

#include "simulator_impl.h"

#include <cmath>
#include <iomanip>

namespace pneuma
{
  // ------------------------------------------------------------------
  // Construction and parameters
  // ------------------------------------------------------------------
  Simulator::Impl::Impl(const MPI_Comm comm)
    : comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
    , triangulation(comm,
                    Triangulation<2, 3>::limit_level_difference_at_vertices)
    , dof_handler(triangulation)
    , assembler(geometry, materials, loads)
    , chamber_assembler(geometry, chamber_parameters)
    , chamber_system(chamber_parameters, chamber_assembler)
    , cable_system(cable_parameters, loads)
    , contact_system(contact_parameters, geometry, cable_system)
  {
  }

  Simulator::Simulator(const MPI_Comm comm)
    : impl(std::make_unique<Impl>(comm))
  {
  }

  Simulator::~Simulator() = default;

  void
  Simulator::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretisation");
    prm.declare_entry("Polynomial degree",
                      "1",
                      Patterns::Integer(1, 2),
                      "Degree of the FE_Q displacement; the mapping of the "
                      "reference surface has the same degree.");
    prm.leave_subsection();
    geometry::SceneGenerator::declare_parameters(prm);
    geometry::AdaptiveRefinement::declare_parameters(prm);
    membrane::MaterialRegions::declare_parameters(prm);
    loads::Loads::declare_parameters(prm);
    loads::BoundaryConditions::declare_parameters(prm);
    loads::RigidRegions::declare_parameters(prm);
    solvers::LoadStepping::declare_parameters(prm);
    solvers::NewtonSolver::declare_parameters(prm);
    solvers::LinearSolver::declare_parameters(prm);
    chambers::ChamberParameters::declare_parameters(prm);
    cables::CableParameters::declare_parameters(prm);
    contact::ContactParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
  }

  void
  Simulator::parse_parameters(ParameterHandler &prm)
  {
    Impl &s = *impl;
    prm.enter_subsection("Discretisation");
    s.degree = prm.get_integer("Polynomial degree");
    prm.leave_subsection();
    s.geometry.parse_parameters(prm);
    s.refinement.parse_parameters(prm);
    s.materials.parse_parameters(prm);
    s.loads.parse_parameters(prm);
    s.boundary_conditions.parse_parameters(prm);
    s.rigid_regions.parse_parameters(prm);
    s.stepping.parse_parameters(prm);
    s.newton.parse_parameters(prm);
    s.linear_solver.parse_parameters(prm);
    s.chamber_parameters.parse_parameters(prm);
    s.cable_parameters.parse_parameters(prm);
    s.contact_parameters.parse_parameters(prm, s.cable_parameters.size());
    s.output.parse_parameters(prm);
    if (!s.contact_parameters.empty())
      check_input(s.has_membrane(),
                  "Contact/Number of pairs",
                  "contact needs a membrane (Geometry/Type is none)");
    if (!s.has_membrane())
      {
        check_input(!s.cable_parameters.empty(),
                    "Geometry/Type",
                    "none (no membrane) needs at least one cable "
                    "(Cables/Number of cables)");
        check_input(s.chamber_parameters.empty(),
                    "Chambers/Number of chambers",
                    "chambers need a membrane (Geometry/Type is none)");
      }
    if (s.output.quiet)
      s.pcout.set_condition(false);
  }

  // ------------------------------------------------------------------
  // Setup
  // ------------------------------------------------------------------
  void
  Simulator::setup()
  {
    Impl              &s = *impl;
    TimerOutput::Scope t(s.timer, "setup");
    if (!s.has_membrane())
      {
        s.setup_system();
        return;
      }
    s.geometry.create_triangulation(s.triangulation);
    s.fe      = std::make_unique<FESystem<2, 3>>(FE_Q<2, 3>(s.degree), 3);
    // The mapped support points of every cell are computed once from the
    // manifolds and cached: FEValues::reinit no longer calls the manifolds.
    s.cache_mapping();

    // Every region a cell is in must have a valid material; every id
    // named in the input must exist in the mesh.
    std::set<unsigned int> local_ids;
    for (const auto &cell : s.triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        local_ids.insert(cell->material_id());
    const auto all_ids = Utilities::MPI::compute_set_union(
      std::vector<unsigned int>(local_ids.begin(), local_ids.end()), s.comm);
    for (const auto id : all_ids)
      (void)s.materials[id];
    for (const auto id : s.loads.pressure_regions())
      check_input(std::find(all_ids.begin(), all_ids.end(), id)
                    != all_ids.end(),
                  "Loads/Pressure regions",
                  "the mesh has no cells in region " + std::to_string(id));

    s.setup_system();
    s.boundary_conditions.check_against_mesh(s.dof_handler);
    // Junction copies are tied vertex by vertex: both sides of a junction
    // would have to be refined alike.
    check_input(s.refinement.cycles() == 0 || s.junction_ties.ties.empty(),
                "Adaptive refinement/Cycles",
                "meshes with junction lines (more than two cells on a line) "
                "cannot be refined adaptively yet; refine the Gmsh mesh "
                "instead");
    if (!s.chamber_parameters.empty())
      s.chamber_assembler.check_chambers();
  }

  void
  Simulator::Impl::setup_system()
  {
    // Global numbering: the membrane dofs, then the cable dofs (owned by
    // rank 0), then nothing else; the chamber unknowns are the border.
    types::global_dof_index n_membrane = 0;
    IndexSet                membrane_owned, membrane_relevant;
    if (has_membrane())
      {
        dof_handler.distribute_dofs(*fe);
        n_membrane        = dof_handler.n_dofs();
        membrane_owned    = dof_handler.locally_owned_dofs();
        membrane_relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);
      }
    cable_system.setup(n_membrane, comm);
    const types::global_dof_index n_total = n_membrane + cable_system.n_dofs();
    const IndexSet cable_owned = cable_system.locally_owned_dofs(n_total);
    locally_owned = IndexSet(n_total);
    locally_owned.add_indices(membrane_owned);
    locally_owned.add_indices(cable_owned);
    locally_relevant = IndexSet(n_total);
    locally_relevant.add_indices(membrane_relevant);
    locally_relevant.add_indices(cable_owned);
    if (has_membrane())
      {
        // Rigid plates couple every plate dof to three master nodes, which
        // every rank must see.
        if (!rigid_regions.empty())
          locally_relevant.add_indices(
            rigid_regions.master_dofs(*mapping, dof_handler));
        // Junction copies are tied to a master that every rank must see.
        auto master_regions = rigid_regions.all_ids();
        for (const auto id : boundary_conditions.prescribed_regions())
          master_regions.insert(id);
        IndexSet relevant_membrane(n_membrane);
        relevant_membrane.add_indices(membrane_relevant);
        junction_ties.find(*mapping, dof_handler, master_regions, relevant_membrane);
        for (const auto i : junction_ties.masters)
          locally_relevant.add_index(i);
        // Contact: every rank sees the mid-lines of the paired cables.
        contact_system.setup(*mapping, dof_handler, comm);
        locally_relevant.add_indices(contact_system.cable_dofs(n_total));
        contact_system.update_candidates(nullptr);
      }
    make_constraints();

    solution.reinit(locally_owned, comm);
    external.reinit(locally_owned, comm);
    ghosted.reinit(locally_owned, locally_relevant, comm);
    if (has_membrane())
      {
        assembler.reinit(*mapping, dof_handler, degree);
        chamber_assembler.reinit(*mapping, dof_handler, degree);
      }
    build_matrices();

    // AMG near-null space: the three rigid translations, i.e. one
    // indicator per displacement component over the owned dofs.
    std::vector<std::vector<bool>> modes(
      3, std::vector<bool>(locally_owned.n_elements()));
    for (unsigned int c = 0; c < 3; ++c)
      {
        IndexSet dofs(n_total);
        if (has_membrane())
          {
            std::vector<bool> mask(3, false);
            mask[c] = true;
            dofs.add_indices(
              DoFTools::extract_dofs(dof_handler, ComponentMask(mask)));
          }
        for (unsigned int k = 0; k < locally_owned.n_elements(); ++k)
          {
            const auto i = locally_owned.nth_index_in_set(k);
            modes[c][k]  = i < n_membrane ?
                             dofs.is_element(i) :
                             cable_system.translation_component(i) == int(c);
          }
      }
    linear_solver.set_constant_modes(modes);

    // AMG near-null space of a free membrane: the three translations and
    // three rotations about the centroid of the reference surface, on the
    // membrane dofs (cable dofs get the translations only).
    if (has_membrane() && linear_solver.type() == "amg")
      {
        std::map<types::global_dof_index, Point<3>> support;
        DoFTools::map_dofs_to_support_points(*mapping, dof_handler, support);
        Point<3> centre;
        double   count = 0.;
        for (const auto &[i, x] : support)
          if (membrane_owned.is_element(i))
            {
              centre += x;
              count += 1.;
            }
        for (unsigned int d = 0; d < 3; ++d)
          centre[d] = Utilities::MPI::sum(centre[d], comm);
        centre /= std::max(1., Utilities::MPI::sum(count, comm));
        // The translations are the component masks above; the rotation
        // about axis a moves a dof of component c by (e_a x r)_c.
        std::vector<std::vector<double>> rigid(
          6, std::vector<double>(locally_owned.n_elements(), 0.));
        for (unsigned int k = 0; k < locally_owned.n_elements(); ++k)
          for (unsigned int c = 0; c < 3; ++c)
            if (modes[c][k])
              {
                rigid[c][k]  = 1.;
                const auto i = locally_owned.nth_index_in_set(k);
                if (i >= n_membrane)
                  continue;
                const Tensor<1, 3> r = support.at(i) - centre;
                for (unsigned int a = 0; a < 3; ++a)
                  {
                    Tensor<1, 3> e;
                    e[a]            = 1.;
                    rigid[3 + a][k] = cross_product_3d(e, r)[c];
                  }
              }
        linear_solver.set_rigid_body_modes(rigid);
      }
    linear_solver.reset();
  }

  void
  Simulator::Impl::build_matrices()
  {
    DynamicSparsityPattern dsp(locally_relevant);
    if (has_membrane())
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    cable_system.add_sparsity(dsp, constraints);
    contact_system.add_sparsity(dsp, constraints);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned,
                                               comm,
                                               locally_relevant);
    linear_solver.reset();
    tangent.reinit(locally_owned, locally_owned, dsp, comm);
    laplacian.reinit(locally_owned, locally_owned, dsp, comm);
    if (has_membrane())
      assembler.surface_laplacian(constraints, laplacian);
    cable_system.assemble_regularisation(constraints, laplacian);
  }

  void
  Simulator::Impl::refine_mesh()
  {
    ghosted = solution;
    refinement.refine(*mapping, dof_handler, ghosted, triangulation);
    cache_mapping();
    setup_system();
  }

  void
  Simulator::Impl::cache_mapping()
  {
    auto cache = std::make_unique<MappingQCache<2, 3>>(degree);
    cache->initialize(MappingQ<2, 3>(degree), triangulation);
    mapping = std::move(cache);
  }

  IndexSet
  Simulator::Impl::shared_masters() const
  {
    // Masters that dependent dofs on any rank refer to: junction masters
    // and the plates' master nodes (share_constraints.h).
    IndexSet result(locally_relevant.size());
    result.add_indices(junction_ties.masters);
    for (const auto d : rigid_regions.plate_master_dofs())
      result.add_index(d);
    result.compress();
    return result;
  }

  void
  Simulator::Impl::make_constraints()
  {
    // Kinematic constraints first (hanging nodes, rigid plates), then the
    // prescribed components of the Newton update.
    kinematic_constraints.clear();
    kinematic_constraints.reinit(locally_relevant);
    if (has_membrane())
      {
        DoFTools::make_hanging_node_constraints(dof_handler,
                                                kinematic_constraints);
        rigid_regions.add_constraints(*mapping,
                                      dof_handler,
                                      kinematic_constraints);
        share_constraint_lines(kinematic_constraints,
                               shared_masters(),
                               locally_owned,
                               comm);
        junction_ties.add_constraints(kinematic_constraints);
      }
    kinematic_constraints.close();

    constraints.clear();
    constraints.reinit(locally_relevant);
    constraints.merge(kinematic_constraints);
    if (has_membrane())
      boundary_conditions.add_update_constraints(dof_handler,
                                                 rigid_regions.slave_dofs(),
                                                 rigid_regions.plate_master_dofs(),
                                                 junction_ties.copies(),
                                                 constraints);
    cable_system.add_support_constraints(constraints);
    if (has_membrane())
      share_constraint_lines(constraints, shared_masters(), locally_owned, comm);
    constraints.close();
  }

  // ------------------------------------------------------------------
  // The nonlinear problem seen by Newton
  // ------------------------------------------------------------------
  void
  Simulator::Impl::assemble(const solvers::BorderedVector &u,
                            solvers::BorderedVector       &residual)
  {
    TimerOutput::Scope t(timer, "assembly");
    ghosted = u.field;
    membrane::AssemblyRequest request;
    request.time     = current_time;
    request.residual = &residual.field;
    request.tangent  = &tangent;
    request.external = &external;
    // The cable block and the contact couple after the membrane (and
    // chamber) terms.
    const auto add_cables_and_contact = [&]() {
      if (!cable_system.empty())
        {
          TimerOutput::Scope tc(timer, "cable assembly");
          cable_system.assemble(current_time,
                                ghosted,
                                constraints,
                                &tangent,
                                &residual.field,
                                &external);
        }
      if (!contact_system.empty())
        {
          TimerOutput::Scope tc(timer, "contact");
          contact_system.assemble(ghosted,
                                  constraints,
                                  &tangent,
                                  &residual.field);
        }
    };
    if (!has_membrane())
      {
        tangent          = 0.;
        residual.field   = 0.;
        external         = 0.;
      }
    else if (chamber_parameters.empty())
      assembler.assemble(ghosted, constraints, request);
    if (chamber_parameters.empty())
      {
        add_cables_and_contact();
        residual.border.reinit(0);
        return;
      }
    // The chamber terms join the membrane's cell matrices.
    const auto chamber_loads = chamber_system.loads(u.border);
    chambers::ChamberAssembler::Pass pass(
      chamber_assembler, ghosted, constraints, chamber_loads, chamber_measures, true);
    request.cell_terms = [&pass](const auto &cell,
                                 const auto &fe_values,
                                 const auto &local_u,
                                 auto       *cell_matrix,
                                 auto       *cell_residual,
                                 const auto &dof_indices) {
      pass.cell(
        cell, local_u, cell_matrix, cell_residual, dof_indices, &fe_values);
    };
    assembler.assemble(ghosted, constraints, request);
    pass.finish();
    add_cables_and_contact();
    chamber_system.evaluate(u.border, chamber_measures, residual.border);
  }

  void
  Simulator::Impl::solve_linear(const double                   shift,
                                const solvers::BorderedVector &rhs,
                                solvers::BorderedVector       &du)
  {
    TimerOutput::Scope t(timer, "linear solve");
    if (shift > 0.)
      tangent.add(shift, laplacian);
    linear_solver.factorize(tangent);
    if (chamber_parameters.empty())
      {
        linear_solver.solve(tangent, du.field, rhs.field);
        du.border.reinit(0);
      }
    else
      chamber_system.solve(linear_solver, tangent, rhs, du);
    constraints.distribute(du.field);
    ++n_linear_solves;
  }

  void
  Simulator::Impl::apply_kinematic_constraints()
  {
    // Dependent dofs (rigid plates, junction copies) follow their masters
    // after prescribed values have changed.
    if (rigid_regions.empty() && junction_ties.ties.empty())
      return;
    ghosted = solution;
    for (const auto i : locally_owned)
      if (kinematic_constraints.is_constrained(i))
        {
          double v = kinematic_constraints.get_inhomogeneity(i);
          for (const auto &e : *kinematic_constraints.get_constraint_entries(i))
            v += e.second * ghosted[e.first];
          solution[i] = v;
        }
    solution.compress(VectorOperation::insert);
  }

  double
  Simulator::Impl::shift_scale()
  {
    if (!has_membrane())
      {
        // Cables only: a hanging, unstressed cable is a mechanism, and the
        // shift s of the continuation acts as an axial force s in it. Under
        // a load W (nodal loads f) a first regularised step deflects the
        // cable by about W L/(8 s), i.e. turns it by W/(2 s), which
        // stretches it by (W/(2 s))^2/2 and adds an axial force EA times
        // that; the step is accepted if that error stays below the nodal
        // load f: s >= W sqrt(EA/(8 f)). Nor should s be below the total
        // load, the order of the forces the cable will carry.
        double load = 0., f_max = 0.;
        for (const auto i : locally_owned)
          {
            load += std::abs(external[i]);
            f_max = std::max(f_max, std::abs(external[i]));
          }
        load  = Utilities::MPI::sum(load, comm);
        f_max = Utilities::MPI::max(f_max, comm);
        const double s0 =
          f_max > 0. ?
            std::max(load,
                     load * std::sqrt(cable_system.axial_stiffness() /
                                      (8. * f_max))) :
            0.;
        if (s0 > 0. && newton.regularisation_factor() > 0.)
          return s0 / newton.regularisation_factor();
      }
    // The membrane sets the scale (stiff cables must not slow its
    // continuation down).
    const types::global_dof_index n_membrane =
      has_membrane() ? dof_handler.n_dofs() : locally_owned.size();
    double k_sum = 0., m_sum = 0.;
    for (const auto i : locally_owned)
      if (i < n_membrane && !constraints.is_constrained(i))
        {
          k_sum += std::abs(tangent.diag_element(i));
          m_sum += laplacian.diag_element(i);
        }
    k_sum = Utilities::MPI::sum(k_sum, comm);
    m_sum = Utilities::MPI::sum(m_sum, comm);
    return m_sum > 0. ? k_sum / m_sum : 0.;
  }

  void
  Simulator::Impl::laplacian_vmult(const solvers::BorderedVector &x,
                                   solvers::BorderedVector       &y)
  {
    laplacian.vmult(y.field, x.field);
    // Rows of dependent and prescribed dofs carry only the diagonal that
    // the condensation leaves; the residual has no such rows, and neither
    // may its regularisation (else the regularised residual keeps a part
    // that no update can remove).
    constraints.set_zero(y.field);
    y.border.reinit(x.border.size());
  }

  double
  Simulator::Impl::load_norm()
  {
    const double f = external.l2_norm();
    const double c =
      chamber_parameters.empty() ? 0. : chamber_system.force_scale();
    // Cables: the largest axial force at the current state (Newton assembles
    // before it asks), so that a prestress-driven step without external
    // load has a force scale.
    double n = 0.;
    if (!cable_system.empty())
      {
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          for (const auto &r : cable_system.reports(current_time, ghosted))
            n = std::max({n, std::abs(r.max_force), std::abs(r.min_force)});
        n = Utilities::MPI::max(n, comm);
      }
    return std::sqrt(f * f + c * c + n * n);
  }

  std::vector<CableState>
  Simulator::Impl::cable_states()
  {
    // Computed on rank 0 (it owns the cable dofs), then shared.
    constexpr unsigned int  n_values = 21;
    std::vector<double>     packed(n_values * cable_parameters.size(), 0.);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        const auto reports = cable_system.reports(current_time, solution);
        for (unsigned int k = 0; k < reports.size(); ++k)
          {
            const auto &r = reports[k];
            double     *v = &packed[n_values * k];
            v[0] = r.max_force, v[1] = r.min_force, v[2] = r.length;
            v[3] = r.max_bending, v[4] = r.max_torsion;
            v[20] = r.end_rotation;
            for (unsigned int c = 0; c < 3; ++c)
              {
                v[5 + c]  = r.start_reaction[c];
                v[8 + c]  = r.end_reaction[c];
                v[11 + c] = r.start_displacement[c];
                v[14 + c] = r.end_displacement[c];
                v[17 + c] = r.mid_displacement[c];
              }
          }
      }
    if (!packed.empty())
      MPI_Bcast(packed.data(), packed.size(), MPI_DOUBLE, 0, comm);
    std::vector<CableState> states(cable_parameters.size());
    for (unsigned int k = 0; k < states.size(); ++k)
      {
        const double *v = &packed[n_values * k];
        auto         &s = states[k];
        s.max_force = v[0], s.min_force = v[1], s.length = v[2];
        s.max_bending = v[3], s.max_torsion = v[4];
        s.end_rotation = v[20];
        for (unsigned int c = 0; c < 3; ++c)
          {
            s.start_reaction[c]     = v[5 + c];
            s.end_reaction[c]       = v[8 + c];
            s.start_displacement[c] = v[11 + c];
            s.end_displacement[c]   = v[14 + c];
            s.mid_displacement[c]   = v[17 + c];
          }
      }
    return states;
  }

  void
  Simulator::Impl::refresh_contact()
  {
    if (contact_system.empty())
      return;
    ghosted = solution;
    contact_system.assemble(ghosted, constraints, nullptr, nullptr);
  }

  std::vector<ContactState>
  Simulator::Impl::contact_states() const
  {
    std::vector<ContactState> states;
    for (const auto &r : contact_system.reports())
      {
        ContactState c;
        c.active_points   = r.active_points;
        c.points          = r.points;
        c.total_force     = r.total_force;
        c.max_penetration = r.max_penetration;
        c.force           = r.force;
        c.slip_points     = r.slip_points;
        c.friction_force  = r.friction_force;
        states.push_back(c);
      }
    return states;
  }

  std::vector<ChamberState>
  Simulator::Impl::chamber_states() const
  {
    std::vector<ChamberState> states;
    for (const auto &r : chamber_system.reports())
      {
        ChamberState c;
        c.pressure          = r.pressure;
        c.absolute_pressure = r.absolute_pressure;
        c.volume            = r.volume;
        c.gas_volume        = r.gas_volume;
        c.liquid_volume     = r.liquid_volume;
        c.level             = r.level;
        c.wetted_area       = r.wetted_area;
        c.gas_amount        = r.gas_amount;
        c.pv_kappa          = r.pv_kappa;
        states.push_back(c);
      }
    return states;
  }

  // ------------------------------------------------------------------
  // Load stepping through the stages
  // ------------------------------------------------------------------
  RunSummary
  Simulator::run()
  {
    Impl &s = *impl;
    if (s.refinement.cycles() == 0 || !s.has_membrane())
      return s.run();

    // Convergence study: the load path on each adapted mesh, outputs per
    // cycle, one table of all cycles.
    const std::string base = s.output.directory;
    std::vector<RunSummary::Cycle> cycles;
    RunSummary                     summary;
    for (unsigned int cycle = 0; cycle <= s.refinement.cycles(); ++cycle)
      {
        if (cycle > 0)
          {
            TimerOutput::Scope t(s.timer, "setup");
            s.refine_mesh();
          }
        s.output.directory = base + "/cycle-" + std::to_string(cycle);
        s.pcout << "Adaptive refinement: cycle " << cycle << std::endl;
        summary = s.run();
        cycles.push_back({summary.n_cells,
                          summary.n_dofs,
                          summary.n_newton_iterations,
                          summary.exit_code,
                          summary.volume,
                          summary.monitor_displacements});
        if (summary.exit_code != success)
          break;
      }
    s.output.directory = base;
    summary.cycles     = cycles;
    s.write_refinement_table(cycles);
    return summary;
  }

  RunSummary
  Simulator::Impl::run()
  {
    RunSummary summary;
    summary.n_cells = has_membrane() ? triangulation.n_global_active_cells() : 0;
    summary.n_cable_cells = cable_system.n_cells();
    summary.n_dofs        = locally_owned.size();
    pcout << "pneuma: " << summary.n_cells << " membrane cells, ";
    if (!cable_system.empty())
      pcout << summary.n_cable_cells << " cable elements, ";
    pcout << summary.n_dofs << " dofs, degree " << degree << ", "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s)\n";

    prepare_output_directory();
    locate_monitor_points();

    solution     = 0.;
    current_time = 0.;
    if (has_membrane())
      boundary_conditions.set_prescribed_values(*mapping,
                                                dof_handler,
                                                0.,
                                                solution);
    cable_system.set_prescribed_values(0., solution);
    ghosted = solution;
    if (geometry.is_closed())
      initial_volume = assembler.enclosed_volume(ghosted);
    summary.initial_volume = initial_volume;
    const bool with_chambers = !chamber_parameters.empty();
    if (with_chambers)
      {
        chamber_system.initialize(ghosted, 0.);
        summary.chamber_history.emplace_back(0., chamber_states());
      }
    // Friction: points in contact at the start stick where they are.
    refresh_contact();
    contact_system.commit_step();
    write_history_row(0, 0., 0);
    if (output.write_vtu)
      write_vtu(0, 0.);

    double       dt   = stepping.initial();
    unsigned int step = 0;
    // Bergan's current stiffness parameter: (dt/|du|) relative to the
    // first step of the stage; near zero at a limit point.
    double       stiffness_reference = 0., stiffness_parameter = 1.;
    unsigned int stiffness_stage = numbers::invalid_unsigned_int;
    LA::Vector   last_converged(solution);

    while (!stepping.finished(current_time))
      {
        const double t_old = current_time;
        const double t_new = stepping.next_time(t_old, dt);
        last_converged     = solution;
        current_time       = t_new;
        if (has_membrane())
          boundary_conditions.set_prescribed_values(*mapping,
                                                    dof_handler,
                                                    t_new,
                                                    solution);
        cable_system.set_prescribed_values(t_new, solution);
        apply_kinematic_constraints();
        if (!contact_system.empty())
          {
            // New contact candidates of the current state; the sparsity
            // pattern grows if they bring new couplings.
            ghosted = solution;
            bool grown = false;
            {
              TimerOutput::Scope ts(timer, "contact search");
              grown = contact_system.update_candidates(&ghosted);
            }
            if (grown)
              build_matrices();
          }
        pcout << "Step " << step + 1 << "  t = " << t_new
              << "  dt = " << t_new - t_old << std::endl;
        if (with_chambers)
          {
            ghosted                 = solution;
            const std::string error = chamber_system.begin_step(ghosted, t_new);
            if (!error.empty())
              {
                summary.exit_code = solver_failed;
                summary.message   = error + ". The last converged state (t = " +
                                  std::to_string(t_old) + ") is written.";
                solution     = last_converged;
                current_time = t_old;
                break;
              }
          }
        solvers::BorderedVector state;
        state.field = solution;
        if (with_chambers)
          state.border = chamber_system.pack();
        auto result = newton.solve(*this,
                                   state,
                                   pcout,
                                   last_converged.linfty_norm() == 0.);
        solution = state.field;
        summary.n_newton_iterations += result.iterations;
        // A closed surface must keep a positive enclosed volume.
        if (result.converged && geometry.is_closed())
          {
            ghosted = solution;
            if (assembler.enclosed_volume(ghosted) <= 0.)
              {
                result.converged      = false;
                result.failure_reason = "the surface turned inside out";
              }
          }

        if (!result.converged)
          {
            ++summary.n_cutbacks;
            solution     = last_converged;
            current_time = t_old;
            dt           = stepping.cut(t_new - t_old);
            pcout << "  Newton failed (" << result.failure_reason
                  << "); cutting back to dt = " << dt << std::endl;
            if (dt < stepping.minimum())
              {
                std::ostringstream msg;
                msg << "the load step could not be completed at t = " << t_old
                    << " even with the minimum increment " << stepping.minimum()
                    << " (" << result.failure_reason << ")";
                if (stiffness_parameter < 0.1)
                  msg << "; a limit point was reached: the current stiffness "
                         "parameter fell to "
                      << stiffness_parameter
                      << ", so the load cannot grow further under load "
                         "control (use volume or gas-amount control)";
                msg << ". The last converged state (t = " << t_old
                    << ") is written.";
                summary.exit_code = solver_failed;
                summary.message   = msg.str();
                break;
              }
            continue;
          }

        // Converged step.
        ++step;
        cable_system.commit_step(solution);
        summary.step_iterations.push_back(result.iterations);
        if (with_chambers)
          {
            chamber_system.unpack(state.border);
            ghosted = solution;
            chamber_system.commit_step(ghosted, t_new, pcout);
            summary.chamber_history.emplace_back(t_new, chamber_states());
          }
        LA::Vector increment(solution);
        increment -= last_converged;
        const double ratio =
          (t_new - t_old) / std::max(increment.l2_norm(), 1e-300);
        const unsigned int stage = stepping.stage_of(t_old);
        if (stage != stiffness_stage)
          {
            stiffness_stage     = stage;
            stiffness_reference = ratio;
          }
        stiffness_parameter           = ratio / stiffness_reference;
        summary.last_residual_history = result.residual_history;
        pcout << "  converged in " << result.iterations << " iterations, wall "
              << std::fixed << std::setprecision(2) << wall_clock.wall_time()
              << " s" << std::defaultfloat << std::setprecision(6) << std::endl;
        refresh_contact();
        contact_system.commit_step(); // friction: anchors of this state
        write_history_row(step, t_new, result.iterations);
        if (output.write_vtu && output.vtu_interval > 0
            && step % output.vtu_interval == 0)
          write_vtu(step, t_new);
        dt = stepping.grown(t_new - t_old, result.iterations);
      }

    summary.n_steps         = step;
    summary.final_time      = current_time;
    refresh_contact(); // the reports of the last converged state
    summary.n_linear_solves = n_linear_solves;
    summary.n_factorizations    = linear_solver.n_factorizations();
    summary.n_krylov_iterations = linear_solver.n_krylov_iterations();
    ghosted                 = solution;
    // The last converged state is always written.
    if (output.write_vtu
        && (summary.exit_code != success || output.vtu_interval == 0
            || step % output.vtu_interval != 0))
      write_vtu(step, current_time);
    summary.monitor_displacements = monitor_displacements();
    summary.monitor_positions     = monitor_positions;
    if (geometry.is_closed())
      summary.volume = assembler.enclosed_volume(ghosted);
    compute_reactions(summary.reaction, summary.applied_load);
    if (with_chambers)
      summary.chambers = chamber_states();
    summary.cables       = cable_states();
    summary.contact      = contact_states();
    summary.wall_seconds = wall_clock.wall_time();
    write_summary(summary);
    return summary;
  }

  // ------------------------------------------------------------------
  // Finite-difference check of the tangent
  // ------------------------------------------------------------------
  TangentCheck
  Simulator::check_tangent(const double t,
                           const double amplitude,
                           const double h)
  {
    Impl &s        = *impl;
    s.current_time = t;
    // A smooth random state: random nodal values scaled by amplitude.
    solvers::BorderedVector u;
    u.field = s.solution;
    for (const auto i : s.locally_owned)
      u.field[i] =
        amplitude * (2. * std::sin(1.7 * i + 0.3) * std::cos(0.37 * i));
    u.field.compress(VectorOperation::insert);
    // An admissible state: prescribed values zero, dependent dofs (rigid
    // plates, junction copies) following their masters.
    s.constraints.set_zero(u.field);
    s.constraints.distribute(u.field);

    // The direction d acts on the independent dofs: K d with the condensed
    // tangent, and the residual is perturbed along d with its dependent
    // dofs distributed (C d).
    solvers::BorderedVector direction(u);
    for (const auto i : s.locally_owned)
      direction.field[i] = std::cos(0.91 * i + 0.1);
    direction.field.compress(VectorOperation::insert);
    s.constraints.set_zero(direction.field);

    if (!s.chamber_parameters.empty())
      {
        s.ghosted = 0.;
        s.chamber_system.initialize(s.ghosted, t);
        s.ghosted = u.field;
        s.chamber_system.begin_step(s.ghosted, t);
        u.border = s.chamber_system.pack();
        // Off equilibrium in the chamber unknowns too.
        direction.border.reinit(u.border.size());
        for (unsigned int j = 0; j < u.border.size(); ++j)
          {
            u.border[j] *= 1.01;
            direction.border[j] = 0.3 + 0.1 * j;
          }
      }

    solvers::BorderedVector r(u), r_plus(u), r_minus(u), Kd(u), fd(u);
    s.assemble(u, r);
    if (s.chamber_parameters.empty())
      s.tangent.vmult(Kd.field, direction.field);
    else
      s.chamber_system.vmult(s.tangent, direction, Kd);

    solvers::BorderedVector full(direction);
    s.constraints.distribute(full.field);
    solvers::BorderedVector up(u);
    up.add(h, full);
    s.assemble(up, r_plus);
    solvers::BorderedVector um(u);
    um.add(-h, full);
    s.assemble(um, r_minus);
    fd = r_plus;
    fd -= r_minus;
    fd *= 1. / (2. * h);
    TangentCheck check;
    check.tangent_norm = Kd.l2_norm();
    fd -= Kd;
    check.relative_error = fd.l2_norm() / std::max(check.tangent_norm, 1e-300);
    return check;
  }
} // namespace pneuma
