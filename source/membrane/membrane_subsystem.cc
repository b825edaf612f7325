#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <pneuma/core/checkpoint.h>
#include <pneuma/core/collective_error.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/model.h>
#include <pneuma/core/share_constraints.h>
#include <pneuma/membrane/face_assembly.h>
#include <pneuma/membrane/form_finding_law.h>
#include <pneuma/membrane/membrane_subsystem.h>
#include <pneuma/postprocess/membrane_fields.h>
#include <pneuma/postprocess/membrane_probes.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <limits>
#include <sstream>

namespace pneuma
{
  namespace membrane
  {
    MembraneSubsystem::MembraneSubsystem(Model &model)
      : model(model)
      , comm(model.mpi_communicator())
      , mesh(comm, Triangulation<2, 3>::limit_level_difference_at_vertices)
      , dofs(mesh)
    {
    }

    MembraneSubsystem::~MembraneSubsystem()
    {
      output.reset();
      dofs.clear();
    }

    void
    MembraneSubsystem::declare_switches(ParameterHandler &prm)
    {
      geometry::SceneGenerator::declare_type(prm);
    }

    bool
    MembraneSubsystem::is_active(const InputLayout &layout)
    {
      return layout.is_template()
             || layout.value("Geometry/Type", "closed cylinder") != "none";
    }

    void
    MembraneSubsystem::declare_parameters(ParameterHandler  &prm,
                                          const InputLayout &layout)
    {
      prm.enter_subsection("Discretisation");
      prm.add_parameter("Polynomial degree",
                        fe_degree,
                        "Degree of the FE_Q displacement; the mapping of the "
                        "reference surface has the same degree.",
                        Patterns::Integer(1, 2));
      prm.leave_subsection();
      scene.declare_parameters(prm);
      adaptive.declare_parameters(prm);
      materials.declare_parameters(prm, layout);
      bending::Parameters::declare(prm);
      boundary_conditions.declare_parameters(prm);
      rigid_regions.declare_parameters(prm);
      prm.enter_subsection("Output");
      prm.declare_entry("Monitor points",
                        "",
                        Patterns::Anything(),
                        "Points 'x,y,z; x,y,z; ...' [m]: the displacement of "
                        "the nearest mesh vertex is written to history.csv "
                        "and summary.json (columns m0_u_x, ...).");
      prm.declare_entry(
        "Probe points",
        "",
        Patterns::Anything(),
        "Points 'x,y,z; ...' [m] on the reference surface: the membrane "
        "state at the point itself is written to history.csv and "
        "summary.json (p0_N1, p0_N2 [N/m] principal forces, p0_N1_direction; "
        "where the region wrinkles also p0_wrinkling_state 0/1/2, "
        "p0_wrinkle_direction and p0_plain_minor_force [N/m], which is "
        "negative where compression is relaxed away).");
      prm.leave_subsection();
    }

    void
    MembraneSubsystem::parse_parameters(ParameterHandler &prm)
    {
      scene.parse_parameters(prm);
      adaptive.parse_parameters(prm);
      materials.parse_parameters(prm);
      bending_parameters.parse(prm);
      // Shell regions add their bending to the cell and edge loops (before
      // the setup: the edges' couplings enter the sparsity pattern).
      if (materials.any_bending() && !shell)
        {
          shell =
            std::make_unique<bending::ShellBending>(*this, bending_parameters);
          add_cell_terms(shell->cell_terms());
          add_face_terms(shell->face_terms());
        }
      boundary_conditions.parse_parameters(prm);
      rigid_regions.parse_parameters(prm);
      prm.enter_subsection("Output");
      monitor_points.clear();
      for (const auto &item :
           Utilities::split_string_list(prm.get("Monitor points"), ';'))
        monitor_points.push_back(
          loads::parse_point(item, "Output/Monitor points"));
      probe_points.clear();
      for (const auto &item :
           Utilities::split_string_list(prm.get("Probe points"), ';'))
        probe_points.push_back(loads::parse_point(item, "Output/Probe points"));
      prm.leave_subsection();
    }

    // ------------------------------------------------------------------
    // Setup
    // ------------------------------------------------------------------
    void
    MembraneSubsystem::cache_mapping()
    {
      // The mapped support points of every cell are computed once from the
      // manifolds: FEValues::reinit no longer calls the manifolds.
      auto cache = std::make_unique<MappingQCache<2, 3>>(fe_degree);
      cache->initialize(MappingQ<2, 3>(fe_degree), mesh);
      mapping_cache = std::move(cache);
    }

    types::global_dof_index
    MembraneSubsystem::setup_unknowns(const types::global_dof_index first,
                                      const MPI_Comm)
    {
      AssertThrow(first == 0,
                  ExcMessage("the membrane's dofs must come first"));
      if (!mesh_created)
        {
          // A restart refines the coarse mesh as its checkpoint saved it.
          scene.create_triangulation(mesh,
                                     model.restart_directory().empty()
                                       ? std::string()
                                       : model.restart_directory()
                                           + "/membrane.mesh",
                                     3. * fe_degree * fe_degree);
          fe = std::make_unique<FESystem<2, 3>>(FE_Q<2, 3>(fe_degree), 3);
          cache_mapping();
          mesh_created = true;

          // Every region a cell is in must have a valid material; every id
          // named in the input must exist in the mesh.
          std::set<unsigned int> local_ids;
          for (const auto &cell : mesh.active_cell_iterators())
            if (cell->is_locally_owned())
              local_ids.insert(cell->material_id());
          const auto all_ids = Utilities::MPI::compute_set_union(
            std::vector<unsigned int>(local_ids.begin(), local_ids.end()),
            comm);
          for (const auto id : all_ids)
            (void)materials[id];
          mesh_ids =
            std::set<types::material_id>(all_ids.begin(), all_ids.end());
          for (const auto id : rigid_regions.all_ids())
            check_input(mesh_ids.count(id) > 0,
                        "Boundary conditions/Rigid regions",
                        "the mesh has no cells in region "
                          + std::to_string(id));
          for (const auto id : materials.ids())
            check_input(std::find(all_ids.begin(), all_ids.end(), id)
                          != all_ids.end(),
                        "Materials/Region " + std::to_string(id),
                        "no cell of the mesh has material id "
                          + std::to_string(id));
          for (const auto &[ids, entry] :
               {std::make_pair(&model.loads().pressure_regions(),
                               "Loads/Pressure regions"),
                std::make_pair(&model.loads().surface_load_regions(),
                               "Loads/Surface load regions")})
            for (const auto id : *ids)
              check_input(std::find(all_ids.begin(), all_ids.end(), id)
                            != all_ids.end(),
                          entry,
                          "the mesh has no cells in region "
                            + std::to_string(id));
        }
      dofs.distribute_dofs(*fe);
      owned_dofs    = dofs.locally_owned_dofs();
      relevant_dofs = DoFTools::extract_locally_relevant_dofs(dofs);
      return dofs.n_dofs();
    }

    void
    MembraneSubsystem::add_locally_owned(IndexSet &owned) const
    {
      owned.add_indices(owned_dofs);
    }

    void
    MembraneSubsystem::add_locally_relevant(IndexSet &relevant)
    {
      relevant.add_indices(relevant_dofs);
      // Rigid plates couple every plate dof to three master nodes, which
      // every rank must see.
      if (!rigid_regions.empty())
        relevant.add_indices(rigid_regions.master_dofs(*mapping_cache, dofs));
      // Junction copies are tied to a master that every rank must see.
      auto master_regions = rigid_regions.all_ids();
      for (const auto id : boundary_conditions.prescribed_regions())
        master_regions.insert(id);
      IndexSet relevant_membrane(dofs.n_dofs());
      relevant_membrane.add_indices(relevant_dofs);
      junction_ties.find(*mapping_cache,
                         dofs,
                         master_regions,
                         relevant_membrane);
      for (const auto i : junction_ties.masters)
        relevant.add_index(i);
    }

    IndexSet
    MembraneSubsystem::shared_masters() const
    {
      // Masters that dependent dofs on any rank refer to: junction masters
      // and the plates' master nodes (share_constraints.h).
      IndexSet result(model.locally_relevant().size());
      result.add_indices(junction_ties.masters);
      for (const auto d : rigid_regions.plate_master_dofs())
        result.add_index(d);
      result.compress();
      return result;
    }

    void
    MembraneSubsystem::add_kinematic_constraints(
      AffineConstraints<double> &c) const
    {
      DoFTools::make_hanging_node_constraints(dofs, c);
      rigid_regions.add_constraints(*mapping_cache, dofs, c);
      share_constraint_lines(c, shared_masters(), model.locally_owned(), comm);
      junction_ties.add_constraints(c);
    }

    void
    MembraneSubsystem::add_update_constraints(
      AffineConstraints<double> &c) const
    {
      boundary_conditions.add_update_constraints(
        dofs,
        rigid_regions.slave_dofs(),
        rigid_regions.plate_master_dofs(),
        junction_ties.copies(),
        c);
      if (form_finding)
        add_normal_motion_constraints(c);
      share_constraint_lines(c, shared_masters(), model.locally_owned(), comm);
    }

    void
    MembraneSubsystem::finish_setup()
    {
      assembler =
        std::make_unique<MembraneAssembler>(scene, materials, model.loads());
      assembler->reinit(*mapping_cache, dofs, fe_degree);
      boundary_conditions.check_against_mesh(dofs);
      {
        // The shell edges' ids, and the edge moment at the start.
        std::vector<Point<3>> moment_centres;
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary()
                  && bending_parameters.moment_edges.count(
                    cell->face(f)->boundary_id()))
                moment_centres.push_back(cell->face(f)->center());
        bending::check_edges(bending_parameters,
                             shell != nullptr,
                             mesh.get_boundary_ids(),
                             moment_centres,
                             comm);
      }
      if (shell)
        model.out() << shell->description(fe_degree) << std::endl;
      prestress_force = prestress_force_scale();
      // The loads at the start: finite at every cell centre (and line-load
      // edge) of the reference surface, on every rank alike.
      std::vector<Point<3>> centres, line_centres;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            if (model.loads().pressure_acts_on(cell->material_id()))
              centres.push_back(cell->center());
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary()
                  && model.loads().line_load_boundaries().count(
                    cell->face(f)->boundary_id()))
                line_centres.push_back(cell->face(f)->center());
          }
      throw_if_any(comm,
                   model.loads().non_finite_at_start(centres, line_centres));
      // An anisotropic region needs its warp direction off the normal at
      // every point (the frame's first axis is its projection, which turns
      // abruptly near a point where the direction is normal): at least
      // 0.1 of it projects onto the surface.
      {
        std::string     error;
        const QGauss<2> quadrature(fe_degree + 1);
        FEValues<2, 3>  fe_values(*mapping_cache,
                                 dofs.get_fe(),
                                 quadrature,
                                 update_normal_vectors
                                   | update_quadrature_points);
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned() && error.empty())
            {
              const auto &material = materials[cell->material_id()];
              if (material.law->isotropic())
                continue;
              fe_values.reinit(cell);
              const Tensor<1, 3> d = material.warp(scene, cell);
              if (d.norm() == 0.)
                {
                  std::ostringstream where;
                  where << cell->center();
                  error = "Materials/Region "
                          + std::to_string(cell->material_id())
                          + "/Warp direction: 'gmsh' needs a \"warp\" "
                            "$ElementData vector for every element of the "
                            "region in Geometry/gmsh/Mesh file; the cell at ("
                          + where.str() + ") has none";
                  continue;
                }
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  const Tensor<1, 3> &N = fe_values.normal_vector(q);
                  if ((d - (d * N) * N).norm() < 0.1 * d.norm())
                    {
                      std::ostringstream where;
                      where << fe_values.quadrature_point(q);
                      error = "Materials/Region "
                              + std::to_string(cell->material_id())
                              + "/Warp direction: it is within 6 degrees "
                                "of the surface normal at ("
                              + where.str()
                              + "), where it gives no material frame; "
                                "choose a direction that lies in the "
                                "surface everywhere in the region";
                      break;
                    }
                }
            }
        throw_if_any(comm, error);
      }
    }

    Point<3>
    MembraneSubsystem::support_centroid(
      std::map<types::global_dof_index, Point<3>> &support) const
    {
      DoFTools::map_dofs_to_support_points(*mapping_cache, dofs, support);
      Point<3> centre;
      double   count = 0.;
      for (const auto &[i, x] : support)
        if (owned_dofs.is_element(i))
          {
            centre += x;
            count += 1.;
          }
      for (unsigned int d = 0; d < 3; ++d)
        centre[d] = Utilities::MPI::sum(centre[d], comm);
      return centre / std::max(1., Utilities::MPI::sum(count, comm));
    }

    void
    MembraneSubsystem::add_sparsity(
      DynamicSparsityPattern          &dsp,
      const AffineConstraints<double> &constraints) const
    {
      DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
      // The two cells of an edge couple through its terms.
      if (std::any_of(face_terms.begin(),
                      face_terms.end(),
                      [](const FaceTerms *t) {
                        return t->on_interior_faces();
                      }))
        add_face_sparsity(dofs, constraints, dsp);
    }

    void
    MembraneSubsystem::add_regularisation(
      const AffineConstraints<double> &constraints,
      LA::SparseMatrix                &L) const
    {
      assembler->surface_laplacian(constraints, L);
    }

    void
    MembraneSubsystem::add_mass(const AffineConstraints<double> &constraints,
                                LA::SparseMatrix                &M) const
    {
      assembler->mass_matrix(constraints, M);
    }

    void
    MembraneSubsystem::add_lumped_mass(LA::Vector &m) const
    {
      assembler->lumped_mass(m);
    }

    void
    MembraneSubsystem::stiffest_tangent(const bool on)
    {
      std::map<types::material_id, RegionMaterial> plain;
      if (on)
        for (const auto id : mesh_ids)
          {
            RegionMaterial m = materials[id];
            if (m.plain_law)
              m.law = m.plain_law;
            m.tension_field = nullptr;
            plain[id]       = m;
          }
      assembler->set_plain_laws(std::move(plain));
    }

    void
    MembraneSubsystem::largest_per_node(LA::Vector &v) const
    {
      // The three components of a support point are owned by one rank,
      // and an owned dof lies on a locally owned cell.
      const auto                          &fe = dofs.get_fe();
      std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
      std::vector<std::array<types::global_dof_index, 3>> node(
        fe.base_element(0).n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
              node[fe.system_to_base_index(i).second]
                  [fe.system_to_component_index(i).first] = indices[i];
            for (const auto &n : node)
              if (owned_dofs.is_element(n[0]))
                {
                  const double largest = std::max(
                    {double(v[n[0]]), double(v[n[1]]), double(v[n[2]])});
                  for (const auto i : n)
                    v[i] = largest;
                }
          }
      v.compress(VectorOperation::insert);
    }

    void
    MembraneSubsystem::add_near_null_space(
      const IndexSet                   &owned,
      std::vector<std::vector<double>> &modes) const
    {
      // The three translations (one indicator per component), and the
      // three rotations about the centroid of the reference surface,
      // which only AMG needs (they cost a pass over the support points).
      std::vector<IndexSet> component_dofs;
      for (unsigned int c = 0; c < 3; ++c)
        {
          std::vector<bool> mask(3, false);
          mask[c] = true;
          component_dofs.push_back(
            DoFTools::extract_dofs(dofs, ComponentMask(mask)));
        }
      for (unsigned int k = 0; k < owned.n_elements(); ++k)
        {
          const auto i = owned.nth_index_in_set(k);
          if (i < dofs.n_dofs())
            for (unsigned int c = 0; c < 3; ++c)
              modes[c][k] = component_dofs[c].is_element(i) ? 1. : 0.;
        }
      if (model.linear_solver().type() != solvers::LinearSolverType::amg)
        return;
      std::map<types::global_dof_index, Point<3>> support;
      const Point<3> centre = support_centroid(support);
      // The rotation about axis a moves a dof of component c by
      // (e_a x r)_c.
      for (unsigned int k = 0; k < owned.n_elements(); ++k)
        {
          const auto i = owned.nth_index_in_set(k);
          if (i >= dofs.n_dofs())
            continue;
          for (unsigned int c = 0; c < 3; ++c)
            if (modes[c][k] != 0.)
              {
                const Tensor<1, 3> r = support.at(i) - centre;
                for (unsigned int a = 0; a < 3; ++a)
                  {
                    Tensor<1, 3> e;
                    e[a]            = 1.;
                    modes[3 + a][k] = cross_product_3d(e, r)[c];
                  }
              }
        }
    }

    double
    MembraneSubsystem::initial_shift(
      const double            factor,
      const UnknownRange     &range,
      const LA::SparseMatrix &K,
      const LA::SparseMatrix &L,
      const LA::Vector &,
      const AffineConstraints<double> &constraints) const
    {
      // mean(diag K)/mean(diag L) over the unconstrained membrane dofs:
      // the membrane sets the scale (stiff cables must not slow its
      // continuation down).
      return factor * model.diagonal_ratio(range, K, L, constraints);
    }

    double
    MembraneSubsystem::start_prestress(const LA::Vector &external) const
    {
      // Virial of the applied loads: in equilibrium
      // int tr N dA = sum_i x_i . f_i (reactions included), so the mean
      // isotropic membrane force is about sum (x_i - c) . f_i / (2 A) over
      // the free dofs and the deformable cells (the reactions of supports
      // and rigid plates are unknown here and left out). Exact for a
      // closed, pressurised sphere (pR/2); the axial force pR/2 of a
      // cylinder between plates.
      std::map<types::global_dof_index, Point<3>> support;
      const Point<3> centre      = support_centroid(support);
      const auto    &constraints = model.constraints();
      double         virial      = 0.;
      for (unsigned int c = 0; c < 3; ++c)
        {
          std::vector<bool> mask(3, false);
          mask[c] = true;
          for (const auto i : DoFTools::extract_dofs(dofs, ComponentMask(mask)))
            if (!constraints.is_constrained(i))
              virial += (support.at(i)[c] - centre[c]) * external[i];
        }
      virial            = Utilities::MPI::sum(virial, comm);
      const double area = reference_area(rigid_regions.all_ids());
      return area > 0. ? std::max(0., virial / (2. * area)) : 0.;
    }

    // ------------------------------------------------------------------
    // Steps
    // ------------------------------------------------------------------
    void
    MembraneSubsystem::set_prescribed_values(const double t,
                                             LA::Vector  &field) const
    {
      // Form finding keeps the supports where the input puts them.
      if (!form_finding)
        boundary_conditions.set_prescribed_values(*mapping_cache,
                                                  dofs,
                                                  t,
                                                  field);
    }

    double
    MembraneSubsystem::prestress_force_scale() const
    {
      // The largest prestress times the square root of the area.
      double n_max = 0.;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto &n = materials[cell->material_id()].prestress;
            n_max         = std::max({n_max, std::abs(n[0]), std::abs(n[1])});
          }
      return Utilities::MPI::max(n_max, comm) * std::sqrt(reference_area());
    }

    double
    MembraneSubsystem::force_scale(const LA::Vector &) const
    {
      return prestress_force;
    }

    void
    MembraneSubsystem::initialize(const LA::Vector &field, const double)
    {
      locate_monitor_points();
      locate_point_loads();
      // A probe off the surface is an input error before the first step.
      if (!probe_points.empty())
        postprocess::membrane_probes(*mapping_cache,
                                     dofs,
                                     materials,
                                     scene,
                                     field,
                                     probe_points,
                                     "Output/Probe points");
      reference_volume =
        scene.is_closed() ? assembler->enclosed_volume(field) : 0.;
    }

    void
    MembraneSubsystem::add_cell_terms(CellTerms &terms)
    {
      cell_terms.push_back(&terms);
    }

    void
    MembraneSubsystem::add_face_terms(FaceTerms &terms)
    {
      face_terms.push_back(&terms);
    }

    void
    MembraneSubsystem::assemble(const Assembly &a)
    {
      AssemblyRequest request;
      request.time     = a.time;
      request.residual = a.residual;
      request.tangent  = a.tangent;
      request.external = a.external;
      for (auto *terms : cell_terms)
        terms->begin(a);
      request.cell_terms = cell_terms;
      assembler->assemble(*a.field, *a.constraints, request);
      for (auto *terms : cell_terms)
        terms->end();
      const bool faces =
        !face_terms.empty() && (a.residual != nullptr || a.tangent != nullptr);
      if (faces)
        {
          for (auto *terms : face_terms)
            terms->begin(a);
          assemble_faces(*mapping_cache,
                         dofs,
                         face_terms,
                         *a.field,
                         *a.constraints,
                         a.tangent,
                         a.residual);
          for (auto *terms : face_terms)
            terms->end();
        }
      const bool points =
        add_point_loads(a.time, *a.constraints, a.residual, a.external);
      if (a.residual && (faces || points))
        a.residual->compress(VectorOperation::add);
      if (a.external && points)
        a.external->compress(VectorOperation::add);
      if (a.tangent && faces)
        a.tangent->compress(VectorOperation::add);
    }

    std::string
    MembraneSubsystem::check_state(const LA::Vector &field) const
    {
      // A closed surface must keep a positive enclosed volume.
      if (scene.is_closed() && assembler->enclosed_volume(field) <= 0.)
        return "the surface turned inside out";
      return "";
    }

  } // namespace membrane
} // namespace pneuma

PNEUMA_REGISTER_SUBSYSTEM(pneuma::membrane::MembraneSubsystem,
                          "membrane",
                          10,
                          pneuma::membrane::MembraneSubsystem::declare_switches,
                          pneuma::membrane::MembraneSubsystem::is_active)
