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
    MembraneSubsystem::save_checkpoint(
      Checkpoint                            &checkpoint,
      const std::vector<const LA::Vector *> &fields) const
    {
      // The displacements (and the path's other vectors) travel with the
      // mesh (p4est), so a restart may use another number of ranks.
      std::vector<LA::Vector>         ghosted(fields.size());
      std::vector<const LA::Vector *> pointers;
      for (unsigned int k = 0; k < fields.size(); ++k)
        {
          LA::Vector owned(owned_dofs, comm);
          for (const auto i : owned_dofs)
            owned[i] = (*fields[k])[i];
          owned.compress(VectorOperation::insert);
          ghosted[k].reinit(owned_dofs, relevant_dofs, comm);
          ghosted[k] = owned;
          pointers.push_back(&ghosted[k]);
        }
      parallel::distributed::SolutionTransfer<2, LA::Vector, 3> transfer(dofs);
      transfer.prepare_for_serialization(pointers);
      mesh.save(checkpoint.directory() + "/membrane.mesh");
      checkpoint.put("membrane/pvd", pvd_records);
    }

    void
    MembraneSubsystem::load_checkpoint(const Checkpoint &checkpoint,
                                       const std::vector<LA::Vector *> &fields)
    {
      std::vector<LA::Vector>   owned(fields.size());
      std::vector<LA::Vector *> pointers;
      for (auto &v : owned)
        {
          v.reinit(owned_dofs, comm);
          pointers.push_back(&v);
        }
      parallel::distributed::SolutionTransfer<2, LA::Vector, 3> transfer(dofs);
      transfer.deserialize(pointers);
      for (unsigned int k = 0; k < fields.size(); ++k)
        for (const auto i : owned_dofs)
          (*fields[k])[i] = owned[k][i];
      pvd_records = checkpoint.get<std::vector<std::pair<double, std::string>>>(
        "membrane/pvd");
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
    MembraneSubsystem::compute_motion_directions()
    {
      // The consistent nodal normal int N_i n dA of every node of the
      // owned cells (their patches are owned or ghost cells), each cell's
      // part turned to agree with what the node has so far.
      const auto     &fe = dofs.get_fe();
      const QGauss<2> quadrature(fe_degree + 1);
      FEValues<2, 3>  fe_values(*mapping_cache,
                               fe,
                               quadrature,
                               update_values | update_normal_vectors
                                 | update_JxW_values);
      auto           &normal = motion_direction;
      normal.clear();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      const unsigned int n_nodes = fe.base_element(0).n_dofs_per_cell();
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dof_indices);
            for (unsigned int k = 0; k < n_nodes; ++k)
              {
                const unsigned int i = fe.component_to_system_index(0, k);
                Tensor<1, 3>       part;
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  part += fe_values.shape_value(i, q)
                          * fe_values.normal_vector(q) * fe_values.JxW(q);
                auto &n = normal[dof_indices[i]];
                n += (n * part < 0. ? -1. : 1.) * part;
              }
          }
    }

    void
    MembraneSubsystem::add_normal_motion_constraints(
      AffineConstraints<double> &c) const
    {
      const auto        &fe      = dofs.get_fe();
      const unsigned int n_nodes = fe.base_element(0).n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      // Motion along the normal only: among the node's free components,
      // u_b = (n_b / n_a) u_a with a the one the normal is most along.
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            for (unsigned int q = 0; q < n_nodes; ++q)
              {
                std::array<types::global_dof_index, 3> d;
                for (unsigned int k = 0; k < 3; ++k)
                  d[k] = dof_indices[fe.component_to_system_index(k, q)];
                const Tensor<1, 3>       &m = motion_direction.at(d[0]);
                const Tensor<1, 3>        n = m / m.norm();
                std::vector<unsigned int> free;
                for (unsigned int k = 0; k < 3; ++k)
                  if (!c.is_constrained(d[k]))
                    free.push_back(k);
                if (free.size() < 2)
                  continue;
                unsigned int a = free[0];
                for (const auto k : free)
                  if (std::abs(n[k]) > std::abs(n[a]))
                    a = k;
                for (const auto b : free)
                  if (b != a)
                    {
                      c.add_line(d[b]);
                      c.add_entry(d[b], d[a], n[b] / n[a]);
                    }
              }
          }
    }

    void
    MembraneSubsystem::finish_setup()
    {
      assembler =
        std::make_unique<MembraneAssembler>(scene, materials, model.loads());
      assembler->reinit(*mapping_cache, dofs, fe_degree);
      boundary_conditions.check_against_mesh(dofs);
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
    MembraneSubsystem::check_well_posed() const
    {
      // A rigid motion r (3 translations, 3 rotations about the centroid,
      // scaled to unit size over the membrane) is removed by the supports
      // iff it moves some prescribed dof: the free motions are the null
      // space of G = sum over prescribed dofs i of r(i) r(i)^T (6 x 6).
      // Rigid plates and ties follow rigid motions, so they count through
      // their prescribed masters. Checked before the first factorization,
      // so that an ill-posed scene is a message, not minutes of cut-backs.
      std::map<types::global_dof_index, Point<3>> support;
      const Point<3> centre = support_centroid(support);
      double         size   = 0.;
      for (const auto &[i, x] : support)
        size = std::max(size, x.distance(centre));
      size = std::max(Utilities::MPI::max(size, comm), 1e-300);

      const auto        &constraints = model.constraints();
      FullMatrix<double> G(6, 6);
      for (unsigned int c = 0; c < 3; ++c)
        {
          std::vector<bool> mask(3, false);
          mask[c] = true;
          for (const auto i : DoFTools::extract_dofs(dofs, ComponentMask(mask)))
            if (constraints.is_constrained(i)
                && constraints.get_constraint_entries(i)->empty())
              {
                const Tensor<1, 3> r = (support.at(i) - centre) / size;
                double             row[6];
                for (unsigned int a = 0; a < 3; ++a)
                  {
                    Tensor<1, 3> e;
                    e[a]       = 1.;
                    row[a]     = (a == c) ? 1. : 0.;
                    row[3 + a] = cross_product_3d(e, r)[c];
                  }
                for (unsigned int j = 0; j < 6; ++j)
                  for (unsigned int k = 0; k < 6; ++k)
                    G(j, k) += row[j] * row[k];
              }
        }
      double trace = 0.;
      for (unsigned int j = 0; j < 6; ++j)
        for (unsigned int k = 0; k < 6; ++k)
          {
            G(j, k) = Utilities::MPI::sum(G(j, k), comm);
            if (j == k)
              trace += G(j, j);
          }

      // The free motions: eigenvectors of G with (numerically) zero
      // eigenvalue, described by their leading terms.
      LAPACKFullMatrix<double> lapack(6, 6);
      lapack = G;
      Vector<double>     values;
      FullMatrix<double> vectors;
      lapack.compute_eigenvalues_symmetric(
        -1., 1e-10 * std::max(trace, 1.), 1e-14, values, vectors);
      if (values.size() == 0)
        return;
      const char        *names[6] = {"translation along x",
                                     "translation along y",
                                     "translation along z",
                                     "rotation about x",
                                     "rotation about y",
                                     "rotation about z"};
      std::ostringstream free;
      for (unsigned int m = 0; m < values.size(); ++m)
        {
          free << (m ? "; " : "");
          bool first = true;
          for (unsigned int j = 0; j < 6; ++j)
            if (std::abs(vectors(j, m)) > 0.3)
              {
                free << (first ? "" : " + ") << names[j];
                first = false;
              }
        }
      std::ostringstream where;
      where << centre;
      const std::string message =
        "the membrane is free to move as a rigid body (" + free.str()
        + "; rotations about its centroid (" + where.str()
        + ")): add supports (Fixed points, Fixed boundaries, Fixed regions) "
          "that hold it";
      // Contact with supported cables may hold it; then it is a warning.
      const auto holders = model.with<Holds>();
      if (std::any_of(holders.begin(), holders.end(), [this](const Holds *h) {
            return h->holds(*this);
          }))
        {
          model.out() << "pneuma: warning: " << message << std::endl;
          return;
        }
      throw InputError("Boundary conditions", message);
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
      if (model.linear_solver().type() != "amg")
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

    void
    MembraneSubsystem::refine(const LA::Vector &field)
    {
      adaptive.refine(*mapping_cache, dofs, field, mesh);
      cache_mapping();
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

    // ------------------------------------------------------------------
    // Form finding
    // ------------------------------------------------------------------
    void
    MembraneSubsystem::begin_form_finding(const double lambda)
    {
      check_input(rigid_regions.empty(),
                  "Boundary conditions/Rigid regions",
                  "form finding moves the reference surface, which rigid "
                  "plates cannot follow; hold those regions with Fixed "
                  "regions instead");
      check_input(fe_degree >= 2,
                  "Discretisation/Polynomial degree",
                  "form finding needs degree 2: on the facets of degree 1 "
                  "the iteration is unstable (a catenoid collapses)");
      check_input(adaptive.cycles() == 0,
                  "Adaptive refinement/Cycles",
                  "form finding and adaptive refinement cannot be combined "
                  "(new cells would lie on the input's surface)");
      std::map<types::material_id, RegionMaterial> laws;
      for (const auto id : mesh_ids)
        {
          const RegionMaterial &m    = materials[id];
          const std::string     path = "Materials/Region " + std::to_string(id);
          const double          n1 = m.prestress[0], n2 = m.prestress[1];
          check_input(n1 > 0. && n2 > 0.,
                      path + "/Prestress",
                      "form finding needs a positive prestress in every "
                      "region (the membrane forces of the shape to find)");
          check_input(lambda == 0. || n1 == n2,
                      "Form finding/Homotopy factor",
                      "must be 0 where the prestress is anisotropic (" + path
                        + "/Prestress)");
          RegionMaterial f = m;
          f.law = std::make_shared<FormFindingLaw>(n1, n2, lambda, m.thickness);
          f.tension_field.reset();
          laws[id] = f;
        }
      assembler->set_form_finding(laws);
      form_finding = true;
      // Nodes move along the normals of the input surface.
      compute_motion_directions();

      if (reference_shift.size() == 0)
        {
          reference_shift.reinit(owned_dofs, relevant_dofs, comm);
          reference_shift = 0.;
        }
    }

    double
    MembraneSubsystem::move_reference(const LA::Vector &field)
    {
      // The membrane's part of the model's ghosted field.
      LA::Vector owned(owned_dofs, comm);
      for (const auto i : owned_dofs)
        owned[i] = field[i];
      owned.compress(VectorOperation::insert);
      const double change = owned.linfty_norm();
      LA::Vector   shift(owned_dofs, comm);
      shift = reference_shift;
      shift += owned;
      reference_shift = shift;
      // (MappingQCache imports the ghost values itself.)
      auto moved = std::make_unique<MappingQCache<2, 3>>(fe_degree);
      moved->initialize(*mapping_cache, dofs, owned, true);
      mapping_cache = std::move(moved);
      assembler->reinit(*mapping_cache, dofs, fe_degree);
      ++form_finding_updates;
      return change;
    }

    void
    MembraneSubsystem::end_form_finding()
    {
      assembler->set_form_finding({});
      form_finding = false;
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
    MembraneSubsystem::reference_area(
      const std::set<types::material_id> &excluded) const
    {
      const QGauss<2> quadrature(fe_degree + 1);
      FEValues<2, 3>  fe_values(*mapping_cache,
                               dofs.get_fe(),
                               quadrature,
                               update_JxW_values);
      double          area = 0.;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned() && !excluded.count(cell->material_id()))
          {
            fe_values.reinit(cell);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              area += fe_values.JxW(q);
          }
      return Utilities::MPI::sum(area, comm);
    }

    double
    MembraneSubsystem::reference_diameter() const
    {
      std::array<double, 3> lo, hi;
      lo.fill(std::numeric_limits<double>::max());
      hi.fill(-std::numeric_limits<double>::max());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &x : mapping_cache->get_vertices(cell))
            for (unsigned int d = 0; d < 3; ++d)
              {
                lo[d] = std::min(lo[d], x[d]);
                hi[d] = std::max(hi[d], x[d]);
              }
      double sum = 0.;
      for (unsigned int d = 0; d < 3; ++d)
        sum += std::pow(Utilities::MPI::max(hi[d], comm)
                          + Utilities::MPI::max(-lo[d], comm),
                        2);
      return std::sqrt(sum);
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
      if (face_terms.empty() || (!a.residual && !a.tangent))
        return;
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
      if (a.residual)
        a.residual->compress(VectorOperation::add);
      if (a.tangent)
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

    // ------------------------------------------------------------------
    // Reports
    // ------------------------------------------------------------------
    void
    MembraneSubsystem::locate_monitor_points()
    {
      monitor_dofs.clear();
      monitor_positions.clear();
      for (const auto &p : monitor_points)
        {
          double local_min = std::numeric_limits<double>::max();
          for (const auto &cell : dofs.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto v : cell->vertex_indices())
                local_min = std::min(local_min, cell->vertex(v).distance(p));
          const double global_min = Utilities::MPI::min(local_min, comm);
          // The lowest rank that owns a vertex at that distance reports it.
          std::array<types::global_dof_index, 3> dof;
          dof.fill(numbers::invalid_dof_index);
          std::array<double, 3> position{{0., 0., 0.}};
          bool                  found = false;
          for (const auto &cell : dofs.active_cell_iterators())
            if (cell->is_locally_owned() && !found)
              for (const auto v : cell->vertex_indices())
                if (cell->vertex(v).distance(p) <= global_min * (1 + 1e-12)
                    && owned_dofs.is_element(cell->vertex_dof_index(v, 0)))
                  {
                    for (unsigned int c = 0; c < 3; ++c)
                      {
                        dof[c]      = cell->vertex_dof_index(v, c);
                        position[c] = cell->vertex(v)[c];
                        // The surface form finding found.
                        if (reference_shift.size() > 0)
                          position[c] += reference_shift[dof[c]];
                      }
                    found = true;
                    break;
                  }
          const unsigned int me = Utilities::MPI::this_mpi_process(comm);
          const unsigned int reporter =
            Utilities::MPI::min(found ? me : numbers::invalid_unsigned_int,
                                comm);
          if (me != reporter)
            {
              dof.fill(numbers::invalid_dof_index);
              position.fill(0.);
            }
          for (unsigned int c = 0; c < 3; ++c)
            position[c] = Utilities::MPI::sum(position[c], comm);
          monitor_dofs.push_back(dof);
          monitor_positions.push_back(position);
        }
    }

    void
    MembraneSubsystem::compute_reactions(const LA::Vector      &u,
                                         std::array<double, 3> &reaction,
                                         std::array<double, 3> &applied) const
    {
      // The reactions: the model's support residual (every subsystem's
      // f_int - f_ext with the dependent dofs' forces condensed onto their
      // masters): at a prescribed dof, the force the support exerts on the
      // structure, whatever loads it (cables pressing on it too). The
      // applied loads are assembled here; those of the cell terms
      // (chambers) count as applied loads.
      LA::Vector      ext = model.make_field(), scratch = model.make_field();
      AssemblyRequest request;
      request.time     = model.time();
      request.external = &ext;
      assembler->assemble(u, model.kinematic_constraints(), request);
      for (const auto *terms : cell_terms)
        terms->add_loads(u, model.kinematic_constraints(), scratch, ext);
      const LA::Vector &residual = model.support_residual();
      reaction.fill(0.);
      applied.fill(0.);
      const auto &constraints = model.constraints();
      for (unsigned int c = 0; c < 3; ++c)
        {
          std::vector<bool> mask(3, false);
          mask[c] = true;
          const IndexSet component_dofs =
            DoFTools::extract_dofs(dofs, ComponentMask(mask));
          for (const auto i : component_dofs)
            {
              applied[c] += ext[i];
              if (constraints.is_constrained(i)
                  && constraints.get_constraint_entries(i)->empty())
                reaction[c] += residual[i];
            }
          reaction[c] = Utilities::MPI::sum(reaction[c], comm);
          applied[c]  = Utilities::MPI::sum(applied[c], comm);
        }

      // Per supported boundary: the force and its moment about the origin
      // at the current positions, from the prescribed dofs on it (a node
      // on two boundaries counts in both).
      boundary_reactions.clear();
      const auto &ids = boundary_conditions.supported_boundaries();
      if (ids.empty())
        return;
      const auto                                 &fe = dofs.get_fe();
      std::map<types::global_dof_index, Point<3>> support;
      DoFTools::map_dofs_to_support_points(*mapping_cache, dofs, support);
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      for (const auto id : ids)
        {
          std::set<types::global_dof_index> seen;
          Tensor<1, 3>                      force, moment;
          for (const auto &cell : dofs.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto f : cell->face_indices())
                if (cell->face(f)->at_boundary()
                    && cell->face(f)->boundary_id() == id)
                  {
                    cell->face(f)->get_dof_indices(face_dofs);
                    // The face's nodes: their three dofs, by base index.
                    std::map<unsigned int,
                             std::array<types::global_dof_index, 3>>
                      nodes;
                    for (unsigned int k = 0; k < face_dofs.size(); ++k)
                      {
                        const auto ci = fe.face_system_to_component_index(k);
                        nodes[ci.second][ci.first] = face_dofs[k];
                      }
                    for (const auto &[base, d] : nodes)
                      {
                        if (!owned_dofs.is_element(d[0])
                            || !seen.insert(d[0]).second)
                          continue;
                        Tensor<1, 3> x, r;
                        for (unsigned int c = 0; c < 3; ++c)
                          {
                            x[c] = support.at(d[c])[c] + u[d[c]];
                            if (constraints.is_constrained(d[c])
                                && constraints.get_constraint_entries(d[c])
                                     ->empty())
                              r[c] = residual[d[c]];
                          }
                        force += r;
                        moment += cross_product_3d(x, r);
                      }
                  }
          std::array<double, 6> fm;
          for (unsigned int c = 0; c < 3; ++c)
            {
              fm[c]     = Utilities::MPI::sum(force[c], comm);
              fm[3 + c] = Utilities::MPI::sum(moment[c], comm);
            }
          boundary_reactions[id] = fm;
        }
    }

    void
    MembraneSubsystem::add_statistics(Statistics       &statistics,
                                      const LA::Vector &field) const
    {
      const auto run = StatisticsGroup::run();
      // The supports' reaction and the applied load at every converged
      // state (one residual assembly per step): a load-deflection curve
      // needs the force the mesh actually carries, which differs from a
      // load function's nominal value where the function is discontinuous
      // across cells (a load band narrower than its cells).
      std::array<double, 3> reaction, applied;
      compute_reactions(field, reaction, applied);
      statistics.add_vector(run, "reaction", "N", reaction, Statistics::report);
      statistics.add_vector(
        run, "applied_load", "N", applied, Statistics::report);
      if (statistics.is_summary())
        {
          statistics.add_count(run,
                               "cells",
                               mesh.n_global_active_cells(),
                               Statistics::summary | Statistics::test);
          for (const auto &[id, fm] : boundary_reactions)
            {
              const std::string b = "boundary_" + std::to_string(id);
              statistics.add_vector(run,
                                    b + "_reaction",
                                    "N",
                                    {{fm[0], fm[1], fm[2]}},
                                    Statistics::summary);
              statistics.add_vector(run,
                                    b + "_reaction_moment",
                                    "N m",
                                    {{fm[3], fm[4], fm[5]}},
                                    Statistics::summary);
            }
          if (form_finding_updates > 0)
            {
              statistics.add_count(run,
                                   "form_finding_updates",
                                   form_finding_updates,
                                   Statistics::summary);
              statistics.add(run,
                             "surface_area",
                             "m^2",
                             assembler->surface_area(field),
                             Statistics::summary);
            }
        }
      if (materials.any_wrinkling())
        {
          const auto w = postprocess::wrinkling_summary(
            *mapping_cache, dofs, materials, scene, field);
          statistics.add(
            run, "wrinkled_area", "m^2", w.areas[1], Statistics::report);
          statistics.add(
            run, "slack_area", "m^2", w.areas[2], Statistics::report);
          statistics.add(
            run, "plain_minor_force", "N/m", w.minor_force, Statistics::report);
        }
      if (scene.is_closed())
        {
          statistics.add(run,
                         "volume",
                         "m^3",
                         assembler->enclosed_volume(field),
                         Statistics::all);
          statistics.add(run,
                         "initial_volume",
                         "m^3",
                         reference_volume,
                         Statistics::summary);
        }
      for (unsigned int m = 0; m < monitor_dofs.size(); ++m)
        {
          std::array<double, 3> u{{0., 0., 0.}};
          for (unsigned int c = 0; c < 3; ++c)
            if (monitor_dofs[m][c] != numbers::invalid_dof_index)
              u[c] = field[monitor_dofs[m][c]];
          const StatisticsGroup group{"m", "monitor_points", "monitor", m};
          statistics.add_vector(
            group, "position", "m", monitor_positions[m], Statistics::summary);
          statistics.add_vector(
            group, "u", "m", u, Statistics::all, Statistics::Reduction::sum);
        }
      if (!probe_points.empty())
        {
          const auto probes =
            postprocess::membrane_probes(*mapping_cache,
                                         dofs,
                                         materials,
                                         scene,
                                         field,
                                         probe_points,
                                         "Output/Probe points");
          const auto sum = Statistics::Reduction::sum;
          const auto vec = [](const Tensor<1, 3> &t) {
            return std::array<double, 3>{{t[0], t[1], t[2]}};
          };
          for (unsigned int k = 0; k < probes.size(); ++k)
            {
              const auto           &p = probes[k];
              const StatisticsGroup group{"p", "probe_points", "probe", k};
              statistics.add_vector(
                group,
                "position",
                "m",
                {{probe_points[k][0], probe_points[k][1], probe_points[k][2]}},
                Statistics::summary);
              statistics.add(
                group, "N1", "N/m", p.forces.N1, Statistics::all, sum);
              statistics.add(
                group, "N2", "N/m", p.forces.N2, Statistics::all, sum);
              statistics.add_vector(group,
                                    "N1_direction",
                                    "",
                                    vec(p.forces.direction_1),
                                    Statistics::all,
                                    sum);
              if (materials.any_wrinkling())
                {
                  statistics.add_count(group,
                                       "wrinkling_state",
                                       p.wrinkling_state,
                                       Statistics::all,
                                       sum);
                  statistics.add_vector(group,
                                        "wrinkle_direction",
                                        "",
                                        vec(p.wrinkle_direction),
                                        Statistics::all,
                                        sum);
                  statistics.add(group,
                                 "plain_minor_force",
                                 "N/m",
                                 p.plain_minor_force,
                                 Statistics::all,
                                 sum);
                }
            }
        }
    }

    // ------------------------------------------------------------------
    // Output
    // ------------------------------------------------------------------
    void
    MembraneSubsystem::add_output_fields(const LA::Vector &field)
    {
      output = std::make_unique<DataOut<2, 3>>();
      output->attach_dof_handler(dofs);
      const std::vector<std::string> names(3, "displacement");
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          3, DataComponentInterpretation::component_is_part_of_vector);
      output->add_data_vector(field,
                              names,
                              DataOut<2, 3>::type_dof_data,
                              interpretation);
      const postprocess::CellFields fields = postprocess::membrane_cell_fields(
        *mapping_cache, dofs, materials, scene, field);
      output_cell_data.clear();
      output_cell_data.reserve(fields.names.size() + 1);
      for (unsigned int i = 0; i < fields.names.size(); ++i)
        {
          output_cell_data.emplace_back(fields.values[i]);
          output->add_data_vector(output_cell_data.back(),
                                  fields.names[i],
                                  DataOut<2, 3>::type_cell_data);
        }
      output_cell_data.emplace_back(mesh.n_active_cells());
      output_cell_data.back() = mesh.locally_owned_subdomain();
      output->add_data_vector(output_cell_data.back(), "subdomain");
    }

    void
    MembraneSubsystem::add_mode_fields(const std::vector<std::string> &names,
                                       const std::vector<LA::Vector>  &modes)
    {
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          3, DataComponentInterpretation::component_is_part_of_vector);
      for (unsigned int k = 0; k < modes.size(); ++k)
        output->add_data_vector(modes[k],
                                std::vector<std::string>(3, names[k]),
                                DataOut<2, 3>::type_dof_data,
                                interpretation);
    }

    void
    MembraneSubsystem::write_output_files(const std::string &directory,
                                          const unsigned int step,
                                          const double       t,
                                          const LA::Vector &)
    {
      output->build_patches(*mapping_cache,
                            fe_degree,
                            DataOut<2, 3>::curved_inner_cells);
      const std::string pvtu = output->write_vtu_with_pvtu_record(
        directory + "/", "solution", step, comm, 4);
      if (step == 0)
        pvd_records.clear();
      // A state written again (with its modes) keeps one record.
      if (pvd_records.empty() || pvd_records.back().second != pvtu)
        pvd_records.emplace_back(t, pvtu);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::ofstream pvd(directory + "/solution.pvd");
          DataOutBase::write_pvd_record(pvd, pvd_records);
        }
      output.reset();
    }
  } // namespace membrane
} // namespace pneuma

PNEUMA_REGISTER_SUBSYSTEM(pneuma::membrane::MembraneSubsystem,
                          "membrane",
                          10,
                          pneuma::membrane::MembraneSubsystem::declare_switches,
                          pneuma::membrane::MembraneSubsystem::is_active)
