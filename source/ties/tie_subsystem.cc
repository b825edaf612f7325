#include <deal.II/base/mpi.h>

#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/model.h>
#include <pneuma/core/share_constraints.h>
#include <pneuma/core/statistics.h>
#include <pneuma/ties/tie_subsystem.h>

#include <limits>
#include <map>
#include <sstream>

namespace pneuma
{
  namespace ties
  {
    namespace
    {
      membrane::MembraneSubsystem &
      the_membrane(Model &model)
      {
        auto *m = model.find<membrane::MembraneSubsystem>();
        check_input(m != nullptr,
                    "Ties/Number of ties",
                    "ties need a membrane (Geometry/Type is none)");
        return *m;
      }

      cables::CableSubsystem &
      the_cables(Model &model)
      {
        auto *c = model.find<cables::CableSubsystem>();
        check_input(c != nullptr,
                    "Ties/Number of ties",
                    "ties need cables (Cables/Number of cables is 0)");
        return *c;
      }

      std::string
      to_string(const Point<3> &x)
      {
        std::ostringstream s;
        s << "(" << x << ")";
        return s.str();
      }
    } // namespace

    TieSubsystem::TieSubsystem(Model &model)
      : model(model)
      , membrane(the_membrane(model))
      , cables(the_cables(model))
    {
    }

    bool
    TieSubsystem::holds(const Subsystem &other) const
    {
      // A supported cable tied to the membrane may hold it.
      return &other == &membrane;
    }

    void
    TieSubsystem::declare_switches(ParameterHandler &prm)
    {
      TieParameters::declare_count(prm);
    }

    bool
    TieSubsystem::is_active(const InputLayout &layout)
    {
      return !layout.numbered("Ties", "Tie", "Ties/Number of ties").empty();
    }

    void
    TieSubsystem::declare_parameters(ParameterHandler  &prm,
                                     const InputLayout &layout)
    {
      parameters.declare_parameters(prm, layout);
    }

    void
    TieSubsystem::parse_parameters(ParameterHandler &prm)
    {
      const auto &definitions = cables.definitions();
      parameters.parse_parameters(prm, definitions.size());
      check_input(membrane.refinement_cycles() == 0,
                  "Ties/Number of ties",
                  "ties are not available with adaptive refinement (a tied "
                  "node inside a refined cell would follow hanging nodes "
                  "whose masters another rank owns)");
      for (const auto &d : parameters.all())
        {
          const auto &cable = definitions[d.cable];
          const auto  name  = cable.path;
          check_input(!cable.closed() || d.nodes == TiedNodes::all,
                      d.path + "/Nodes",
                      name
                        + " is closed (a ring has no ends): only all "
                          "its nodes can be tied");
          const bool start = d.nodes == TiedNodes::start
                             || d.nodes == TiedNodes::both_ends
                             || d.nodes == TiedNodes::all;
          const bool end = d.nodes == TiedNodes::end
                           || d.nodes == TiedNodes::both_ends
                           || d.nodes == TiedNodes::all;
          check_input(
            (!start || cable.start_support == cables::EndSupport::free)
              && (!end || cable.end_support == cables::EndSupport::free),
            d.path + "/Nodes",
            "ties a supported end of " + name
              + " (set its Start support / End support to free: "
                "the tie holds it)");
          cables.hold(d.cable);
        }
    }

    void
    TieSubsystem::add_locally_relevant(IndexSet &relevant)
    {
      // The search is collective and needs the numbering of every
      // subsystem: it runs here, in the same place on every rank.
      find_constraint_lines();

      membrane_dofs = IndexSet(relevant.size());
      for (const auto &line : lines)
        {
          relevant.add_index(line.dof);
          for (const auto &e : line.entries)
            membrane_dofs.add_index(e.first);
        }
      membrane_dofs.compress();
      relevant.add_indices(membrane_dofs);
    }

    void
    TieSubsystem::find_constraint_lines()
    {
      check_regions();
      const std::vector<TiedNode> nodes = tied_nodes();

      std::vector<std::vector<MembranePoint>> found(nodes.size());
      const std::vector<double> nearest = search_membrane(nodes, found);
      check_distances(nodes, nearest);

      const RowSums sums = share_rows(nodes, found, nearest);
      const auto    tied = make_lines(nodes, sums);
      check_tied_nodes(nodes, tied);
    }

    void
    TieSubsystem::check_regions() const
    {
      // Every region a tie names must exist in the mesh.
      for (const auto &d : parameters.all())
        for (const auto id : d.regions)
          check_input(membrane.material_ids().count(id) > 0,
                      d.path + "/Membrane regions",
                      "the mesh has no cells in region " + std::to_string(id));
    }

    std::vector<TieSubsystem::TiedNode>
    TieSubsystem::tied_nodes() const
    {
      const auto           &all = parameters.all();
      std::vector<TiedNode> nodes;
      for (unsigned int k = 0; k < all.size(); ++k)
        {
          const TieDefinition &d    = all[k];
          const auto           view = cables.system().view(d.cable);
          auto                 dofs =
            cables.system().node_dofs(d.cable, d.nodes != TiedNodes::all);
          if (d.nodes == TiedNodes::start)
            dofs.resize(1);
          else if (d.nodes == TiedNodes::end)
            dofs.erase(dofs.begin());
          for (const auto &node_dofs : dofs)
            {
              TiedNode n;
              n.tie          = k;
              n.dofs         = node_dofs;
              const auto ref = [&](const unsigned int c) {
                return (*view.reference)[node_dofs[c] - view.offset];
              };
              n.position        = Point<3>(ref(0), ref(1), ref(2));
              const auto &slots = view.section_components;
              if (!slots.empty() && d.follow_section)
                {
                  n.section_slots = slots;
                  for (unsigned int v = 0; v < 2; ++v)
                    n.sections.push_back(Tensor<1, 3>({ref(slots[3 * v]),
                                                       ref(slots[3 * v + 1]),
                                                       ref(slots[3 * v + 2])}));
                }
              n.reach = (d.max_distance > 0.) ? d.max_distance : view.radius;
              nodes.push_back(n);
            }
        }
      return nodes;
    }

    std::vector<double>
    TieSubsystem::search_membrane(
      const std::vector<TiedNode>             &nodes,
      std::vector<std::vector<MembranePoint>> &found) const
    {
      const auto         &all = parameters.all();
      std::vector<double> distance(nodes.size());
      for (unsigned int n = 0; n < nodes.size(); ++n)
        {
          found[n]    = nearest_membrane_points(membrane.mapping(),
                                             membrane.dof_handler(),
                                             all[nodes[n].tie].regions,
                                             nodes[n].position,
                                             nodes[n].reach);
          distance[n] = std::numeric_limits<double>::infinity();
          for (const auto &p : found[n])
            distance[n] = std::min(distance[n], p.distance);
        }
      std::vector<double> nearest(nodes.size());
      MPI_Allreduce(distance.data(),
                    nearest.data(),
                    nodes.size(),
                    MPI_DOUBLE,
                    MPI_MIN,
                    model.mpi_communicator());
      return nearest;
    }

    void
    TieSubsystem::check_distances(const std::vector<TiedNode> &nodes,
                                  const std::vector<double>   &nearest)
    {
      const auto &all = parameters.all();
      offsets.assign(all.size(), 0.);
      for (unsigned int n = 0; n < nodes.size(); ++n)
        {
          const TieDefinition &d = all[nodes[n].tie];
          const double         r = nodes[n].reach;
          check_input(nearest[n] <= r * (1. + 1e-9) + 1e-12,
                      d.path + "/Maximum distance",
                      "the node at " + to_string(nodes[n].position) + " of "
                        + cables.definitions()[d.cable].path
                        + (std::isfinite(nearest[n])
                             ? " lies " + std::to_string(nearest[n])
                                 + " m from the membrane, more than"
                             : " has no membrane point within")
                        + (d.regions.empty() ? "" : " (in Membrane regions)")
                        + " the maximum distance " + std::to_string(r) + " m");
          offsets[nodes[n].tie] = std::max(offsets[nodes[n].tie], nearest[n]);
        }
    }

    TieSubsystem::RowSums
    TieSubsystem::share_rows(
      const std::vector<TiedNode>                   &nodes,
      const std::vector<std::vector<MembranePoint>> &found,
      const std::vector<double>                     &nearest) const
    {
      // Every cell (on any rank) whose point is as near as the nearest
      // writes its rows as (node, slot, m, (membrane dof, weight) x m),
      // slot c < 3 the position's component c, section_slots[3 v + c]
      // that of the section vector v. A node on a cell edge or vertex lies in
      // several cells: the rows are averaged over them (the same for the
      // position, the mean of the one-sided gradients for a section vector).
      std::vector<double> local;
      const auto          write = [&](const unsigned int n,
                             const unsigned int slot,
                             const Combination &entries) {
        local.insert(local.end(),
                     {double(n), double(slot), double(entries.size())});
        for (const auto &[j, w] : entries)
          local.insert(local.end(), {double(j), w});
      };
      for (unsigned int n = 0; n < nodes.size(); ++n)
        for (const auto &p : found[n])
          if (p.distance <= nearest[n] + p.tolerance)
            {
              Tensor<1, 3> normal;
              const auto   rows =
                interpolation(membrane.mapping(), p, nodes[n].sections, normal);
              for (unsigned int c = 0; c < 3; ++c)
                write(n, c, rows[c]);
              // A section vector within 30 degrees of the tangent plane
              // follows the membrane: a = A + (grad_S u) A.
              for (unsigned int v = 0; v < nodes[n].sections.size(); ++v)
                {
                  const Tensor<1, 3> &A = nodes[n].sections[v];
                  if (std::abs(A * normal) <= 0.5 * A.norm())
                    for (unsigned int c = 0; c < 3; ++c)
                      write(n,
                            nodes[n].section_slots[3 * v + c],
                            rows[3 * (v + 1) + c]);
                }
            }

      RowSums sum(nodes.size());
      for (const auto &part :
           Utilities::MPI::all_gather(model.mpi_communicator(), local))
        for (std::size_t k = 0; k + 2 < part.size();)
          {
            const auto        n    = static_cast<unsigned int>(part[k]);
            const auto        slot = static_cast<unsigned int>(part[k + 1]);
            const std::size_t m    = static_cast<std::size_t>(part[k + 2]);
            auto             &row  = sum[n][slot];
            ++row.first;
            for (std::size_t e = 0; e < m; ++e)
              row.second[static_cast<types::global_dof_index>(
                part[k + 3 + 2 * e])] += part[k + 4 + 2 * e];
            k += 3 + 2 * m;
          }
      return sum;
    }

    std::set<types::global_dof_index>
    TieSubsystem::make_lines(const std::vector<TiedNode> &nodes,
                             const RowSums               &sums)
    {
      lines.clear();
      std::set<types::global_dof_index> tied;
      for (unsigned int n = 0; n < nodes.size(); ++n)
        for (const auto &[slot, row] : sums[n])
          {
            Line line;
            line.dof = nodes[n].dofs[slot];
            for (const auto &[j, w] : row.second)
              if (w != 0.)
                line.entries.emplace_back(j, w / row.first);
            tied.insert(line.dof);
            lines.push_back(std::move(line));
          }
      return tied;
    }

    void
    TieSubsystem::check_tied_nodes(
      const std::vector<TiedNode>             &nodes,
      const std::set<types::global_dof_index> &tied)
    {
      // Checks every rank makes alike: no node tied twice; a solid beam's
      // section follows through at least one of its vectors.
      const auto &all = parameters.all();
      tied_translations.assign(all.size(), {});
      std::set<types::global_dof_index> seen;
      for (const auto &n : nodes)
        {
          const TieDefinition &d    = all[n.tie];
          const std::string    name = cables.definitions()[d.cable].path;
          check_input(seen.insert(n.dofs[0]).second,
                      d.path + "/Nodes",
                      "the node at " + to_string(n.position) + " of " + name
                        + " is tied twice");
          bool section = n.sections.empty();
          for (const unsigned int i : n.section_slots)
            section = section || tied.count(n.dofs[i]) > 0;
          check_input(section,
                      d.path + "/Section",
                      "neither section semi-axis of " + name + " at the node "
                        + to_string(n.position)
                        + " lies within 30 degrees of the membrane's tangent "
                          "plane, so the section cannot follow the membrane "
                          "(set Section = free)");
          tied_translations[n.tie].insert(tied_translations[n.tie].end(),
                                          n.dofs.begin(),
                                          n.dofs.begin() + 3);
        }
    }

    void
    TieSubsystem::add_kinematic_constraints(AffineConstraints<double> &c) const
    {
      for (const auto &line : lines)
        if (c.can_store_line(line.dof) && !c.is_constrained(line.dof))
          {
            c.add_line(line.dof);
            c.add_entries(line.dof, line.entries);
          }
      // A membrane dof of a tie may itself be constrained (a rigid plate's
      // node follows its masters): every rank must resolve the chain alike.
      share_constraint_lines(c,
                             membrane_dofs,
                             model.locally_owned(),
                             model.mpi_communicator());
    }

    void
    TieSubsystem::add_update_constraints(AffineConstraints<double> &c) const
    {
      // And a supported membrane dof is held in the update.
      share_constraint_lines(c,
                             membrane_dofs,
                             model.locally_owned(),
                             model.mpi_communicator());
    }

    void
    TieSubsystem::add_statistics(Statistics &statistics,
                                 const LA::Vector &,
                                 const double) const
    {
      constexpr auto    all = Statistics::all, summary = Statistics::summary;
      const LA::Vector &r     = model.unconstrained_residual();
      const auto       &owned = model.locally_owned();
      for (unsigned int k = 0; k < tied_translations.size(); ++k)
        {
          // r = f_int - f_ext of everything that loads the tied nodes: the
          // force the tie exerts on them.
          std::vector<double> force(3, 0.);
          for (unsigned int i = 0; i < tied_translations[k].size(); ++i)
            if (owned.is_element(tied_translations[k][i]))
              force[i % 3] += r[tied_translations[k][i]];
          MPI_Allreduce(MPI_IN_PLACE,
                        force.data(),
                        3,
                        MPI_DOUBLE,
                        MPI_SUM,
                        model.mpi_communicator());
          const StatisticsGroup g{"tie", "ties", "tie", k + 1};
          statistics.add_vector(
            g, "force", "N", {{force[0], force[1], force[2]}}, all);
          statistics.add(g, "offset", "m", offsets[k], summary);
        }
    }
  } // namespace ties
} // namespace pneuma

PNEUMA_REGISTER_SUBSYSTEM(pneuma::ties::TieSubsystem,
                          "ties",
                          35,
                          pneuma::ties::TieSubsystem::declare_switches,
                          pneuma::ties::TieSubsystem::is_active)
