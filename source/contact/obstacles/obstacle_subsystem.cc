#include <deal.II/base/mpi.h>

#include <pneuma/contact/obstacles/obstacle_subsystem.h>
#include <pneuma/core/checkpoint.h>
#include <pneuma/core/collective_error.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/model.h>

#include <iomanip>
#include <map>
#include <sstream>

namespace pneuma
{
  namespace contact
  {
    namespace
    {
      membrane::MembraneSubsystem &
      the_membrane(Model &model)
      {
        auto *m = model.find<membrane::MembraneSubsystem>();
        check_input(m != nullptr,
                    "Obstacles/Number of obstacles",
                    "obstacles need a membrane (Geometry/Type is none)");
        return *m;
      }

      /// A thread's sums of a cell (an assembly does not add them up),
      /// and the force-controlled obstacles' own terms of a cell.
      struct SumsScratch : membrane::CellTerms::Scratch
      {
        std::vector<ObstacleSums>          sums;
        std::vector<FullMatrix<double>>    matrix;
        std::vector<Vector<double>>        residual;
        std::vector<ObstacleContact::Sink> sinks;
      };
      /// Per force-controlled obstacle, what one cell adds to its row:
      /// e . f, the local B and C, D, and its points in contact.
      struct ForceRecord : membrane::CellTerms::Record
      {
        std::vector<double>         force, stiffness;
        std::vector<unsigned int>   points;
        std::vector<Vector<double>> B, C;
      };
    } // namespace

    ObstacleSubsystem::ObstacleSubsystem(Model &model)
      : model(model)
      , membrane(the_membrane(model))
    {
      membrane.add_cell_terms(*this);
    }

    void
    ObstacleSubsystem::declare_switches(ParameterHandler &prm)
    {
      ObstacleParameters::declare_count(prm);
    }

    bool
    ObstacleSubsystem::is_active(const InputLayout &layout)
    {
      return !layout
                .numbered("Obstacles",
                          "Obstacle",
                          "Obstacles/Number of obstacles")
                .empty();
    }

    bool
    ObstacleSubsystem::holds(const Subsystem &other) const
    {
      return &other == &membrane;
    }

    void
    ObstacleSubsystem::declare_parameters(ParameterHandler  &prm,
                                          const InputLayout &layout)
    {
      parameters.declare_parameters(prm, layout);
    }

    void
    ObstacleSubsystem::parse_parameters(ParameterHandler &prm)
    {
      parameters.parse_parameters(prm);
    }

    void
    ObstacleSubsystem::finish_setup()
    {
      const auto &ids = membrane.material_ids();
      for (const auto &def : parameters.obstacles)
        for (const auto id : def.regions)
          check_input(ids.count(id) > 0,
                      def.path + "/Regions",
                      "the mesh has no cells in region " + std::to_string(id));
      contact = std::make_unique<ObstacleContact>(parameters.obstacles,
                                                  membrane.material_regions());
      force_controlled.clear();
      for (unsigned int k = 0; k < parameters.obstacles.size(); ++k)
        if (parameters.obstacles[k].force_controlled)
          force_controlled.push_back(k);
      accepted_positions.reinit(force_controlled.size());
      set_positions(nullptr);
      const auto range = penalty_range();
      for (unsigned int k = 0; k < contact->size(); ++k)
        {
          const auto &def     = parameters.obstacles[k];
          const auto [lo, hi] = range[k];
          std::ostringstream s;
          s << std::setprecision(3) << def.path << ": " << def.shape->describe()
            << "; penalty ";
          if (def.penalty > 0.)
            s << def.penalty << " Pa/m (given)";
          else
            s << lo << " to " << hi << " Pa/m (" << def.penalty_factor
              << " E t / h^2 on the cells it may touch; Penalty = 0)";
          model.out() << s.str() << std::endl;
        }
    }

    std::vector<std::pair<double, double>>
    ObstacleSubsystem::penalty_range() const
    {
      const auto        &reference = membrane.reference_geometry();
      const unsigned int degree    = element_degree(reference);
      const MPI_Comm     comm      = model.mpi_communicator();
      std::vector<std::pair<double, double>> range(contact->size(),
                                                   {1e300, 0.});
      unsigned int                           c = 0;
      for (const auto &cell : membrane.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const double area = cell_area(reference, c++);
            for (unsigned int k = 0; k < contact->size(); ++k)
              if (parameters.obstacles[k].touches(cell->material_id()))
                {
                  const double eps =
                    contact->penalty(k, cell->material_id(), area, degree);
                  range[k].first  = std::min(range[k].first, eps);
                  range[k].second = std::max(range[k].second, eps);
                }
          }
      for (auto &[lo, hi] : range)
        {
          lo = Utilities::MPI::min(lo, comm);
          hi = Utilities::MPI::max(hi, comm);
        }
      return range;
    }

    void
    ObstacleSubsystem::cell_values(const LA::Vector    &u,
                                   const unsigned int   cell_index,
                                   std::vector<double> &local_u) const
    {
      const auto &reference = membrane.reference_geometry();
      const auto *dofs      = reference.dof_indices(cell_index);
      local_u.resize(3 * reference.n_nodes());
      for (unsigned int i = 0; i < local_u.size(); ++i)
        local_u[i] = u[dofs[i]];
    }

    std::vector<ObstacleSums>
    ObstacleSubsystem::sums(const LA::Vector                &u,
                            const double                     t,
                            std::vector<ObstacleCellOutput> *cells) const
    {
      const auto               &reference    = membrane.reference_geometry();
      const auto                translations = contact->translations(t);
      std::vector<ObstacleSums> total(contact->size());
      std::vector<double>       local_u;
      unsigned int              c = 0;
      for (const auto &cell : membrane.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell_values(u, c, local_u);
            std::vector<ObstacleSums> part(contact->size());
            contact->cell(cell->material_id(),
                          reference,
                          c,
                          local_u,
                          translations,
                          nullptr,
                          nullptr,
                          part,
                          true,
                          cells ? &(*cells)[cell->active_cell_index()]
                                : nullptr,
                          friction_of(c));
            ++c;
            for (unsigned int k = 0; k < total.size(); ++k)
              total[k].add(part[k]);
          }
      return total;
    }

    void
    ObstacleSubsystem::initialize(const LA::Vector &field, const double t)
    {
      // The first point (in cell order, on the lowest rank) that starts
      // more than 1 % of its offset inside an obstacle.
      const auto         &reference    = membrane.reference_geometry();
      const auto          translations = contact->translations(t);
      std::string         found;
      std::vector<double> local_u;
      unsigned int        c = 0;
      for (const auto &cell : membrane.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() && found.empty())
          {
            cell_values(field, c, local_u);
            std::vector<ObstacleSums> sums(contact->size());
            contact->cell(cell->material_id(),
                          reference,
                          c,
                          local_u,
                          translations,
                          nullptr,
                          nullptr,
                          sums,
                          false);
            const double offset =
              0.5 * membrane.material_regions()[cell->material_id()].thickness;
            for (unsigned int k = 0; k < contact->size() && found.empty(); ++k)
              if (sums[k].penetration > 0.01 * offset + 1e-12)
                {
                  std::ostringstream s;
                  s << std::setprecision(4)
                    << "the membrane starts inside the obstacle: the cell at "
                    << format_point(cell->center()) << " (region "
                    << int(cell->material_id()) << ") is "
                    << sums[k].penetration
                    << " m deep, counting its half thickness " << offset
                    << " m as the offset; move the obstacle (a plane under a "
                       "membrane at z = 0 goes at z = -t/2)";
                  found = parameters.obstacles[k].path + ": " + s.str();
                }
            ++c;
          }
      throw_if_any(model.mpi_communicator(), found);
      // Points in contact at the start stick where they are.
      if (contact->has_friction())
        accept_friction(field, t);
    }

    unsigned int
    ObstacleSubsystem::n_border_unknowns() const
    {
      unsigned int n = 0;
      for (const auto &def : parameters.obstacles)
        n += def.force_controlled ? 1 : 0;
      return n;
    }

    Vector<double>
    ObstacleSubsystem::border() const
    {
      return accepted_positions;
    }

    void
    ObstacleSubsystem::reject_step()
    {
      set_positions(nullptr);
    }

    void
    ObstacleSubsystem::set_positions(const Vector<double> *border)
    {
      std::vector<double> s(parameters.obstacles.size(), 0.);
      const unsigned int  offset = border ? model.border_offset(*this) : 0;
      for (unsigned int j = 0; j < force_controlled.size(); ++j)
        s[force_controlled[j]] =
          border ? (*border)[offset + j] : accepted_positions[j];
      contact->set_positions(s);
    }

    void
    ObstacleSubsystem::begin(const Assembly &a)
    {
      assembly = &a;
      if (!force_controlled.empty())
        {
          const unsigned int n = force_controlled.size();
          set_positions(a.border != nullptr && a.border->size() > 0 ? a.border
                                                                    : nullptr);
          force_sum.assign(n, 0.);
          stiffness_sum.assign(n, 0.);
          contact_points.assign(n, 0);
          if (a.tangent != nullptr && a.coupling != nullptr)
            for (unsigned int j = 0; j < n; ++j)
              {
                const unsigned int row = model.border_offset(*this) + j;
                a.coupling->B[row]     = 0.;
                a.coupling->C[row]     = 0.;
              }
        }
      assembly_translations = contact->translations(a.time);
      if (!contact->has_friction())
        return;
      // Friction's tangent is not symmetric (slip; stick on a curved
      // obstacle).
      if (a.symmetric != nullptr)
        *a.symmetric = false;
      // A model assembled before any initialize() (a tangent check) sticks
      // where the reference state touches, as a run does; a new mesh
      // starts without anchors.
      if (anchors.empty() && a.field != nullptr)
        {
          LA::Vector reference(*a.field);
          reference = 0.;
          accept_friction(reference, a.time);
        }
      const std::size_t size =
        membrane.reference_geometry().n_cells() * friction_stride();
      if (anchors.size() != size)
        anchors.assign(size, PointFriction());
    }

    unsigned int
    ObstacleSubsystem::friction_stride() const
    {
      return membrane.reference_geometry().n_q_points() * contact->size();
    }

    const PointFriction *
    ObstacleSubsystem::friction_of(const unsigned int c) const
    {
      const std::size_t first = std::size_t(c) * friction_stride();
      if (!contact->has_friction()
          || first + friction_stride() > anchors.size())
        return nullptr;
      return anchors.data() + first;
    }

    void
    ObstacleSubsystem::commit_step(const double          t,
                                   const LA::Vector     &field,
                                   const Vector<double> &border)
    {
      if (!force_controlled.empty())
        {
          accepted_positions = border;
          set_positions(nullptr);
        }
      if (!anchors.empty())
        accept_friction(field, t);
    }

    void
    ObstacleSubsystem::accept_friction(const LA::Vector &field, const double t)
    {
      const std::size_t size =
        membrane.reference_geometry().n_cells() * friction_stride();
      if (anchors.size() != size)
        anchors.assign(size, PointFriction());
      const auto                &reference    = membrane.reference_geometry();
      const auto                 translations = contact->translations(t);
      std::vector<PointFriction> accepted(anchors.size());
      std::vector<ObstacleSums>  unused(contact->size());
      std::vector<double>        local_u;
      unsigned int               c = 0;
      for (const auto &cell : membrane.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell_values(field, c, local_u);
            contact->cell(cell->material_id(),
                          reference,
                          c,
                          local_u,
                          translations,
                          nullptr,
                          nullptr,
                          unused,
                          false,
                          nullptr,
                          friction_of(c),
                          accepted.data() + std::size_t(c) * friction_stride());
            ++c;
          }
      anchors.swap(accepted);
    }

    void
    ObstacleSubsystem::save_checkpoint(
      Checkpoint &checkpoint,
      const std::vector<const LA::Vector *> &) const
    {
      if (!force_controlled.empty())
        checkpoint.put("obstacles/positions",
                       std::vector<double>(accepted_positions.begin(),
                                           accepted_positions.end()));
      if (!contact->has_friction())
        return;
      // Per owned cell: its id and, per point and obstacle, the flag and
      // the anchor; gathered on rank 0, which writes.
      using Entry = std::pair<std::string, std::vector<double>>;
      std::vector<Entry> local;
      unsigned int       c = 0;
      for (const auto &cell : membrane.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            Entry       e{cell->id().to_string(), {}};
            const auto *f = friction_of(c++);
            for (unsigned int i = 0; f != nullptr && i < friction_stride(); ++i)
              e.second.insert(e.second.end(),
                              {f[i].active ? 1. : 0.,
                               f[i].anchor[0],
                               f[i].anchor[1],
                               f[i].anchor[2]});
            local.push_back(e);
          }
      std::vector<Entry> all;
      for (const auto &part :
           Utilities::MPI::gather(model.mpi_communicator(), local, 0))
        all.insert(all.end(), part.begin(), part.end());
      checkpoint.put("obstacles/anchors", all);
    }

    void
    ObstacleSubsystem::load_checkpoint(const Checkpoint &checkpoint,
                                       const std::vector<LA::Vector *> &)
    {
      if (!force_controlled.empty())
        {
          const auto s =
            checkpoint.get<std::vector<double>>("obstacles/positions");
          check_input(s.size() == force_controlled.size(),
                      "--restart " + checkpoint.directory(),
                      "the checkpoint has another number of obstacles "
                      "loaded by a force");
          for (unsigned int j = 0; j < s.size(); ++j)
            accepted_positions[j] = s[j];
          set_positions(nullptr);
        }
      if (!contact->has_friction())
        return;
      using Entry = std::pair<std::string, std::vector<double>>;
      std::map<std::string, std::vector<double>> saved;
      for (auto &[id, values] :
           checkpoint.get<std::vector<Entry>>("obstacles/anchors"))
        saved[id] = values;
      const unsigned int stride = friction_stride();
      anchors.assign(membrane.reference_geometry().n_cells() * stride,
                     PointFriction());
      unsigned int c = 0;
      for (const auto &cell : membrane.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto it = saved.find(cell->id().to_string());
            if (it != saved.end() && !it->second.empty())
              {
                check_input(it->second.size() == 4 * stride,
                            "--restart " + checkpoint.directory(),
                            "the checkpoint's friction state has another "
                            "number of points or obstacles");
                for (unsigned int i = 0; i < stride; ++i)
                  anchors[std::size_t(c) * stride + i] = {
                    Tensor<1, 3>({it->second[4 * i + 1],
                                  it->second[4 * i + 2],
                                  it->second[4 * i + 3]}),
                    it->second[4 * i] != 0.};
              }
            ++c;
          }
    }

    std::unique_ptr<membrane::CellTerms::Scratch>
    ObstacleSubsystem::new_scratch() const
    {
      auto scratch = std::make_unique<SumsScratch>();
      scratch->sums.resize(contact->size());
      const unsigned int n = 3 * membrane.reference_geometry().n_nodes();
      scratch->matrix.assign(force_controlled.size(), FullMatrix<double>(n, n));
      scratch->residual.assign(force_controlled.size(), Vector<double>(n));
      scratch->sinks.resize(contact->size());
      return scratch;
    }

    std::unique_ptr<membrane::CellTerms::Record>
    ObstacleSubsystem::new_record() const
    {
      auto               record = std::make_unique<ForceRecord>();
      const unsigned int n      = force_controlled.size();
      record->force.resize(n);
      record->stiffness.resize(n);
      record->points.resize(n);
      record->B.resize(n);
      record->C.resize(n);
      return record;
    }

    void
    ObstacleSubsystem::cell(const DoFHandler<2, 3>::active_cell_iterator &cell,
                            const membrane::ReferenceGeometry &reference,
                            const unsigned int                 cell_index,
                            const std::vector<double>         &local_u,
                            FullMatrix<double>                *cell_matrix,
                            Vector<double>                    *cell_residual,
                            membrane::CellTerms::Scratch      &scratch,
                            membrane::CellTerms::Record       &record) const
    {
      auto &sc = static_cast<SumsScratch &>(scratch);
      // A force-controlled obstacle's terms go to its own matrix and
      // residual first (zero between the cells it touches); its point
      // count starts at zero (a thread's sums are not added up).
      for (unsigned int j = 0; j < force_controlled.size(); ++j)
        {
          sc.sinks[force_controlled[j]] = {
            cell_matrix != nullptr ? &sc.matrix[j] : nullptr, &sc.residual[j]};
          sc.sums[force_controlled[j]].points = 0;
        }
      contact->cell(cell->material_id(),
                    reference,
                    cell_index,
                    local_u,
                    assembly_translations,
                    cell_matrix,
                    cell_residual,
                    sc.sums,
                    false,
                    nullptr,
                    friction_of(cell_index),
                    nullptr,
                    force_controlled.empty() ? nullptr : &sc.sinks);
      auto &r = static_cast<ForceRecord &>(record);
      for (unsigned int j = 0; j < force_controlled.size(); ++j)
        {
          r.points[j] = sc.sums[force_controlled[j]].points;
          r.force[j] = r.stiffness[j] = 0.;
          if (r.points[j] == 0)
            continue;
          add_force_row(reference,
                        force_controlled[j],
                        sc.matrix[j],
                        sc.residual[j],
                        cell_matrix,
                        cell_residual,
                        r,
                        j);
          sc.residual[j] = 0.;
          if (cell_matrix != nullptr)
            sc.matrix[j] = 0.;
        }
    }

    void
    ObstacleSubsystem::add_force_row(
      const membrane::ReferenceGeometry &reference,
      const unsigned int                 k,
      const FullMatrix<double>          &M,
      const Vector<double>              &f,
      FullMatrix<double>                *cell_matrix,
      Vector<double>                    *cell_residual,
      membrane::CellTerms::Record       &record,
      const unsigned int                 j) const
    {
      auto &r = static_cast<ForceRecord &>(record);
      // E: the rigid motion along e; e . f = E . r, and with the terms
      // depending on x - s e: dr/ds = -M E, d(E . r)/du = M^T E. The row
      // is g = -(F + e . f) = dPi/ds (Pi the potential with the load's
      // -F s): B = -M E, C = -M^T E (= B where M is symmetric), D = E M E.
      const unsigned int n = f.size();
      const auto        &e = parameters.obstacles[k].force_direction;
      Vector<double>     E(n);
      for (unsigned int i = 0; i < n; ++i)
        E[i] = e[reference.component(i)];
      r.force[j] = E * f;
      if (cell_residual != nullptr)
        *cell_residual += f;
      if (cell_matrix == nullptr)
        return;
      cell_matrix->add(1., M);
      r.B[j].reinit(n);
      r.C[j].reinit(n);
      M.vmult(r.B[j], E);
      r.B[j] *= -1.;
      M.Tvmult(r.C[j], E);
      r.C[j] *= -1.;
      r.stiffness[j] = -(r.B[j] * E);
    }

    void
    ObstacleSubsystem::commit(const membrane::CellTerms::Record &record,
                              const std::vector<types::global_dof_index> &dofs)
    {
      const auto &r = static_cast<const ForceRecord &>(record);
      for (unsigned int j = 0; j < force_controlled.size(); ++j)
        {
          if (r.points[j] == 0)
            continue;
          contact_points[j] += r.points[j];
          force_sum[j] += r.force[j];
          stiffness_sum[j] += r.stiffness[j];
          if (assembly->tangent == nullptr || assembly->coupling == nullptr)
            continue;
          const unsigned int row = model.border_offset(*this) + j;
          assembly->constraints->distribute_local_to_global(
            r.B[j], dofs, assembly->coupling->B[row]);
          assembly->constraints->distribute_local_to_global(
            r.C[j], dofs, assembly->coupling->C[row]);
        }
    }

    void
    ObstacleSubsystem::end()
    {
      if (force_controlled.empty())
        return;
      const MPI_Comm     comm   = model.mpi_communicator();
      const auto        &a      = *assembly;
      const bool         matrix = a.tangent != nullptr && a.coupling != nullptr;
      const unsigned int offset = model.border_offset(*this);
      for (unsigned int j = 0; j < force_controlled.size(); ++j)
        {
          const unsigned int row = offset + j;
          const auto        &def = parameters.obstacles[force_controlled[j]];
          const unsigned int points =
            Utilities::MPI::sum(contact_points[j], comm);
          const double f = Utilities::MPI::sum(force_sum[j], comm);
          const double D = Utilities::MPI::sum(stiffness_sum[j], comm);
          if (matrix)
            {
              a.coupling->B[row].compress(VectorOperation::add);
              a.coupling->C[row].compress(VectorOperation::add);
            }
          if (a.coupling != nullptr)
            {
              auto &c = *a.coupling;
              for (unsigned int k = 0; k < c.size(); ++k)
                c.D(row, k) = 0.;
              c.unknown_scale[row]  = 1.;
              c.residual_scale[row] = 1.;
              c.has_B[row] = c.has_C[row] = matrix && points > 0;
              c.primal[row]               = true;
              c.D(row, row)               = points > 0 ? D : 1.;
            }
          // Touching nothing, the obstacle keeps its position.
          double g = (*a.border)[row] - accepted_positions[j];
          if (points > 0)
            {
              def.force->set_time(a.time);
              g = -(def.force->value(Point<3>()) + f);
            }
          (*a.border_residual)[row] = g;
        }
    }

    void
    ObstacleSubsystem::add_loads(const LA::Vector                &u,
                                 const AffineConstraints<double> &constraints,
                                 const double                     t,
                                 LA::Vector                      &residual,
                                 LA::Vector &external) const
    {
      // The contact forces f: -f into the residual, +f into the loads.
      const auto &reference    = membrane.reference_geometry();
      const auto  translations = contact->translations(t);
      LA::Vector  part(residual);
      part = 0.;
      std::vector<double>                  local_u;
      std::vector<types::global_dof_index> dofs(3 * reference.n_nodes());
      Vector<double>                       cell_residual(dofs.size());
      std::vector<ObstacleSums>            unused(contact->size());
      unsigned int                         c = 0;
      for (const auto &cell : membrane.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell_values(u, c, local_u);
            cell_residual = 0.;
            contact->cell(cell->material_id(),
                          reference,
                          c,
                          local_u,
                          translations,
                          nullptr,
                          &cell_residual,
                          unused,
                          false,
                          nullptr,
                          friction_of(c));
            const auto *d = reference.dof_indices(c++);
            dofs.assign(d, d + dofs.size());
            constraints.distribute_local_to_global(cell_residual, dofs, part);
          }
      part.compress(VectorOperation::add);
      residual += part;
      external -= part;
    }

    void
    ObstacleSubsystem::add_statistics(Statistics       &statistics,
                                      const LA::Vector &field,
                                      const double      t) const
    {
      using R              = Statistics::Reduction;
      constexpr auto all   = Statistics::all;
      const auto     total = sums(field, t);
      const auto     moved = contact->translations(t);
      const auto     range = statistics.is_summary()
                               ? penalty_range()
                               : std::vector<std::pair<double, double>>();
      for (unsigned int k = 0; k < total.size(); ++k)
        {
          const auto           &s = total[k];
          const StatisticsGroup g{"obstacle", "obstacles", "obstacle", k + 1};
          statistics.add_vector(g,
                                "force",
                                "N",
                                {{s.force[0], s.force[1], s.force[2]}},
                                all,
                                R::sum);
          statistics.add(g, "contact_area", "m^2", s.area, all, R::sum);
          statistics.add(g, "penetration", "m", s.penetration, all, R::max);
          statistics.add(
            g, "energy", "J", s.energy, Statistics::report, R::sum);
          statistics.add_count(
            g, "contact_points", s.points, Statistics::report, R::sum);
          if (parameters.obstacles[k].friction > 0.)
            {
              statistics.add(
                g, "friction_force", "N", s.friction_force, all, R::sum);
              statistics.add_count(
                g, "slip_points", s.slip_points, Statistics::report, R::sum);
            }
          if (statistics.is_summary())
            {
              statistics.add(
                g, "penalty_min", "Pa/m", range[k].first, Statistics::summary);
              statistics.add(
                g, "penalty_max", "Pa/m", range[k].second, Statistics::summary);
            }
          statistics.add_vector(g,
                                "displacement",
                                "m",
                                {{moved[k][0], moved[k][1], moved[k][2]}},
                                Statistics::report);
        }
    }

    void
    ObstacleSubsystem::add_output_fields(const LA::Vector &field,
                                         const double      t)
    {
      const auto n = membrane.triangulation().n_active_cells();
      std::vector<ObstacleCellOutput> cells(n);
      sums(field, t, &cells);
      pressure_output.reinit(n);
      gap_output.reinit(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          pressure_output[i] = cells[i].pressure;
          // Cells of other ranks keep no gap.
          gap_output[i] = cells[i].gap < 1e300 ? cells[i].gap : 0.;
        }
      auto &out = membrane.data_out();
      out.add_data_vector(pressure_output,
                          "obstacle_pressure",
                          DataOut<2, 3>::type_cell_data);
      out.add_data_vector(gap_output,
                          "obstacle_gap",
                          DataOut<2, 3>::type_cell_data);
    }
  } // namespace contact
} // namespace pneuma

PNEUMA_REGISTER_SUBSYSTEM(pneuma::contact::ObstacleSubsystem,
                          "obstacles",
                          45,
                          pneuma::contact::ObstacleSubsystem::declare_switches,
                          pneuma::contact::ObstacleSubsystem::is_active)
