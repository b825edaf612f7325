#include <deal.II/base/parsed_function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <pneuma/core/collective_error.h>
#include <pneuma/core/input_error.h>
#include <pneuma/loads/loads.h>
#include <pneuma/membrane/bending/bending_cells.h>
#include <pneuma/membrane/bending/bending_edges.h>
#include <pneuma/membrane/bending/point_geometry.h>
#include <pneuma/membrane/bending/shell_bending.h>
#include <pneuma/membrane/membrane_subsystem.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace pneuma
{
  namespace membrane
  {
    namespace bending
    {
      void
      Parameters::declare(ParameterHandler &prm)
      {
        prm.enter_subsection("Bending");
        prm.declare_entry(
          "Interior penalty factor",
          "2",
          Patterns::Double(),
          "eta of the penalty gamma D / h on the jump of the normal's "
          "rotation across the cells' edges of shell regions (C0 interior "
          "penalty, doc/theory.md 21; D the bending stiffness, h the cell's "
          "size across the edge), gamma = 3 eta on Q2 and eta/2 on Q1; > 0. "
          "The default 2 gives deal.II step-47's gamma = p (p + 1) = 6 on "
          "Q2, and gamma = 1 on Q1, where the kink energy is then the "
          "bending energy of a cylindrical bend across the edges; it "
          "depends on neither the mesh nor the material.");
        prm.declare_entry(
          "Clamped boundaries",
          "",
          Patterns::List(Patterns::Integer(0)),
          "Boundary ids of shell regions whose normal keeps its reference "
          "direction about the edge (clamped edges and symmetry planes; "
          "their displacements are set in Boundary conditions). Other "
          "edges are free to rotate (simply supported or free).");
        prm.declare_entry(
          "Edge moment boundaries",
          "",
          Patterns::List(Patterns::Integer(0)),
          "Boundary ids of shell regions loaded by the Edge moment: a "
          "bending moment per unit length about the edge, work-conjugate to "
          "the rotation of the normal about it (any angle, a roll-up to a "
          "full circle included).");
        loads::declare_function(prm, "Edge moment", 1, "0");
        prm.leave_subsection();
      }

      void
      Parameters::parse(ParameterHandler &prm)
      {
        prm.enter_subsection("Bending");
        penalty_factor = prm.get_double("Interior penalty factor");
        check_input(std::isfinite(penalty_factor) && penalty_factor > 0.,
                    "Bending/Interior penalty factor",
                    "must be positive, got "
                      + prm.get("Interior penalty factor"));
        const auto ids = loads::parse_id_list(prm.get("Clamped boundaries"),
                                              "Bending/Clamped boundaries");
        clamped        = std::set<types::boundary_id>(ids.begin(), ids.end());
        const auto loaded =
          loads::parse_id_list(prm.get("Edge moment boundaries"),
                               "Bending/Edge moment boundaries");
        moment_edges =
          std::set<types::boundary_id>(loaded.begin(), loaded.end());
        moment = std::make_shared<Functions::ParsedFunction<3>>(1);
        loads::parse_function(prm,
                              *moment,
                              "Edge moment",
                              "Bending/Edge moment");
        prm.leave_subsection();
      }

      void
      check_edges(const Parameters                      &parameters,
                  const bool                             has_shell,
                  const std::vector<types::boundary_id> &ids,
                  const std::vector<Point<3>>           &centres,
                  const MPI_Comm                         comm)
      {
        for (const auto &[path, edges] :
             {std::make_pair("Bending/Clamped boundaries", parameters.clamped),
              std::make_pair("Bending/Edge moment boundaries",
                             parameters.moment_edges)})
          {
            check_input(edges.empty() || has_shell,
                        path,
                        "no region is a shell (Materials/Region k/Bending = "
                        "shell): a membrane has no rotations");
            for (const auto b : edges)
              check_input(std::find(ids.begin(), ids.end(), b) != ids.end(),
                          path,
                          "the mesh has no boundary " + std::to_string(b));
          }
        parameters.moment->set_time(0.);
        const std::string why =
          loads::first_non_finite(*parameters.moment, centres);
        throw_if_any(comm,
                     why.empty()
                       ? why
                       : "Bending/Edge moment/Function expression: " + why);
      }

      std::map<types::material_id, RegionStiffness>
      region_stiffness(const MaterialRegions &materials)
      {
        std::map<types::material_id, RegionStiffness> result;
        for (const auto id : materials.ids())
          {
            const RegionMaterial &m = materials[id];
            if (m.bending_factor <= 0.)
              continue;
            // D_b = t^3/12 dS/dE at zero strain (prestress left out).
            SymmetricTensor<2, 2> S;
            SymmetricTensor<4, 2> dS_dE;
            m.plain_law->evaluate(unit_symmetric_tensor<2>(), S, dS_dE);
            const double scale =
              m.bending_factor * std::pow(m.thickness, 3) / 12.;
            RegionStiffness k;
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                for (unsigned int a = 0; a < 2; ++a)
                  for (unsigned int b = 0; b < 2; ++b)
                    k.D[i][j][a][b] = scale * dS_dE[i][j][a][b];
            k.largest  = std::max(k.D[0][0][0][0], k.D[1][1][1][1]);
            result[id] = k;
          }
        return result;
      }

      ShellBending::ShellBending(const MembraneSubsystem &membrane,
                                 const Parameters        &parameters)
      {
        context.membrane   = &membrane;
        context.parameters = parameters;
        context.stiffness  = region_stiffness(membrane.material_regions());
        cells              = std::make_unique<BendingCells>(context);
        edges              = std::make_unique<BendingEdges>(context);
      }

      ShellBending::~ShellBending() = default;

      CellTerms &
      ShellBending::cell_terms()
      {
        return *cells;
      }

      FaceTerms &
      ShellBending::face_terms()
      {
        return *edges;
      }

      double
      ShellBending::energy() const
      {
        return cells->energy() + edges->energy();
      }

      const std::map<types::boundary_id, Tensor<1, 3>> &
      ShellBending::clamp_moments() const
      {
        return edges->clamp_moments();
      }

      namespace
      {
        /// The principal values (larger first) of a symmetric 2x2 @p a.
        std::array<double, 2>
        principal(const double a[2][2])
        {
          const double mean = 0.5 * (a[0][0] + a[1][1]);
          const double r    = std::hypot(0.5 * (a[0][0] - a[1][1]), a[0][1]);
          return {{mean + r, mean - r}};
        }
      } // namespace

      void
      ShellBending::cell_fields(
        const LA::Vector                    &field,
        std::vector<std::string>            &names,
        std::vector<dealii::Vector<double>> &values) const
      {
        const auto        &membrane = *context.membrane;
        const auto        &dofs     = membrane.dof_handler();
        const auto        &base     = dofs.get_fe().base_element(0);
        const auto         dof      = node_dofs(dofs.get_fe());
        const unsigned int first    = values.size();
        for (const char *name : {"curvature_change_1",
                                 "curvature_change_2",
                                 "bending_moment_1",
                                 "bending_moment_2"})
          {
            names.emplace_back(name);
            values.emplace_back(membrane.triangulation().n_active_cells());
          }
        NodePositions                 nodes(membrane.mapping(), base);
        const QGauss<2>               gauss(membrane.degree() + 1);
        std::vector<ShapeDerivatives> shape;
        for (unsigned int q = 0; q < gauss.size(); ++q)
          shape.push_back(shape_derivatives(base, gauss.point(q)));
        std::vector<types::global_dof_index> indices(
          dofs.get_fe().n_dofs_per_cell());
        for (const auto &cell : dofs.active_cell_iterators())
          {
            const RegionStiffness *k = context.of(cell->material_id());
            if (!cell->is_locally_owned() || k == nullptr)
              continue;
            cell->get_dof_indices(indices);
            const auto              &X = nodes.of(cell);
            std::vector<Vec<double>> x = X;
            for (unsigned int a = 0; a < x.size(); ++a)
              for (unsigned int c = 0; c < 3; ++c)
                x[a][c] += field[indices[dof[a][c]]];
            const Tensor<1, 3> w =
              membrane.material_regions()[cell->material_id()].warp(
                membrane.geometry(), cell);
            double kappa[2][2] = {{0., 0.}, {0., 0.}}, area = 0.;
            for (unsigned int q = 0; q < gauss.size(); ++q)
              {
                double G[15], g[15], kq[2][2];
                point_derivatives(X, shape[q], G);
                const ReferencePoint ref =
                  reference_point(G, {{w[0], w[1], w[2]}}, k->D, 1.);
                point_derivatives(x, shape[q], g);
                Vec<double> n;
                curvature_change(g, ref.frame, kq, n);
                const double dA = ref.area * gauss.weight(q);
                for (unsigned int i = 0; i < 2; ++i)
                  for (unsigned int j = 0; j < 2; ++j)
                    kappa[i][j] += kq[i][j] * dA;
                area += dA;
              }
            double m[2][2];
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                kappa[i][j] /= area;
            PointFrame frame;
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                for (unsigned int a = 0; a < 2; ++a)
                  for (unsigned int b = 0; b < 2; ++b)
                    frame.D[i][j][a][b] = k->D[i][j][a][b];
            moments(kappa, frame, m);
            const auto pk = principal(kappa), pm = principal(m);
            const auto c         = cell->active_cell_index();
            values[first][c]     = pk[0];
            values[first + 1][c] = pk[1];
            values[first + 2][c] = pm[0];
            values[first + 3][c] = pm[1];
          }
      }

      std::vector<std::array<double, 3>>
      ShellBending::clamped_axes() const
      {
        std::vector<std::array<double, 3>> axes;
        const auto                        &clamped = context.parameters.clamped;
        if (clamped.empty())
          return axes;
        for (const auto &cell :
             context.membrane->triangulation().active_cell_iterators())
          if (cell->is_locally_owned() && context.of(cell->material_id()))
            for (const unsigned int f : cell->face_indices())
              if (cell->at_boundary(f)
                  && clamped.count(cell->face(f)->boundary_id()))
                {
                  const Tensor<1, 3> a =
                    cell->face(f)->vertex(1) - cell->face(f)->vertex(0);
                  axes.push_back(
                    {{a[0] / a.norm(), a[1] / a.norm(), a[2] / a.norm()}});
                }
        return axes;
      }

      std::string
      ShellBending::description(const unsigned int degree) const
      {
        std::ostringstream s;
        s << std::setprecision(4)
          << "Bending (Kirchhoff-Love shell, C0 interior "
          << "penalty): regions";
        for (const auto &[id, k] : context.stiffness)
          s << " " << id << " (D = " << k.largest << " N m)";
        s << "; penalty " << context.parameters.gamma(degree)
          << " D / h (Interior penalty factor "
          << context.parameters.penalty_factor << "); clamped edges:";
        if (context.parameters.clamped.empty())
          s << " none";
        for (const auto b : context.parameters.clamped)
          s << " " << b;
        if (degree == 1)
          s << ". On Q1 cells the curvature inside a cell is only its twist: "
               "the bending lives in the kinks between the cells (a hinge "
               "model: right for a bend across the cells' edges, stiffer "
               "along their diagonals); converging shells need Polynomial "
               "degree = 2";
        return s.str();
      }
    } // namespace bending
  }   // namespace membrane
} // namespace pneuma
