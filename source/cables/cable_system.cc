#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/data_out.h>

#include <pneuma/cables/cable_element.h>
#include <pneuma/cables/cable_shape.h>
#include <pneuma/cables/cable_system.h>
#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/output.h>
#include <pneuma/loads/loads.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace pneuma
{
  namespace cables
  {
    struct CableSystem::Body
    {
      explicit Body(const CableDefinition &d)
        : definition(d)
        , element(*d.element)
        , dof_handler(tria)
      {
      }

      const CableDefinition &definition;
      /// The cable's element (prepared by setup()).
      CableElement                   &element;
      Triangulation<1, 3>             tria;
      std::unique_ptr<FESystem<1, 3>> fe;
      DoFHandler<1, 3>                dof_handler;
      unsigned int                    n_components = 3;
      /// Global index of local dof 0.
      types::global_dof_index offset = 0;
      /// Reference values of every local dof: position (components 0-2),
      /// then the element's own (the solid beam's semi-axis vectors A1, A2).
      Vector<double> reference;
      /// Reference length / unstressed length (rho_full: of the given
      /// Unstressed length, before a ramp).
      double rho = 1., rho_full = 1., reference_length = 0.;
      /// Local dofs of the start, end and middle node (all components).
      std::vector<types::global_dof_index> start_dofs, end_dofs, mid_dofs;
      Point<3>                             start_point, end_point;
      /// Reused for every cell: the element's quadrature for its terms,
      /// two Gauss points for the loads.
      std::unique_ptr<FEValues<1, 3>> element_values, load_values;
      /// The end moment at the current time (zero without one).
      Tensor<1, 3>
      end_moment() const
      {
        Tensor<1, 3> M;
        if (definition.has_end_moment && !end_dofs.empty())
          for (unsigned int c = 0; c < 3; ++c)
            M[c] = definition.end_moment->value(end_point, c);
        return M;
      }
      /// The end node's reference values and unknowns (all components).
      void
      end_node(const Vector<double> &local_u,
               Vector<double>       &node_reference,
               Vector<double>       &node_u) const
      {
        node_reference.reinit(n_components);
        node_u.reinit(n_components);
        for (unsigned int c = 0; c < n_components; ++c)
          {
            node_reference[c] = reference[end_dofs[c]];
            node_u[c]         = local_u[end_dofs[c]];
          }
      }
      /// With an end moment: the rotation of the end section since the
      /// start, at the last converged step.
      double section_rotation = 0.;
    };

    namespace
    {
      const MappingQ1<1, 3> &
      mapping()
      {
        static const MappingQ1<1, 3> m;
        return m;
      }

      template <typename Iterator>
      Tensor<1, 3>
      cell_tangent(const Iterator &cell)
      {
        const Tensor<1, 3> d = cell->vertex(1) - cell->vertex(0);
        return d / d.norm();
      }

      /// Lengths are in metres, as for the membrane (scene_generator.cc): a
      /// cable of no extent or of an astronomical one is a typing error
      /// (e.g. a point at 1e300, whose element lengths overflow).
      void
      check_extent(const Triangulation<1, 3> &tria, const std::string &where)
      {
        const auto   box    = GridTools::compute_bounding_box(tria);
        const double extent = box.get_boundary_points().first.distance(
          box.get_boundary_points().second);
        if (!(std::isfinite(extent) && extent >= 1e-6 && extent <= 1e6))
          {
            std::ostringstream m;
            m << "the cable spans " << std::setprecision(3) << extent
              << " m; lengths are in metres (1e-6 m to 1e6 m)";
            throw InputError(where, m.str());
          }
      }
    } // namespace

    CableSystem::CableSystem(const CableParameters &parameters,
                             const loads::Loads    &loads)
      : parameters(parameters)
      , loads(loads)
    {
    }

    CableSystem::~CableSystem() = default;

    CableView
    CableSystem::view(const unsigned int k) const
    {
      const Body &b = *bodies[k];
      CableView   v;
      v.dof_handler = &b.dof_handler;
      v.offset      = b.offset;
      v.reference   = &b.reference;
      v.radius      = std::max(b.definition.section_a, b.definition.section_b);
      v.section_components = b.element.section_vector_components();
      return v;
    }

    std::vector<std::vector<types::global_dof_index>>
    CableSystem::node_dofs(const unsigned int k, const bool ends_only) const
    {
      const Body                                       &b = *bodies[k];
      std::vector<std::vector<types::global_dof_index>> result;
      const auto global = [&](std::vector<types::global_dof_index> dofs) {
        for (auto &i : dofs)
          i += b.offset;
        return dofs;
      };
      if (ends_only)
        {
          if (!b.start_dofs.empty())
            {
              result.push_back(global(b.start_dofs));
              result.push_back(global(b.end_dofs));
            }
          return result;
        }
      // FE_Q(1)^n: the dofs of a vertex are its components.
      std::vector<bool> seen(b.tria.n_vertices(), false);
      for (const auto &cell : b.dof_handler.active_cell_iterators())
        for (unsigned int v = 0; v < 2; ++v)
          if (!seen[cell->vertex_index(v)])
            {
              seen[cell->vertex_index(v)] = true;
              std::vector<types::global_dof_index> dofs;
              for (unsigned int c = 0; c < b.n_components; ++c)
                dofs.push_back(b.offset + cell->vertex_dof_index(v, c));
              result.push_back(dofs);
            }
      return result;
    }

    void
    CableSystem::set_output_field(const unsigned int    k,
                                  const std::string    &name,
                                  const Vector<double> &values)
    {
      extra_fields.resize(bodies.size());
      for (auto &f : extra_fields[k])
        if (f.first == name)
          {
            f.second = values;
            return;
          }
      extra_fields[k].emplace_back(name, values);
    }

    double
    CableSystem::axial_stiffness() const
    {
      double EA = 0.;
      for (unsigned int k = 0; k < parameters.size(); ++k)
        EA = std::max(EA, parameters[k].youngs_modulus * parameters[k].area());
      return EA;
    }

    unsigned int
    CableSystem::n_cells() const
    {
      unsigned int n = 0;
      for (const auto &b : bodies)
        n += b->tria.n_active_cells();
      return n;
    }

    void
    CableSystem::setup(const types::global_dof_index first_dof,
                       const MPI_Comm                comm_)
    {
      comm     = comm_;
      rank     = Utilities::MPI::this_mpi_process(comm);
      n_ranks  = Utilities::MPI::n_mpi_processes(comm);
      is_owner = rank == 0;
      first    = first_dof;
      bodies.clear();
      types::global_dof_index next = first;
      for (unsigned int k = 0; k < parameters.size(); ++k)
        {
          const CableDefinition &d = parameters[k];
          auto                   b = std::make_unique<Body>(d);
          d.shape->create_mesh(d.n_elements, b->tria);
          check_extent(b->tria, d.path + "/" + d.shape_name);
          // The distributed load must be finite along the cable at t = 0.
          {
            std::vector<Point<3>> nodes(b->tria.get_vertices());
            d.distributed_load->set_time(0.);
            const std::string bad =
              loads::first_non_finite(*d.distributed_load, nodes);
            check_input(bad.empty(),
                        d.path + "/Distributed load/Function expression",
                        bad);
          }
          CableElement &element = b->element;
          b->n_components       = element.n_components();
          b->fe =
            std::make_unique<FESystem<1, 3>>(FE_Q<1, 3>(1), b->n_components);
          b->dof_handler.distribute_dofs(*b->fe);
          b->element_values =
            std::make_unique<FEValues<1, 3>>(mapping(),
                                             *b->fe,
                                             element.quadrature(),
                                             update_values | update_gradients
                                               | update_JxW_values);
          b->load_values =
            std::make_unique<FEValues<1, 3>>(mapping(),
                                             *b->fe,
                                             QGauss<1>(2),
                                             update_values
                                               | update_quadrature_points
                                               | update_JxW_values);
          b->offset = next;
          next += b->dof_handler.n_dofs();

          // Reference length and the prestress ratio rho = L_ref / L_0.
          for (const auto &cell : b->tria.active_cell_iterators())
            b->reference_length += cell->diameter();
          // A section wider than the whole cable is a typing error (and
          // its contact would search the whole membrane at every point).
          check_input(std::max(d.section_a, d.section_b) < b->reference_length,
                      d.path + "/Section semi-axes",
                      "a semi-axis of "
                        + std::to_string(std::max(d.section_a, d.section_b))
                        + " m is not below the cable's length "
                        + std::to_string(b->reference_length) + " m");
          const double EA = d.youngs_modulus * d.area();
          if (d.prestress_force > 0.)
            b->rho = 1. + staged_prestress(d, 0.) / EA;
          else if (d.unstressed_length > 0.)
            b->rho = b->reference_length / d.unstressed_length;
          // The unramped ratio (a set-up again for a refinement cycle may
          // find the last run's ramp still set; the run resets it).
          b->rho_full =
            d.prestress_force > 0. ? 1. + d.prestress_force / EA : b->rho;
          element.setup(d, b->rho);

          // Node tangents (mean of the adjacent cells) for the sections.
          const unsigned int        n_v = b->tria.n_vertices();
          std::vector<Tensor<1, 3>> node_tangent(n_v);
          std::vector<unsigned int> n_adjacent(n_v, 0);
          for (const auto &cell : b->tria.active_cell_iterators())
            for (unsigned int v = 0; v < 2; ++v)
              {
                node_tangent[cell->vertex_index(v)] += cell_tangent(cell);
                ++n_adjacent[cell->vertex_index(v)];
              }
          // Reference values: the positions, and the element's own.
          b->reference.reinit(b->dof_handler.n_dofs());
          std::vector<double> values(b->n_components);
          for (const auto &cell : b->dof_handler.active_cell_iterators())
            for (unsigned int v = 0; v < 2; ++v)
              {
                CableNode node;
                node.position = cell->vertex(v);
                node.tangent  = node_tangent[cell->vertex_index(v)];
                node.tangent /= node.tangent.norm();
                node.section_direction =
                  d.shape->section_direction(node.position);
                for (unsigned int c = 0; c < 3; ++c)
                  values[c] = node.position[c];
                element.reference_values(node, make_array_view(values));
                for (unsigned int c = 0; c < b->n_components; ++c)
                  b->reference[cell->vertex_dof_index(v, c)] = values[c];
              }

          // Ends: the boundary vertices; the start is the one nearest to the
          // first vertex of the mesh. The middle: the node nearest to half
          // the arc length along the cells.
          std::vector<std::pair<Point<3>, std::vector<types::global_dof_index>>>
            ends;
          for (const auto &cell : b->dof_handler.active_cell_iterators())
            for (unsigned int v = 0; v < 2; ++v)
              if (cell->at_boundary(v))
                {
                  std::vector<types::global_dof_index> dofs;
                  for (unsigned int c = 0; c < b->n_components; ++c)
                    dofs.push_back(cell->vertex_dof_index(v, c));
                  ends.emplace_back(cell->vertex(v), dofs);
                }
          if (ends.size() == 2)
            {
              const Point<3> first_vertex = b->tria.get_vertices()[0];
              if (ends[1].first.distance(first_vertex)
                  < ends[0].first.distance(first_vertex))
                std::swap(ends[0], ends[1]);
              b->start_point = ends[0].first;
              b->start_dofs  = ends[0].second;
              b->end_point   = ends[1].first;
              b->end_dofs    = ends[1].second;
            }
          double s = 0., best = std::numeric_limits<double>::max();
          for (const auto &cell : b->dof_handler.active_cell_iterators())
            {
              s += cell->diameter();
              const double gap = std::abs(s - 0.5 * b->reference_length);
              if (gap < best)
                {
                  best = gap;
                  b->mid_dofs.clear();
                  for (unsigned int c = 0; c < b->n_components; ++c)
                    b->mid_dofs.push_back(cell->vertex_dof_index(1, c));
                }
            }
          bodies.push_back(std::move(b));
        }
      n_cable_dofs = next - first;
    }

    IndexSet
    CableSystem::locally_owned_dofs(const types::global_dof_index size) const
    {
      IndexSet owned(size);
      if (is_owner && n_cable_dofs > 0)
        owned.add_range(first, first + n_cable_dofs);
      return owned;
    }

    IndexSet
    CableSystem::all_dofs(const types::global_dof_index size) const
    {
      IndexSet all(size);
      if (n_cable_dofs > 0)
        all.add_range(first, first + n_cable_dofs);
      return all;
    }

    bool
    CableSystem::assembles(const std::size_t element) const
    {
      return (element * n_ranks) / std::max<std::size_t>(n_cells(), 1) == rank;
    }

    void
    CableSystem::add_support_constraints(
      AffineConstraints<double> &constraints) const
    {
      // Every rank that stores a supported dof constrains it, not only the
      // owner (rank 0): contact assembles cable forces on the rank of the
      // membrane cell, and a rank that did not know an end node is held
      // would add them to its row, which then moved in the update (2 ranks
      // disagreed with 1 and stalled on the tensairity scene).
      for (const auto &b : bodies)
        {
          const auto add =
            [&](const EndSupport                            s,
                const std::array<bool, 3>                  &held,
                const std::vector<types::global_dof_index> &dofs) {
              if (s == EndSupport::free)
                return;
              const unsigned int n =
                (s == EndSupport::fixed) ? b->n_components : 3;
              for (unsigned int c = 0; c < n; ++c)
                if ((c >= 3 || held[c])
                    && constraints.can_store_line(b->offset + dofs[c]))
                  constraints.add_line(b->offset + dofs[c]);
            };
          add(b->definition.start_support,
              b->definition.start_components,
              b->start_dofs);
          add(b->definition.end_support,
              b->definition.end_components,
              b->end_dofs);
        }
    }

    void
    CableSystem::first_guess(const double t, LA::Vector &solution) const
    {
      if (!is_owner)
        return;
      for (const auto &b : bodies)
        {
          const CableDefinition &d = b->definition;
          // Slack: rho = L_ref / L0 < 1.
          if (b->rho >= 1.)
            continue;
          const Tensor<1, 3> chord  = b->end_point - b->start_point;
          const double       length = chord.norm();
          if (length == 0.)
            continue;
          const Tensor<1, 3> axis = chord / length;
          // A straight reference only (a sagged polyline is its own guess).
          bool straight = true;
          for (const auto &cell : b->tria.active_cell_iterators())
            for (unsigned int v = 0; v < 2; ++v)
              {
                const Tensor<1, 3> x = cell->vertex(v) - b->start_point;
                straight &= (x - (x * axis) * axis).norm() <= 1e-9 * length;
              }
          if (!straight)
            continue;
          // The dead load at the middle, its part normal to the chord.
          const Point<3> middle = b->start_point + 0.5 * chord;
          Tensor<1, 3>   w;
          if (loads.has_gravity() && d.density > 0.)
            w += d.density * d.area() * loads.gravity(t);
          if (d.has_distributed_load)
            {
              d.distributed_load->set_time(t);
              for (unsigned int c = 0; c < 3; ++c)
                w[c] += d.distributed_load->value(middle, c);
            }
          w -= (w * axis) * axis;
          if (w.norm() == 0.)
            continue;
          const Tensor<1, 3> down = w / w.norm();
          // The parabola k x (L - x), k = 4 f / L^2, stretched a little
          // beyond L0 so that it carries a tension (a stress-free chain of
          // bars has no lateral stiffness): by H / EA with the inextensible
          // parabola's H = q L^2 / (8 f). Its arc length from 0 to x is
          // (G(k L) - G(k (L - 2 x))) / (2 k), G(u) = (u sqrt(1 + u^2) +
          // asinh(u)) / 2, so the whole arc is G(k L) / k; f by bisection.
          const auto G = [](const double u) {
            return 0.5 * (u * std::sqrt(1. + u * u) + std::asinh(u));
          };
          const double L0  = b->reference_length / b->rho;
          const auto   arc = [&](const double f) {
            const double k = 4. * f / (length * length);
            return G(k * length) / k;
          };
          const auto sag_of = [&](const double target) {
            double lo = 1e-12 * length, hi = target;
            for (unsigned int i = 0; i < 100; ++i)
              (arc(0.5 * (lo + hi)) < target ? lo : hi) = 0.5 * (lo + hi);
            return 0.5 * (lo + hi);
          };
          const double EA = d.youngs_modulus * d.area();
          const double H  = w.norm() * length * length / (8. * sag_of(L0));
          const double f  = sag_of(L0 * (1. + H / EA));
          // Nodes equally spaced along the arc, as along the reference.
          const double k      = 4. * f / (length * length);
          const auto   arc_to = [&](const double x) {
            return (G(k * length) - G(k * (length - 2. * x))) / (2. * k);
          };
          const double total = G(k * length) / k;
          for (const auto &cell : b->dof_handler.active_cell_iterators())
            for (unsigned int v = 0; v < 2; ++v)
              {
                const double s  = (cell->vertex(v) - b->start_point) * axis;
                double       lo = 0., hi = length;
                for (unsigned int i = 0; i < 100; ++i)
                  (arc_to(0.5 * (lo + hi)) < s / length * total ? lo : hi) =
                    0.5 * (lo + hi);
                const double x     = 0.5 * (lo + hi);
                const double sag   = k * x * (length - x);
                const double slope = k * (length - 2. * x);
                for (unsigned int c = 0; c < 3; ++c)
                  solution[b->offset + cell->vertex_dof_index(v, c)] =
                    (x - s) * axis[c] + sag * down[c];
                // Further components are vectors of the section (the solid
                // beam's semi-axes): turned by the mid-line's angle about
                // axis x down.
                const double       angle = std::atan(slope);
                const Tensor<1, 3> n     = cross_product_3d(axis, down);
                for (unsigned int c0 = 3; c0 + 2 < b->n_components; c0 += 3)
                  {
                    Tensor<1, 3> A;
                    for (unsigned int c = 0; c < 3; ++c)
                      A[c] = b->reference[cell->vertex_dof_index(v, c0 + c)];
                    // Rodrigues' rotation about n.
                    const Tensor<1, 3> R =
                      A * std::cos(angle)
                      + cross_product_3d(n, A) * std::sin(angle)
                      + n * (n * A) * (1. - std::cos(angle));
                    for (unsigned int c = 0; c < 3; ++c)
                      solution[b->offset + cell->vertex_dof_index(v, c0 + c)] =
                        R[c] - A[c];
                  }
              }
        }
    }

    void
    CableSystem::set_prescribed_values(const double t,
                                       LA::Vector  &solution) const
    {
      if (is_owner)
        for (const auto &b : bodies)
          {
            const auto set =
              [&](const EndSupport                            s,
                  const std::array<bool, 3>                  &held,
                  Functions::ParsedFunction<3>               &f,
                  const Point<3>                             &x,
                  const std::vector<types::global_dof_index> &dofs) {
                if (s == EndSupport::free)
                  return;
                f.set_time(t);
                for (unsigned int c = 0; c < 3; ++c)
                  if (held[c])
                    solution[b->offset + dofs[c]] = f.value(x, c);
                if (s == EndSupport::fixed)
                  for (unsigned int c = 3; c < b->n_components; ++c)
                    solution[b->offset + dofs[c]] = 0.;
              };
            set(b->definition.start_support,
                b->definition.start_components,
                *b->definition.start_displacement,
                b->start_point,
                b->start_dofs);
            set(b->definition.end_support,
                b->definition.end_components,
                *b->definition.end_displacement,
                b->end_point,
                b->end_dofs);
          }
      solution.compress(VectorOperation::insert);
    }

    void
    CableSystem::add_sparsity(
      DynamicSparsityPattern          &dsp,
      const AffineConstraints<double> &constraints) const
    {
      // The owner's rows hold every element's couplings; another rank
      // also writes those of its share of the elements (assemble()), whose
      // rows it must have in its pattern.
      std::size_t index = 0;
      for (const auto &b : bodies)
        {
          std::vector<types::global_dof_index> dofs(b->fe->n_dofs_per_cell());
          for (const auto &cell : b->dof_handler.active_cell_iterators())
            {
              if (!assembles(index++) && !is_owner)
                continue;
              cell->get_dof_indices(dofs);
              for (auto &i : dofs)
                i += b->offset;
              constraints.add_entries_local_to_global(dofs, dsp, false);
            }
        }
    }

    Vector<double>
    CableSystem::extract(const Body &b, const LA::Vector &u) const
    {
      Vector<double> local(b.dof_handler.n_dofs());
      for (unsigned int i = 0; i < local.size(); ++i)
        local[i] = u[b.offset + i];
      return local;
    }

    void
    CableSystem::cell_terms(const Body                                   &b,
                            const DoFHandler<1, 3>::active_cell_iterator &cell,
                            const double                                  t,
                            const Vector<double>                         &u,
                            FullMatrix<double> *cell_matrix,
                            Vector<double>     *cell_residual,
                            Vector<double>     *cell_external,
                            CableCellOutput    *cell_output) const
    {
      const CableDefinition               &d  = b.definition;
      const FiniteElement<1, 3>           &fe = *b.fe;
      const unsigned int                   n  = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dofs(n);
      cell->get_dof_indices(dofs);
      Vector<double> local_ref(n), local_u(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          local_ref[i] = b.reference[dofs[i]];
          local_u[i]   = u[dofs[i]];
        }
      const Tensor<1, 3> tangent = cell_tangent(cell);

      // Internal forces: the element's.
      FEValues<1, 3> &fe_values = *b.element_values;
      fe_values.reinit(cell);
      b.element.cell_terms(fe_values,
                           tangent,
                           local_ref,
                           local_u,
                           cell_matrix,
                           cell_residual,
                           cell_output);

      // Dead loads per unstressed length: gravity on density * area, and the
      // distributed load. Mid-line dofs only.
      const bool gravity = loads.has_gravity() && d.density > 0.;
      if ((gravity || d.has_distributed_load)
          && (cell_residual || cell_external))
        {
          FEValues<1, 3> &load_values = *b.load_values;
          load_values.reinit(cell);
          const Tensor<1, 3> g_vec = loads.gravity(t);
          d.distributed_load->set_time(t);
          for (const unsigned int q : load_values.quadrature_point_indices())
            {
              Tensor<1, 3> w;
              if (gravity)
                w += d.density * d.area() * g_vec;
              if (d.has_distributed_load)
                for (unsigned int c = 0; c < 3; ++c)
                  w[c] +=
                    d.distributed_load->value(load_values.quadrature_point(q),
                                              c);
              // Per unstressed length -> per reference length.
              w /= b.rho;
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int ci = fe.system_to_component_index(i).first;
                  if (ci >= 3)
                    continue;
                  const double f =
                    load_values.shape_value(i, q) * w[ci] * load_values.JxW(q);
                  if (cell_residual)
                    (*cell_residual)(i) -= f;
                  if (cell_external)
                    (*cell_external)(i) += f;
                }
            }
        }
    }

    void
    CableSystem::assemble(const double                     t,
                          const LA::Vector                &u,
                          const AffineConstraints<double> &constraints,
                          LA::SparseMatrix                *tangent,
                          LA::Vector                      *residual,
                          LA::Vector                      *external) const
    {
      stage_prestress(t);
      // The elements are shared out over the ranks in contiguous ranges
      // (every rank sees all cable unknowns, add_locally_relevant()): the
      // solid beam's elements cost as much as a tenth of the membrane's
      // cells at the target size of the waterbeam with cables, which the
      // other ranks would otherwise wait for. The rows stay on rank 0.
      std::size_t index = 0;
      for (const auto &b : bodies)
        {
          const Vector<double> local_u = extract(*b, u);
          const unsigned int   n       = b->fe->n_dofs_per_cell();
          FullMatrix<double>   cell_matrix(n, n);
          Vector<double>       cell_residual(n), cell_external(n);
          std::vector<types::global_dof_index> dofs(n);
          for (const auto &cell : b->dof_handler.active_cell_iterators())
            {
              if (!assembles(index++))
                continue;
              cell_matrix   = 0.;
              cell_residual = 0.;
              cell_external = 0.;
              cell_terms(*b,
                         cell,
                         t,
                         local_u,
                         tangent ? &cell_matrix : nullptr,
                         &cell_residual,
                         &cell_external,
                         nullptr);
              cell->get_dof_indices(dofs);
              for (auto &i : dofs)
                i += b->offset;
              LA::distribute(constraints,
                             cell_matrix,
                             cell_residual,
                             dofs,
                             tangent,
                             residual);
              if (external)
                constraints.distribute_local_to_global(cell_external,
                                                       dofs,
                                                       *external);
            }
          if (!is_owner)
            continue;

          // Dead end forces and the end moment.
          const CableDefinition &d = b->definition;
          if (d.has_end_forces && !b->start_dofs.empty())
            for (const auto &[f, x, end_dofs] :
                 {std::make_tuple(d.start_force.get(),
                                  b->start_point,
                                  &b->start_dofs),
                  std::make_tuple(d.end_force.get(),
                                  b->end_point,
                                  &b->end_dofs)})
              {
                f->set_time(t);
                Vector<double>                       force(3);
                std::vector<types::global_dof_index> fdofs(3);
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    force[c] = f->value(x, c);
                    fdofs[c] = b->offset + (*end_dofs)[c];
                  }
                if (external)
                  constraints.distribute_local_to_global(force,
                                                         fdofs,
                                                         *external);
                force *= -1.;
                if (residual)
                  constraints.distribute_local_to_global(force,
                                                         fdofs,
                                                         *residual);
              }
          d.end_moment->set_time(t);
          const Tensor<1, 3> M = b->end_moment();
          if (M.norm() > 0.)
            {
              const unsigned int nc = b->n_components;
              Vector<double>     node_reference, node_u;
              b->end_node(local_u, node_reference, node_u);
              FullMatrix<double> node_matrix(nc, nc);
              Vector<double>     node_residual(nc), node_external(nc);
              b->element.end_moment_terms(
                M, node_reference, node_u, &node_matrix, &node_residual);
              std::vector<types::global_dof_index> mdofs(nc);
              for (unsigned int c = 0; c < nc; ++c)
                mdofs[c] = b->offset + b->end_dofs[c];
              LA::distribute(constraints,
                             node_matrix,
                             node_residual,
                             mdofs,
                             tangent,
                             residual);
              if (external)
                {
                  node_external = node_residual;
                  node_external *= -1.;
                  constraints.distribute_local_to_global(node_external,
                                                         mdofs,
                                                         *external);
                }
            }
        }
      if (residual)
        residual->compress(VectorOperation::add);
      if (external)
        external->compress(VectorOperation::add);
      if (tangent)
        tangent->compress(VectorOperation::add);
    }

    void
    CableSystem::assemble_regularisation(
      const AffineConstraints<double> &constraints,
      LA::SparseMatrix                &matrix) const
    {
      if (is_owner)
        for (const auto &b : bodies)
          {
            const FiniteElement<1, 3>           &fe = *b->fe;
            const unsigned int                   n  = fe.n_dofs_per_cell();
            FEValues<1, 3>                       fe_values(mapping(),
                                     fe,
                                     QGauss<1>(1),
                                     update_gradients | update_JxW_values);
            FullMatrix<double>                   cell_matrix(n, n);
            std::vector<types::global_dof_index> dofs(n);
            for (const auto &cell : b->dof_handler.active_cell_iterators())
              {
                fe_values.reinit(cell);
                cell_matrix = 0.;
                for (const unsigned int q :
                     fe_values.quadrature_point_indices())
                  for (unsigned int i = 0; i < n; ++i)
                    for (unsigned int j = 0; j < n; ++j)
                      if (fe.system_to_component_index(i).first
                          == fe.system_to_component_index(j).first)
                        cell_matrix(i, j) += fe_values.shape_grad(i, q)
                                             * fe_values.shape_grad(j, q)
                                             * fe_values.JxW(q);
                cell->get_dof_indices(dofs);
                for (auto &i : dofs)
                  i += b->offset;
                constraints.distribute_local_to_global(cell_matrix,
                                                       dofs,
                                                       matrix);
              }
          }
      matrix.compress(VectorOperation::add);
    }

    void
    CableSystem::assemble_mass(const AffineConstraints<double> &constraints,
                               LA::SparseMatrix                &matrix) const
    {
      if (is_owner)
        for (const auto &b : bodies)
          {
            const FiniteElement<1, 3> &fe = *b->fe;
            const unsigned int         n  = fe.n_dofs_per_cell();
            // Per unstressed length, as gravity; per reference length.
            const double rho_A =
              b->definition.density * b->definition.area() / b->rho;
            FEValues<1, 3>                       fe_values(mapping(),
                                     fe,
                                     QGauss<1>(fe.degree + 1),
                                     update_values | update_JxW_values);
            FullMatrix<double>                   cell_matrix(n, n);
            std::vector<types::global_dof_index> dofs(n);
            for (const auto &cell : b->dof_handler.active_cell_iterators())
              {
                fe_values.reinit(cell);
                cell_matrix = 0.;
                for (const unsigned int q :
                     fe_values.quadrature_point_indices())
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const auto [ci, bi] = fe.system_to_component_index(i);
                      if (ci >= 3)
                        continue;
                      for (unsigned int j = 0; j < n; ++j)
                        if (fe.system_to_component_index(j).first == ci)
                          cell_matrix(i, j) +=
                            rho_A * fe_values.shape_value(i, q)
                            * fe_values.shape_value(j, q) * fe_values.JxW(q);
                    }
                cell->get_dof_indices(dofs);
                for (auto &i : dofs)
                  i += b->offset;
                constraints.distribute_local_to_global(cell_matrix,
                                                       dofs,
                                                       matrix);
              }
          }
      matrix.compress(VectorOperation::add);
    }

    void
    CableSystem::lumped_mass(LA::Vector &m) const
    {
      // The row sums of assemble_mass(): rho A int N_i ds on the
      // mid-line's translations (the section unknowns carry none).
      if (is_owner)
        for (const auto &b : bodies)
          {
            const FiniteElement<1, 3> &fe = *b->fe;
            const unsigned int         n  = fe.n_dofs_per_cell();
            const double               rho_A =
              b->definition.density * b->definition.area() / b->rho;
            FEValues<1, 3>                       fe_values(mapping(),
                                     fe,
                                     QGauss<1>(fe.degree + 1),
                                     update_values | update_JxW_values);
            Vector<double>                       cell_mass(n);
            std::vector<types::global_dof_index> dofs(n);
            for (const auto &cell : b->dof_handler.active_cell_iterators())
              {
                fe_values.reinit(cell);
                cell_mass = 0.;
                for (const unsigned int q :
                     fe_values.quadrature_point_indices())
                  for (unsigned int i = 0; i < n; ++i)
                    if (fe.system_to_component_index(i).first < 3)
                      cell_mass(i) +=
                        rho_A * fe_values.shape_value(i, q) * fe_values.JxW(q);
                cell->get_dof_indices(dofs);
                for (auto &i : dofs)
                  i += b->offset;
                m.add(dofs, cell_mass);
              }
          }
      m.compress(VectorOperation::add);
    }

    void
    CableSystem::largest_per_node(LA::Vector &v) const
    {
      if (is_owner)
        for (const auto &b : bodies)
          for (const auto &cell : b->dof_handler.active_cell_iterators())
            for (unsigned int vertex = 0; vertex < 2; ++vertex)
              {
                std::array<types::global_dof_index, 3> n;
                double                                 largest = 0.;
                for (unsigned int c = 0; c < 3; ++c)
                  {
                    n[c]    = b->offset + cell->vertex_dof_index(vertex, c);
                    largest = std::max(largest, double(v[n[c]]));
                  }
                for (const auto i : n)
                  v[i] = largest;
              }
      v.compress(VectorOperation::insert);
    }

    void
    CableSystem::set_mode_fields(const std::vector<std::string> &names,
                                 const std::vector<LA::Vector>  &modes)
    {
      mode_fields.assign(bodies.size(), {});
      for (unsigned int k = 0; k < bodies.size(); ++k)
        for (unsigned int m = 0; m < modes.size(); ++m)
          {
            const Vector<double> all(modes[m]); // every rank calls
            if (is_owner)
              {
                Vector<double> local(bodies[k]->dof_handler.n_dofs());
                for (unsigned int i = 0; i < local.size(); ++i)
                  local[i] = all[bodies[k]->offset + i];
                mode_fields[k].emplace_back(names[m], local);
              }
          }
    }

    int
    CableSystem::translation_component(const types::global_dof_index i) const
    {
      for (const auto &b : bodies)
        if (i >= b->offset && i < b->offset + b->dof_handler.n_dofs())
          {
            // FE_Q(1)^n on lines: the dofs of a vertex are its components.
            const unsigned int c = (i - b->offset) % b->n_components;
            return c < 3 ? int(c) : -1;
          }
      return -1;
    }

    void
    CableSystem::commit_step(const LA::Vector &u)
    {
      if (!is_owner)
        return;
      for (auto &b : bodies)
        {
          const Tensor<1, 3> M = b->end_moment();
          if (M.norm() == 0.)
            continue;
          Vector<double> node_reference, node_u;
          b->end_node(extract(*b, u), node_reference, node_u);
          b->section_rotation =
            b->element.commit_end_moment(M, node_reference, node_u);
        }
    }

    void
    CableSystem::save_checkpoint(Checkpoint &checkpoint) const
    {
      std::vector<std::vector<double>> state;
      for (const auto &b : bodies)
        {
          state.push_back(b->element.committed_state());
          state.back().push_back(b->section_rotation);
        }
      checkpoint.put("cables/state", state);
      checkpoint.put("cables/pvd", series);
    }

    void
    CableSystem::load_checkpoint(const Checkpoint &checkpoint)
    {
      auto state =
        checkpoint.get<std::vector<std::vector<double>>>("cables/state");
      check_input(state.size() == bodies.size(),
                  "--restart " + checkpoint.directory(),
                  "the checkpoint has " + std::to_string(state.size())
                    + " cables, the input " + std::to_string(bodies.size()));
      for (unsigned int k = 0; k < bodies.size(); ++k)
        {
          bodies[k]->section_rotation = state[k].back();
          state[k].pop_back();
          bodies[k]->element.restore_state(state[k]);
        }
      series = checkpoint.get<VtuSeries>("cables/pvd");
    }

    double
    CableSystem::ramp_factor(const double t) const
    {
      if (ramp_end <= ramp_start)
        return 1.;
      return std::clamp((t - ramp_start) / (ramp_end - ramp_start), 0., 1.);
    }

    double
    CableSystem::staged_prestress(const CableDefinition &d,
                                  const double           t) const
    {
      double f = ramp_factor(t);
      if (d.staged_prestress)
        {
          d.prestress_factor->set_time(t);
          f *= d.prestress_factor->value(Point<3>());
        }
      return f * d.prestress_force;
    }

    bool
    CableSystem::ramp_initial_loads(const double t0, const double t1)
    {
      ramp_start = ramp_end = 0.;
      if (t1 <= t0)
        return false;
      bool tensioned = false;
      for (const auto &b : bodies)
        {
          const CableDefinition &d = b->definition;
          if (d.prestress_force > 0.)
            {
              double f = 1.;
              if (d.staged_prestress)
                {
                  d.prestress_factor->set_time(t0);
                  f = d.prestress_factor->value(Point<3>());
                }
              tensioned = tensioned || f != 0.;
            }
          else
            tensioned = tensioned || b->rho_full > 1.;
        }
      if (tensioned)
        {
          ramp_start = t0;
          ramp_end   = t1;
        }
      return tensioned;
    }

    void
    CableSystem::check_prestress(const double t) const
    {
      for (const auto &b : bodies)
        if (b->definition.staged_prestress)
          {
            std::ostringstream when;
            when << "the prestress force f(t) F is not finite at t = " << t;
            check_input(std::isfinite(staged_prestress(b->definition, t)),
                        b->definition.path
                          + "/Prestress factor/Function expression",
                        when.str());
          }
    }

    void
    CableSystem::stage_prestress(const double t) const
    {
      const bool ramped = ramp_end > ramp_start;
      for (const auto &b : bodies)
        {
          const CableDefinition &d = b->definition;
          double                 rho;
          if (d.prestress_force > 0. && (d.staged_prestress || ramped))
            rho = 1. + staged_prestress(d, t) / (d.youngs_modulus * d.area());
          else if (ramped && b->rho_full > 1.)
            rho = 1. + ramp_factor(t) * (b->rho_full - 1.);
          else
            rho = b->rho_full;
          if (rho != b->rho)
            {
              b->rho = rho;
              b->element.set_length_ratio(rho);
            }
        }
    }

    std::vector<CableReport>
    CableSystem::reports(const double      t,
                         const LA::Vector &u,
                         const LA::Vector *support) const
    {
      stage_prestress(t);
      std::vector<CableReport> result;
      if (!is_owner)
        return result;
      for (const auto &b : bodies)
        {
          CableReport          r;
          const Vector<double> local_u = extract(*b, u);
          const unsigned int   n       = b->fe->n_dofs_per_cell();
          Vector<double>       cell_residual(n);
          CableCellOutput      out;
          r.max_force = -std::numeric_limits<double>::max();
          r.min_force = std::numeric_limits<double>::max();
          for (const auto &cell : b->dof_handler.active_cell_iterators())
            {
              cell_residual = 0.;
              cell_terms(
                *b, cell, t, local_u, nullptr, &cell_residual, nullptr, &out);
              r.max_force   = std::max(r.max_force, out.axial_force);
              r.min_force   = std::min(r.min_force, out.axial_force);
              r.max_bending = std::max(r.max_bending, out.bending_moment);
              r.max_torsion = std::max(r.max_torsion, out.torsion_moment);
              Tensor<1, 3> chord;
              for (unsigned int c = 0; c < 3; ++c)
                chord[c] = cell->vertex(1)[c] - cell->vertex(0)[c]
                           + local_u[cell->vertex_dof_index(1, c)]
                           - local_u[cell->vertex_dof_index(0, c)];
              r.length += chord.norm();
            }
          // The reactions: the support residual at the held ends.
          const CableDefinition &d = b->definition;
          for (unsigned int c = 0; c < 3; ++c)
            {
              if (!b->start_dofs.empty())
                {
                  r.start_displacement[c] = local_u[b->start_dofs[c]];
                  r.end_displacement[c]   = local_u[b->end_dofs[c]];
                  if (support)
                    {
                      r.start_reaction[c] =
                        (*support)[b->offset + b->start_dofs[c]];
                      r.end_reaction[c] =
                        (*support)[b->offset + b->end_dofs[c]];
                    }
                  // Only held components have a reaction.
                  if (d.start_support == EndSupport::free
                      || !d.start_components[c])
                    r.start_reaction[c] = 0.;
                  if (d.end_support == EndSupport::free || !d.end_components[c])
                    r.end_reaction[c] = 0.;
                }
              r.mid_displacement[c] = local_u[b->mid_dofs[c]];
            }
          r.end_rotation = b->section_rotation;
          result.push_back(r);
        }
      return result;
    }

    void
    CableSystem::write_output(const std::string &directory,
                              const unsigned int step,
                              const double       t,
                              const LA::Vector  &u)
    {
      if (!is_owner)
        return;
      for (unsigned int k = 0; k < bodies.size(); ++k)
        {
          const Body          &b       = *bodies[k];
          const Vector<double> local_u = extract(b, u);
          // The element's nodal fields (the mid-line displacement first);
          // equal names of consecutive components form a vector.
          const std::vector<std::string> names = b.element.component_names();
          std::vector<DataComponentInterpretation::DataComponentInterpretation>
            interpretation;
          for (const auto &name : names)
            interpretation.push_back(
              std::count(names.begin(), names.end(), name) > 1
                ? DataComponentInterpretation::component_is_part_of_vector
                : DataComponentInterpretation::component_is_scalar);
          const std::vector<std::string> field_names = b.element.output_names();
          std::vector<Vector<double>>    fields(
            field_names.size(), Vector<double>(b.tria.n_active_cells()));
          CableCellOutput out;
          unsigned int    index = 0;
          for (const auto &cell : b.dof_handler.active_cell_iterators())
            {
              cell_terms(b, cell, t, local_u, nullptr, nullptr, nullptr, &out);
              for (unsigned int f = 0; f < fields.size(); ++f)
                fields[f][index] = out.values[f];
              ++index;
            }
          // NaN and inf are never written (core/output.h).
          for (unsigned int f = 0; f < fields.size(); ++f)
            for (const double v : fields[f])
              if (!std::isfinite(v))
                throw NonFiniteOutput(
                  "the field " + field_names[f] + " of cable "
                  + std::to_string(k + 1) + " is not finite at t = "
                  + std::to_string(t) + "; the state is not written");
          DataOut<1, 3> data_out;
          data_out.attach_dof_handler(b.dof_handler);
          data_out.add_data_vector(local_u,
                                   names,
                                   DataOut<1, 3>::type_dof_data,
                                   interpretation);
          for (unsigned int f = 0; f < fields.size(); ++f)
            data_out.add_data_vector(fields[f],
                                     field_names[f],
                                     DataOut<1, 3>::type_cell_data);
          // Mode shapes: the mid-line components as one vector, the
          // element's further components (a solid beam's section) apart.
          if (k < mode_fields.size())
            for (const auto &[name, values] : mode_fields[k])
              {
                std::vector<std::string> mode_names;
                for (unsigned int c = 0; c < names.size(); ++c)
                  mode_names.push_back(c < 3 ? name : name + "_" + names[c]);
                data_out.add_data_vector(values,
                                         mode_names,
                                         DataOut<1, 3>::type_dof_data,
                                         interpretation);
              }
          if (k < extra_fields.size())
            for (const auto &[name, values] : extra_fields[k])
              data_out.add_data_vector(values,
                                       name,
                                       DataOut<1, 3>::type_cell_data);
          data_out.build_patches();
          const std::string name =
            series.file_name(step, k, bodies.size()) + ".vtu";
          std::ofstream file(directory + "/" + name);
          // No date and time in the file: a run repeated is byte-identical.
          DataOutBase::VtkFlags flags;
          flags.print_date_and_time = false;
          data_out.set_flags(flags);
          data_out.write_vtu(file);
          series.add(step, t, name, k);
        }
      // cables.pvd: one dataset per cable ("part") and time.
      AssertThrow(series.write_pvd(directory),
                  ExcMessage("cannot write " + series.name() + ".pvd"));
    }
  } // namespace cables
} // namespace pneuma
